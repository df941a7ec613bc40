#pragma once
// Per-station turnaround on a real line: from the moment the request's last byte was read
// (the read that completed the frame) to the moment the station's reply was written (write()
// returned). A master waits at most one slot time TSL for the reply's first character
// ([IEC 61158-4-3 bus parameters, timing]: TSL, max TSDR), so this is the figure to compare
// with the slot time configured in the master (docs/serial.md).
//
// O(1) and allocation-free per telegram: a fixed histogram of log-spaced buckets, four per
// octave (each bucket's upper bound is 2^(1/4) ≈ 1.19 × its lower bound), from 1.024 µs to
// 2^35 ns ≈ 34 s; below and above fall into the first and last bucket. Percentiles are read
// from the histogram (the upper bound of the bucket holding the quantile, never above the
// exact maximum), so they are at most 19 % high; the maximum and the mean are exact.

#include "dp/time/clock.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <functional>

namespace rs4sim::dp::link {

class TurnaroundStats {
 public:
  static constexpr int kFirstOctave = 10;  // 2^10 ns = 1.024 µs
  static constexpr int kLastOctave = 34;   // bucket bounds up to 2^35 ns
  static constexpr int kPerOctave = 4;
  // [0] below 1.024 µs, then kPerOctave per octave, then [last] at or above 2^35 ns.
  static constexpr std::size_t kBuckets = 2 + (kLastOctave - kFirstOctave + 1) * kPerOctave;

  // The bucket of a turnaround of `ns` nanoseconds (negative: 0).
  [[nodiscard]] static constexpr std::size_t bucket_of(std::int64_t ns) {
    if (ns < (std::int64_t{1} << kFirstOctave)) return 0;
    const auto v = static_cast<std::uint64_t>(ns);
    const int octave = static_cast<int>(std::bit_width(v)) - 1;  // ≥ kFirstOctave
    if (octave > kLastOctave) return kBuckets - 1;
    const auto quarter = static_cast<std::size_t>((v >> (octave - 2)) & 3U);
    return 1 + static_cast<std::size_t>(octave - kFirstOctave) * kPerOctave + quarter;
  }
  // The exclusive upper bound of bucket `i` in ns (the last bucket: no bound, INT64_MAX).
  [[nodiscard]] static constexpr std::int64_t bucket_upper_ns(std::size_t i) {
    if (i == 0) return std::int64_t{1} << kFirstOctave;
    if (i >= kBuckets - 1) return INT64_MAX;
    const auto k = i - 1;
    const int octave = kFirstOctave + static_cast<int>(k / kPerOctave);
    const auto quarter = static_cast<std::int64_t>(k % kPerOctave);
    return (4 + quarter + 1) << (octave - 2);
  }

  void record(Duration turnaround) {
    const std::int64_t ns =
        std::chrono::duration_cast<std::chrono::nanoseconds>(turnaround).count();
    ++buckets_[bucket_of(ns)];
    ++count_;
    sum_ns_ += ns > 0 ? static_cast<std::uint64_t>(ns) : 0U;
    max_ns_ = std::max(max_ns_, ns);
  }
  // A reply not sent because it would have left after the slot time (--tsl).
  void record_late() { ++late_; }

  [[nodiscard]] std::uint64_t count() const { return count_; }  // replies sent and timed
  [[nodiscard]] std::uint64_t late() const { return late_; }    // replies dropped as too late
  [[nodiscard]] std::int64_t max_ns() const { return max_ns_; }
  [[nodiscard]] std::int64_t mean_ns() const {
    return count_ == 0 ? 0 : static_cast<std::int64_t>(sum_ns_ / count_);
  }
  [[nodiscard]] const std::array<std::uint64_t, kBuckets>& buckets() const { return buckets_; }

  // The q-quantile (0 < q ≤ 1) in ns: the upper bound of the bucket that holds it, capped at
  // the exact maximum; 0 without samples.
  [[nodiscard]] std::int64_t quantile_ns(double q) const {
    if (count_ == 0) return 0;
    // The rank of the sample that is the quantile, 1-based: ceil(q * count), at least 1.
    const double wanted = q * static_cast<double>(count_);
    auto rank = static_cast<std::uint64_t>(wanted);
    if (static_cast<double>(rank) < wanted) ++rank;
    rank = std::clamp<std::uint64_t>(rank, 1, count_);
    std::uint64_t seen = 0;
    for (std::size_t i = 0; i < kBuckets; ++i) {
      seen += buckets_[i];
      if (seen >= rank) return std::min(bucket_upper_ns(i), max_ns_);
    }
    return max_ns_;
  }

 private:
  std::array<std::uint64_t, kBuckets> buckets_{};
  std::uint64_t count_ = 0;
  std::uint64_t late_ = 0;
  std::uint64_t sum_ns_ = 0;
  std::int64_t max_ns_ = 0;
};

// Where a layer above finds the turnaround of the station at an address (nullptr: none),
// read on the loop: the runtime's StationRunner hands it to rpc and the GSD service.
using TurnaroundSource = std::function<const TurnaroundStats*(std::uint8_t)>;

}  // namespace rs4sim::dp::link
