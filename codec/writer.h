#pragma once
// Bounds-checked writers of big- and little-endian fields that keep the first error, the
// counterpart of codec::Reader: a write that does not fit is dropped, the error latched and
// every later write dropped too; the encoder checks ok() once at the end.
//
//   codec::Writer    writes into a caller's fixed buffer (std::span), e.g. a 10-byte block;
//   codec::Appender  appends to a vector-like container (static_vector, std::vector) up to
//                    a byte limit (by default the container's capacity).

#include "codec/buffer_error.h"
#include "codec/endian.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <system_error>

namespace rs4sim::codec {

// The field writers shared by Writer and Appender. Derived provides
// room() (bytes still allowed) and put(std::span<const std::uint8_t>) (no checks).
template <class Derived>
class FieldWriter {
 public:
  constexpr void u8(std::uint8_t v) noexcept { write(std::array{v}); }
  constexpr void u16_be(std::uint16_t v) noexcept { write(std::array{high_byte(v), low_byte(v)}); }
  constexpr void u16_le(std::uint16_t v) noexcept { write(std::array{low_byte(v), high_byte(v)}); }
  constexpr void u32_be(std::uint32_t v) noexcept {
    write(std::array{byte_of(v, 3), byte_of(v, 2), byte_of(v, 1), byte_of(v, 0)});
  }
  constexpr void u32_le(std::uint32_t v) noexcept {
    write(std::array{byte_of(v, 0), byte_of(v, 1), byte_of(v, 2), byte_of(v, 3)});
  }
  // The low n bytes of v, high byte first, n = 0..4 (e.g. a 24-bit CRC).
  constexpr void uint_be(std::uint32_t v, std::size_t n) noexcept {
    const std::array b{byte_of(v, 3), byte_of(v, 2), byte_of(v, 1), byte_of(v, 0)};
    if (n > 4) return fail();
    write(std::span<const std::uint8_t>(b).last(n));
  }
  constexpr void bytes(std::span<const std::uint8_t> b) noexcept { write(b); }
  // Writes an array of bytes or byte-sized characters.
  template <class T, std::size_t N>
  requires(sizeof(T) == 1) constexpr void copy_from(const std::array<T, N>& in) noexcept {
    std::array<std::uint8_t, N> b{};
    for (std::size_t i = 0; i < N; ++i) b[i] = static_cast<std::uint8_t>(in[i]);
    write(b);
  }

  [[nodiscard]] constexpr bool ok() const noexcept { return !failed_; }
  [[nodiscard]] std::error_code error() const noexcept {
    return failed_ ? make_error_code(BufferError::kWritePastEnd) : std::error_code{};
  }
  // Latches an error found by the caller; every later write is dropped.
  constexpr void fail() noexcept { failed_ = true; }

 private:
  template <class Bytes>
  constexpr void write(const Bytes& b) noexcept {
    auto& self = static_cast<Derived&>(*this);
    if (failed_ || std::size(b) > self.room()) {
      failed_ = true;
      return;
    }
    self.put(std::span<const std::uint8_t>(std::data(b), std::size(b)));
  }

  bool failed_ = false;
};

class Writer : public FieldWriter<Writer> {
 public:
  constexpr explicit Writer(std::span<std::uint8_t> buffer) noexcept : buffer_(buffer) {}

  [[nodiscard]] constexpr std::size_t size() const noexcept { return pos_; }
  [[nodiscard]] constexpr std::span<const std::uint8_t> written() const noexcept {
    return buffer_.first(pos_);
  }

 private:
  friend class FieldWriter<Writer>;
  [[nodiscard]] constexpr std::size_t room() const noexcept { return buffer_.size() - pos_; }
  constexpr void put(std::span<const std::uint8_t> b) noexcept {
    for (const auto c : b) buffer_[pos_++] = c;
  }

  std::span<std::uint8_t> buffer_;
  std::size_t pos_ = 0;
};

template <class Container>
class Appender : public FieldWriter<Appender<Container>> {
 public:
  // `limit`: the container's total size this appender may grow it to.
  constexpr explicit Appender(Container& out,
                              std::size_t limit = std::numeric_limits<std::size_t>::max()) noexcept
      : out_(out), limit_(limit < out.max_size() ? limit : out.max_size()) {}

 private:
  friend class FieldWriter<Appender<Container>>;
  [[nodiscard]] constexpr std::size_t room() const noexcept {
    return out_.size() < limit_ ? limit_ - out_.size() : 0;
  }
  constexpr void put(std::span<const std::uint8_t> b) noexcept {
    out_.insert(out_.end(), b.begin(), b.end());
  }

  Container& out_;
  std::size_t limit_;
};

}  // namespace rs4sim::codec
