#pragma once
// The RS4's non-volatile memory as a file (`rs4sim run --state FILE`, docs/rs4-device.md
// "State file"): what a real unit keeps when it is switched off, so a restarted run is the
// same unit with the same set. Sans-I/O: bytes in, bytes out; the file belongs to the runtime.
//
// Kept: the parameter set in its full encoding (rs4/scanner/parameter_codec.h: identity with
// the serial number, the user passwords, the fields) and the address switches. Not kept: the adapter's error memory, which "geht aber beim Ausschalten
// des Gerätes verloren" ([RS4 manual §5.2.2]).
//
// Format (EXTENSION, docs/decisions.md#rs4-state-file), big-endian:
//   0   8  magic "RS4SIMNV"
//   8   1  format version, 1
//   9   1  device kind, 1 = RS4/PROFIsafe (other kinds are refused)
//   10  1  HexH, 11 1 HexL (the address switches, [RS4 manual §4.5])
//   12  4  N, the length of the set's encoding
//   16  N  the set, scanner::encode()
//   16+N 4 CRC-32/ISO-HDLC of bytes 0 .. 15+N

#include "rs4/adapter/cyclic_bytes.h"
#include "rs4/device/rs4_device.h"
#include "rs4/scanner/parameter_set.h"

#include <boost/outcome/std_result.hpp>

#include <cstdint>
#include <span>
#include <string_view>
#include <system_error>
#include <vector>

namespace rs4sim::rs4::device {

inline constexpr std::uint8_t kStateFormat = 1;
inline constexpr std::uint8_t kStateKindRs4 = 1;

enum class StateError : std::uint8_t {
  kNotAStateFile = 1,  // no magic: some other file
  kNewerFormat,        // written by a newer rs4sim
  kOtherDevice,        // another device kind's memory
  kTruncated,          // shorter than its own lengths say
  kCorrupt,            // the CRC-32 does not match
  kBadSet,             // the set does not decode or the scanner refuses it
  kBadSwitches,        // a switch beyond 0..15
};

[[nodiscard]] std::string_view to_string(StateError e) noexcept;
constexpr const char* error_category_name(StateError) noexcept { return "rs4.state"; }
std::error_code make_error_code(StateError e) noexcept;

struct Rs4State {
  scanner::ParameterSet set;
  adapter::AddressSwitches switches{};
  friend bool operator==(const Rs4State&, const Rs4State&) = default;
};

[[nodiscard]] std::vector<std::uint8_t> encode_state(const Rs4State& state);
[[nodiscard]] boost::outcome_v2::std_result<Rs4State> decode_state(
    std::span<const std::uint8_t> bytes);

// What the device holds now.
[[nodiscard]] Rs4State capture_state(const Rs4Device& device);
// The device configuration of the unit the state describes: `config` with its serial
// number (identity) and switches.
[[nodiscard]] Rs4DeviceConfig with_state(Rs4DeviceConfig config, const Rs4State& state);
// Puts the state's set into a device made from with_state() (powered off, as a unit keeps
// its set over the power-off); false when the scanner refuses it.
bool restore_state(Rs4Device& device, const Rs4State& state, dp::TimePoint now);
// What identifies a change of the memory without encoding it: a new set write (the change
// counter), another unit (serial number), other switches.
struct StateMark {
  std::uint16_t change_counter = 0;
  std::uint32_t serial_number = 0;
  adapter::AddressSwitches switches{};
  friend bool operator==(const StateMark&, const StateMark&) = default;
};
[[nodiscard]] StateMark state_mark(const Rs4Device& device);

}  // namespace rs4sim::rs4::device
