#pragma once
// Typed errors of the CEDES frame codec ([GridScan manual §9.2]), carried as
// std::error_code with the category "gridscan.frame". The device itself never answers with
// an error: a bad request gets the manual's reaction (no reply, or the communication test
// bits, [GridScan manual §10.2, §10.3]); these values name why, for decoders and counters.

#include "codec/error_category.h"

#include <boost/outcome/std_result.hpp>

#include <cstdint>
#include <string_view>
#include <system_error>

namespace rs4sim::gridscan {

template <typename T>
using Result = boost::outcome_v2::std_result<T>;

enum class FrameError : std::uint8_t {
  kTooShort = 1,    // fewer than 10 bytes: sync, SeqCnt, ID and CRC do not fit
  kTooLong,         // more than 20 bytes ([GridScan manual §9.2] "maximum 20 bytes")
  kBadSync,         // bytes 0..3 are not 43 45 44 45
  kBadCrc,          // the CRC-32 over SeqCnt, ID and payload does not match
  kRequestPayload,  // a request with payload bytes ([GridScan manual §9.2.4] "no payload")
  kDirectionBit,    // a request with bit 7 of the ID set, or a response without it
  kUnknownId,       // an ID that is not in the manual's table
  kPayloadLength,   // a response whose payload length does not fit its ID
  kBadField,        // a payload field outside its range (an encoder's input)
};

[[nodiscard]] std::string_view to_string(FrameError e) noexcept;
constexpr const char* error_category_name(FrameError) noexcept { return "gridscan.frame"; }
inline std::error_code make_error_code(FrameError e) noexcept {
  return codec::make_error_code_of(e);
}

}  // namespace rs4sim::gridscan
