// Fuzzes the adapter command parser and every adapter answer / alarm decoder
// ([RS4 manual §5.2.2, §5.3]); whatever decodes must re-encode to the same bytes.
#include "rs4/protocol/adapter_answer.h"
#include "rs4/protocol/adapter_command.h"
#include "rs4/protocol/alarm.h"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

using namespace rs4sim::rs4::protocol;

namespace {

void check(bool ok) {
  if (!ok) __builtin_trap();
}

bool same(std::span<const std::uint8_t> a, const std::vector<std::uint8_t>& b) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end());
}

void parse_command(std::span<const std::uint8_t> in) {
  auto parsed = parse_write_command(in);
  if (!parsed) {
    check(in.empty());
    return;
  }
  std::visit(
      [in](const auto& c) {
        using T = std::decay_t<decltype(c)>;
        if constexpr (std::is_same_v<T, Rs4Command>) {
          check(c.bytes.data() == in.data() && c.bytes.size() == in.size());
        } else if constexpr (std::is_same_v<T, RejectedCommand>) {
          auto back = decode_rejection(encode_rejection(c));
          check(back && back.value() == c);
        } else {
          check(same(in, encode_command(c)));
        }
      },
      parsed.value());
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::span<const std::uint8_t> in(data, size);
  parse_command(in);
  if (auto r = decode_rejection(in)) check(same(in, encode_rejection(r.value())));
  if (auto v = decode_version_answer(in)) check(same(in, encode_version_answer(v.value())));
  if (auto l = decode_last_error_answer(in)) check(same(in, encode_last_error_answer(l.value())));
  if (auto m = decode_error_memory_answer(in)) {
    check(same(in, encode_error_memory_answer(m.value())));
  }
  if (auto u = decode_update_alarm(in)) check(same(in, encode_update_alarm(u.value())));
  if (auto d = decode_diagnosis_alarm(in)) check(same(in, encode_diagnosis_alarm(d.value())));
  return 0;
}
