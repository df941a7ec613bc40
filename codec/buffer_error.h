#pragma once
// The one error of the byte cursors: a read or write past the end of the buffer.

#include "codec/error_category.h"

#include <cstdint>
#include <string_view>
#include <system_error>

namespace rs4sim::codec {

enum class BufferError : std::uint8_t {
  kReadPastEnd = 1,  // Reader: fewer bytes left than the field needs
  kWritePastEnd,     // Writer: no room left in the caller's buffer
};

[[nodiscard]] std::string_view to_string(BufferError e) noexcept;
constexpr const char* error_category_name(BufferError) noexcept { return "codec"; }
inline std::error_code make_error_code(BufferError e) noexcept { return make_error_code_of(e); }

}  // namespace rs4sim::codec
