#pragma once
// Typed FDL receive errors ([IEC 61158-4-3 frame formats, FCS, addresses, SAPs], receiver checklist
// [IEC 61158-4-3 frame reception]). Carried as std::error_code with the category "fdl.decode"
// (codec::ErrorCategory).

#include "codec/error_category.h"

#include <cstdint>
#include <string_view>
#include <system_error>

namespace rs4sim::dp::fdl {

enum class DecodeError : std::uint8_t {
  kGarbage = 1,             // byte(s) outside any frame that are no start delimiter
  kLengthMismatch,          // SD2: LE != LEr ([IEC 61158-4-3 frame formats])
  kLengthOutOfRange,        // SD2: LE < 3 or LE > 249 ([IEC 61158-4-3 frame reception])
  kStartDelimiterMismatch,  // SD2: repeated SD at offset 3 is not 0x68
                            // ([IEC 61158-4-3 frame formats])
  kBadEndDelimiter,         // ED is not 0x16 ([IEC 61158-4-3 frame formats])
  kBadFcs,                  // FCS mismatch ([IEC 61158-4-3 FCS])
  kBadFrameControl,         // reserved function/status code or bit 7 misuse
                            // ([IEC 61158-4-3 frame control])
  kBadAddressExtension,     // extension byte chained/segment, or no room for it
                            // ([IEC 61158-4-3 addresses, SAPs])
  kSapWithoutPartner,       // DSAP without SSAP or SSAP without DSAP
                            // ([IEC 61158-4-3 addresses, SAPs])
  kBadTokenAddress,         // SD4 with address bit 7 set ([IEC 61158-4-3 frame formats, token])
  kTruncated,               // line went idle inside a frame (Decoder::idle())
};
inline constexpr std::size_t kDecodeErrorKinds = 11;

[[nodiscard]] std::string_view to_string(DecodeError e) noexcept;
constexpr const char* error_category_name(DecodeError) noexcept { return "fdl.decode"; }
inline std::error_code make_error_code(DecodeError e) noexcept {
  return codec::make_error_code_of(e);
}

}  // namespace rs4sim::dp::fdl
