#pragma once
// Typed FDL receive errors (spec/profibus-dp.md §1.2–§1.4, receiver checklist §1.10).
// Carried as std::error_code with the category "fdl.decode" (codec::ErrorCategory).

#include "codec/error_category.h"

#include <cstdint>
#include <string_view>
#include <system_error>

namespace rs4sim::dp::fdl {

enum class DecodeError : std::uint8_t {
  kGarbage = 1,               // byte(s) outside any frame that are no start delimiter
  kLengthMismatch,            // SD2: LE != LEr (§1.2)
  kLengthOutOfRange,          // SD2: LE < 3 or LE > 249 (§1.10)
  kStartDelimiterMismatch,    // SD2: repeated SD at offset 3 is not 0x68 (§1.2)
  kBadEndDelimiter,           // ED is not 0x16 (§1.2)
  kBadFcs,                    // FCS mismatch (§1.3)
  kBadFrameControl,           // reserved function/status code or bit 7 misuse (§1.5)
  kBadAddressExtension,       // extension byte chained/segment, or no room for it (§1.4)
  kSapWithoutPartner,         // DSAP without SSAP or SSAP without DSAP (§1.4)
  kBadTokenAddress,           // SD4 with address bit 7 set (§1.2, §1.9)
  kTruncated,                 // line went idle inside a frame (Decoder::idle())
};
inline constexpr std::size_t kDecodeErrorKinds = 11;

[[nodiscard]] std::string_view to_string(DecodeError e) noexcept;
constexpr const char* error_category_name(DecodeError) noexcept { return "fdl.decode"; }
inline std::error_code make_error_code(DecodeError e) noexcept {
  return codec::make_error_code_of(e);
}

}  // namespace rs4sim::dp::fdl

template <>
struct std::is_error_code_enum<rs4sim::dp::fdl::DecodeError> : std::true_type {};
