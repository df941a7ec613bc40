#include "polaris/mode_spec.h"

#include "stream/words.h"

#include <charconv>
#include <optional>

namespace rs4sim::polaris {
namespace {

// The number after "key=": decimal, or hex after 0x when `hex` (register numbers); at most
// `max`. nullopt when it does not parse.
std::optional<std::uint32_t> number_after(std::string_view word, std::size_t key_size,
                                          std::uint32_t max, bool hex) {
  std::string_view digits = word.substr(key_size);
  int base = 10;
  if (hex && (digits.starts_with("0x") || digits.starts_with("0X"))) {
    digits.remove_prefix(2);
    base = 16;
  }
  std::uint32_t value = 0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value, base);
  if (digits.empty() || ec != std::errc{} || end != digits.data() + digits.size() || value > max) {
    return std::nullopt;
  }
  return value;
}

// A word without a value; false when it is none of them.
bool apply_flag(std::string_view word, Options& p) {
  if (word == "slave" || word == "master") {
    p.role = word == "slave" ? Role::kSlave : Role::kMaster;
  } else if (word == "direct" || word == "reverse") {
    p.direction = word == "direct" ? ScanDirection::kDirect : ScanDirection::kReverse;
  } else if (word == "object" || word == "hole") {
    p.detection = word == "object" ? Detection::kObject : Detection::kHole;
  } else if (word == "lsb" || word == "msb") {
    p.bit_order = word == "lsb" ? BitOrder::kLsbFirst : BitOrder::kMsbFirst;
  } else if (word == "nak" || word == "no-nak") {
    p.nak_on_error = word == "nak";
  } else if (word == "temporary" || word == "permanent") {
    p.storage_mode = word == "temporary" ? StorageMode::kTemporary : StorageMode::kPermanent;
  } else {
    return false;
  }
  return true;
}

struct NumberWord {
  std::string_view key;
  std::uint32_t max;
  bool hex;
  std::string_view help;
  void (*assign)(Options&, std::uint32_t);
};

constexpr NumberWord kNumberWords[] = {
    {"start=", 0xFFFF, true,
     "start= takes a register number 0..65535 (slave: 500..12287), e.g. start=8192 or "
     "start=0x2000",
     [](Options& p, std::uint32_t v) { p.start_address = static_cast<std::uint16_t>(v); }},
    {"scan-time=", 0xFFFFFFFF, false, "scan-time= takes milliseconds, 5..5000, e.g. scan-time=100",
     [](Options& p, std::uint32_t v) { p.scan_time = std::chrono::milliseconds(v); }},
    {"pn2-filter=", 0xFFFF, false, "pn2-filter= takes a number of scans, 1..255",
     [](Options& p, std::uint32_t v) { p.pn2_filter = static_cast<std::uint16_t>(v); }},
    {"response-time=", 0xFFFFFFFF, false,
     "response-time= takes microseconds, 0 (the model's) .. 1000000, e.g. response-time=600",
     [](Options& p, std::uint32_t v) { p.response_time = std::chrono::microseconds(v); }},
    {"response-column=", 0xFF, false,
     "response-column= takes 1 or 2 (the model table's maximum response time column)",
     [](Options& p, std::uint32_t v) { p.response_column = static_cast<ResponseColumn>(v); }},
};

// "" when applied; an error for a bad value; nullopt when the word is none of ours.
std::optional<std::string> apply_word(std::string_view word, Options& p) {
  if (apply_flag(word, p)) return std::string{};
  if (word.starts_with("storage=")) {
    const auto s = parse_data_storage(word.substr(8));
    if (!s) return "'" + std::string(word) + "': storage= takes none, object or hole";
    p.storage = *s;
    return std::string{};
  }
  for (const NumberWord& n : kNumberWords) {
    if (!word.starts_with(n.key)) continue;
    const auto v = number_after(word, n.key.size(), n.max, n.hex);
    if (!v) return "'" + std::string(word) + "': " + std::string(n.help);
    n.assign(p, *v);
    return std::string{};
  }
  return std::nullopt;
}

}  // namespace

std::string apply_mode_spec(std::string_view spec, Options& o) {
  bool first = true;
  for (const std::string_view word : stream::split_words(spec, ',')) {
    if (first) {
      const auto m = parse_data_mode(word);
      if (!m) return "'" + std::string(word) + "' is not 485MB, FL1, FL4 or FL10";
      o.mode = *m;
      first = false;
    } else if (const auto why = apply_word(word, o); !why) {
      return "'" + std::string(word) +
             "' is none of slave, master, direct, reverse, object, hole, lsb, msb, nak, no-nak, "
             "start=, scan-time=, pn2-filter=, storage=, temporary, permanent, response-time=, "
             "response-column=";
    } else if (!why->empty()) {
      return *why;
    }
  }
  return {};
}

}  // namespace rs4sim::polaris
