#pragma once
// Bounds-checked reader of big- and little-endian fields that keeps the first error
// (the shape of p-net's pf_get_* block reader: a read past the end returns zero, the error
// is latched and every later read returns zero too, so a decoder reads all its fields and
// checks once at the end).
//
//   codec::Reader r(du);
//   const auto slot = r.u8();
//   const auto number = r.u16_be();
//   if (!r.ok()) return PduError::kTooShort;

#include "codec/buffer_error.h"
#include "codec/endian.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <system_error>

namespace rs4sim::codec {

class Reader {
 public:
  constexpr Reader() noexcept = default;
  constexpr explicit Reader(std::span<const std::uint8_t> bytes) noexcept : bytes_(bytes) {}

  constexpr std::uint8_t u8() noexcept { return need(1) ? bytes_[pos_++] : std::uint8_t{0}; }
  constexpr std::uint16_t u16_be() noexcept {
    if (!need(2)) return 0;
    const auto v = be16(bytes_[pos_], bytes_[pos_ + 1]);
    pos_ += 2;
    return v;
  }
  constexpr std::uint16_t u16_le() noexcept {
    if (!need(2)) return 0;
    const auto v = be16(bytes_[pos_ + 1], bytes_[pos_]);
    pos_ += 2;
    return v;
  }
  constexpr std::uint32_t u32_be() noexcept {
    if (!need(4)) return 0;
    const auto high = u16_be();
    return be32(high, u16_be());
  }
  constexpr std::uint32_t u32_le() noexcept {
    if (!need(4)) return 0;
    const auto low = u16_le();
    return be32(u16_le(), low);
  }
  // An n-byte big-endian unsigned value, n = 0..4 (e.g. a 16- or 24-bit CRC).
  constexpr std::uint32_t uint_be(std::size_t n) noexcept {
    if (n > 4) fail();
    std::uint32_t v = 0;
    for (const auto b : bytes(n)) v = (v << 8U) | b;
    return v;
  }
  // Fills `out` with consecutive big-endian 16-bit values (one bounds check for all;
  // zeros after an error).
  constexpr void u16_be_array(std::span<std::uint16_t> out) noexcept {
    const auto in = bytes(2 * out.size());
    for (std::size_t i = 0; i < out.size(); ++i) {
      out[i] = in.empty() ? std::uint16_t{0} : be16(in[2 * i], in[2 * i + 1]);
    }
  }
  // The next n bytes (a view into the input), or an empty span after an error.
  constexpr std::span<const std::uint8_t> bytes(std::size_t n) noexcept {
    if (!need(n)) return {};
    const auto out = bytes_.subspan(pos_, n);
    pos_ += n;
    return out;
  }
  // Fills an array of bytes or byte-sized characters (zeros after an error).
  template <class T, std::size_t N>
  requires(sizeof(T) == 1) constexpr void copy_to(std::array<T, N>& out) noexcept {
    const auto in = bytes(N);
    for (std::size_t i = 0; i < N; ++i) out[i] = in.empty() ? T{} : static_cast<T>(in[i]);
  }
  constexpr void skip(std::size_t n) noexcept { (void)bytes(n); }
  // Everything not read yet (never an error).
  constexpr std::span<const std::uint8_t> rest() noexcept { return bytes(remaining()); }

  [[nodiscard]] constexpr std::size_t remaining() const noexcept { return bytes_.size() - pos_; }
  [[nodiscard]] constexpr std::size_t position() const noexcept { return pos_; }
  [[nodiscard]] constexpr bool at_end() const noexcept { return remaining() == 0; }
  [[nodiscard]] constexpr bool ok() const noexcept { return !failed_; }
  [[nodiscard]] std::error_code error() const noexcept {
    return failed_ ? make_error_code(BufferError::kReadPastEnd) : std::error_code{};
  }
  // Latches an error found by the caller (e.g. a length field that cannot be right): the
  // reader then behaves as after a read past the end.
  constexpr void fail() noexcept {
    failed_ = true;
    pos_ = bytes_.size();
  }

 private:
  constexpr bool need(std::size_t n) noexcept {
    if (!failed_ && n <= remaining()) return true;
    fail();
    return false;
  }

  std::span<const std::uint8_t> bytes_;
  std::size_t pos_ = 0;
  bool failed_ = false;
};

}  // namespace rs4sim::codec
