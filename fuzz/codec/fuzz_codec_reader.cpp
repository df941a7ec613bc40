// Drives codec::Reader with a field program taken from the input itself and checks it
// against a plain reference model: same values, never a byte outside the input, the
// error latched at the first read that does not fit.
#include "codec/reader.h"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const std::size_t program_length = data[0] % 16U;
  if (size < 1 + program_length) return 0;
  const auto program = std::span(data + 1, program_length);
  const auto input = std::span(data + 1 + program_length, size - 1 - program_length);
  rs4sim::codec::Reader r(input);
  std::size_t pos = 0;
  bool failed = false;
  for (const std::uint8_t op : program) {
    static constexpr std::size_t kWidth[] = {1, 2, 2, 4, 4, 3};
    const std::size_t width = kWidth[op % 6U];
    std::uint32_t expected = 0;
    const bool fits = !failed && width <= input.size() - pos;
    if (fits) {
      for (std::size_t i = 0; i < width; ++i) {
        const bool le = op % 6U == 2 || op % 6U == 4;
        const std::size_t at = le ? pos + width - 1 - i : pos + i;
        expected = (expected << 8U) | input[at];
      }
    }
    std::uint32_t got = 0;
    switch (op % 6U) {
      case 0: got = r.u8(); break;
      case 1: got = r.u16_be(); break;
      case 2: got = r.u16_le(); break;
      case 3: got = r.u32_be(); break;
      case 4: got = r.u32_le(); break;
      default: {
        const auto b = r.bytes(width);
        for (const auto c : b) got = (got << 8U) | c;
        if (b.size() != (fits ? width : 0)) std::abort();
      }
    }
    if (fits)
      pos += width;
    else
      failed = true;
    if (got != expected || r.ok() == failed) std::abort();
    if (r.remaining() != (failed ? 0 : input.size() - pos)) std::abort();
  }
  return 0;
}
