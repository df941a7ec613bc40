#include "rs4/device/rs4_state.h"

#include "codec/error_category.h"
#include "codec/reader.h"
#include "codec/writer.h"
#include "rs4/scanner/crc32.h"
#include "rs4/scanner/parameter_codec.h"

#include <algorithm>
#include <array>

namespace rs4sim::rs4::device {
namespace {

constexpr std::array<std::uint8_t, 8> kMagic{'R', 'S', '4', 'S', 'I', 'M', 'N', 'V'};
constexpr std::size_t kHeaderSize = 16;  // magic, version, kind, switches, N
constexpr std::size_t kCrcSize = 4;

}  // namespace

std::string_view to_string(StateError e) noexcept {
  switch (e) {
    case StateError::kNotAStateFile: return "not an rs4sim state file (no RS4SIMNV magic)";
    case StateError::kNewerFormat: return "written by a newer rs4sim (format version above 1)";
    case StateError::kOtherDevice: return "the memory of another device kind, not an RS4";
    case StateError::kTruncated: return "truncated (shorter than its lengths say)";
    case StateError::kCorrupt: return "corrupt (CRC-32 mismatch)";
    case StateError::kBadSet: return "the parameter set in it does not decode or is not valid";
    case StateError::kBadSwitches: return "an address switch beyond 0..F";
  }
  return "unknown state file error";
}

std::error_code make_error_code(StateError e) noexcept { return codec::make_error_code_of(e); }

std::vector<std::uint8_t> encode_state(const Rs4State& state) {
  const auto set = scanner::encode(state.set);
  std::vector<std::uint8_t> out;
  out.reserve(kHeaderSize + set.size() + kCrcSize);
  codec::Appender w(out);
  w.bytes(kMagic);
  w.u8(kStateFormat);
  w.u8(kStateKindRs4);
  w.u8(state.switches.hex_high);
  w.u8(state.switches.hex_low);
  w.u32_be(static_cast<std::uint32_t>(set.size()));
  w.bytes(set);
  w.u32_be(scanner::crc32_iso_hdlc(out));
  return out;
}

boost::outcome_v2::std_result<Rs4State> decode_state(std::span<const std::uint8_t> bytes) {
  codec::Reader r(bytes);
  const auto magic = r.bytes(kMagic.size());
  if (!r.ok() || !std::equal(magic.begin(), magic.end(), kMagic.begin())) {
    return StateError::kNotAStateFile;
  }
  const auto version = r.u8();
  const auto kind = r.u8();
  if (!r.ok()) return StateError::kTruncated;
  if (version > kStateFormat || version == 0) return StateError::kNewerFormat;
  if (kind != kStateKindRs4) return StateError::kOtherDevice;
  Rs4State state;
  state.switches.hex_high = r.u8();
  state.switches.hex_low = r.u8();
  const auto n = r.u32_be();
  const auto set = r.bytes(n);
  const auto end = r.position();
  const auto crc = r.u32_be();
  if (!r.ok() || !r.at_end()) return StateError::kTruncated;
  if (crc != scanner::crc32_iso_hdlc(bytes.first(end))) return StateError::kCorrupt;
  if (state.switches.hex_high > 0xF || state.switches.hex_low > 0xF) {
    return StateError::kBadSwitches;
  }
  auto decoded = scanner::decode(set);
  if (!decoded || scanner::validate(decoded.value())) return StateError::kBadSet;
  state.set = std::move(decoded).value();
  return state;
}

Rs4State capture_state(const Rs4Device& device) {
  return {device.scanner().parameters(), device.address_switches()};
}

StateMark state_mark(const Rs4Device& device) {
  return {device.scanner().change_counter(),
          device.scanner().parameters().identity.serial_number, device.address_switches()};
}

Rs4DeviceConfig with_state(Rs4DeviceConfig config, const Rs4State& state) {
  config.scanner.identity = state.set.identity;
  config.switches = state.switches;
  return config;
}

bool restore_state(Rs4Device& device, const Rs4State& state, dp::TimePoint now) {
  return !device.powered() && device.scanner().set_parameters(state.set, now).has_value();
}

}  // namespace rs4sim::rs4::device
