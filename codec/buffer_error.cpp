#include "codec/buffer_error.h"

namespace rs4sim::codec {

std::string_view to_string(BufferError e) noexcept {
  switch (e) {
    case BufferError::kReadPastEnd: return "read past the end of the buffer";
    case BufferError::kWritePastEnd: return "write past the end of the buffer";
  }
  return "unknown codec error";
}

}  // namespace rs4sim::codec
