#pragma once
// Internal helpers of the PDU codecs (not part of the public API).

#include "codec/endian.h"
#include "codec/reader.h"
#include "dp/fdl/telegram.h"
#include "dp/pdu/errors.h"

#include <cstdint>
#include <initializer_list>
#include <span>

namespace rs4sim::dp::pdu::wire {

inline constexpr std::size_t kMaxDpDu = 244;  // DP service DU limit ([IEC 61158-6-3 Set_Prm])

inline Result<void> append(fdl::DataUnit& out, std::span<const std::uint8_t> bytes) {
  if (out.size() + bytes.size() > kMaxDpDu) return PduError::kTooLong;
  out.insert(out.end(), bytes.begin(), bytes.end());
  return boost::outcome_v2::success();
}

inline Result<void> append(fdl::DataUnit& out, std::initializer_list<std::uint8_t> bytes) {
  return append(out, std::span<const std::uint8_t>(bytes.begin(), bytes.size()));
}

// Any contiguous container with data()/size() (static_vector, std::array).
template <class Container>
requires requires(const Container& c) {
  c.data();
  c.size();
}
inline Result<void> append(fdl::DataUnit& out, const Container& c) {
  return append(out, std::span<const std::uint8_t>(c.data(), c.size()));
}

inline constexpr bool bit(std::uint8_t b, unsigned n) {
  return ((static_cast<unsigned>(b) >> n) & 1U) != 0;
}
inline constexpr std::uint8_t flag(bool v, unsigned n) {
  return static_cast<std::uint8_t>((v ? 1U : 0U) << n);
}

}  // namespace rs4sim::dp::pdu::wire
