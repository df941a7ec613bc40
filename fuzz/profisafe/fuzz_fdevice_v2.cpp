// libFuzzer target: the F-device and the F-host in V1 and V2 ([IEC 61784-3-3 safety PDU]) fed
// with arbitrary PDUs, well-formed PDUs of chosen numbers and control bits, and time steps.
// Input: byte 0 picks the connection (V1, V2 3-byte, V2 4-byte CRC2), then records of
// [kind, time step ms, a, ...]: kind 0 a raw PDU of a % 10 bytes to the device, kind 1 a PDU
// built with control byte a and number [next byte] to the device, kind 2 one host request and
// the device's answer to it (a & 1: ACK_REI first). Invariants: never crash; the device's answer
// always has the PDU size; real input data leave the device only when sends_process_values();
// the host's output data reach the device's application only in kRun.
#include "profisafe/f_device.h"
#include "profisafe/f_host.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <span>

namespace {

using namespace rs4sim::profisafe;

constexpr std::array<CrcLength, 3> kLengths{CrcLength::k2Byte, CrcLength::k3Byte,
                                            CrcLength::k4Byte};

struct Rig {
  explicit Rig(std::uint8_t mode) : host(host_config(mode)), dev(device_config(mode)) {
    (void)dev.set_parameters(host.parameter_block());
    dev.set_input(std::span<const std::uint8_t>(&kInput, 1));
    pdu = PduConfig::from(parse_f_parameters(host.parameter_block()).value(), 1);
  }
  static FParameters params(std::uint8_t mode) {
    FParameters p;
    p.crc_length = kLengths[mode % 3];
    p.par_version = mode % 3 == 0 ? 0 : 1;
    p.wd_time_ms = 100;
    return p;
  }
  static FHostConfig host_config(std::uint8_t mode) { return FHostConfig{params(mode), 1, {}}; }
  static FDeviceConfig device_config(std::uint8_t mode) {
    DeviceProfile d;
    d.crc_length = kLengths[mode % 3];
    d.par_version = mode % 3 == 0 ? 0 : 1;
    return FDeviceConfig{d, 1, {}};
  }
  void check() {
    const auto r = dev.response();
    if (r.size() != pdu_size(pdu)) std::abort();
    if (r[0] == kInput && !dev.sends_process_values()) std::abort();
    if (dev.output()[0] != 0 && dev.state() != FDeviceState::kRun) std::abort();
  }
  static constexpr std::uint8_t kInput = 0xA5;
  FHost host;
  FDevice dev;
  PduConfig pdu{};
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  Rig rig(data[0]);
  TimePoint now{std::chrono::hours(1)};
  std::size_t at = 1;
  while (at + 3 <= size) {
    const std::uint8_t kind = data[at] % 3;
    now += std::chrono::milliseconds(data[at + 1]);
    const std::uint8_t a = data[at + 2];
    at += 3;
    if (kind == 0) {
      const std::size_t len = std::min<std::size_t>(a % 10u, size - at);
      (void)rig.dev.on_pdu(std::span<const std::uint8_t>(data + at, len), now);
      at += len;
    } else if (kind == 1 && at < size) {
      std::array<std::uint8_t, kMaxPduSize> out{};
      const std::uint8_t payload = 0x3C;
      const auto n = build_pdu(rig.pdu, std::span<const std::uint8_t>(&payload, 1), a, data[at],
                               out);
      if (n) (void)rig.dev.on_pdu(std::span<const std::uint8_t>(out).first(n.value()), now);
      ++at;
    } else {
      const auto req = rig.host.request(now);
      if (!req.empty()) (void)rig.dev.on_pdu(req, now);
      if (a & 1) rig.host.ack_rei();
      (void)rig.host.on_pdu(rig.dev.response(), now);
    }
    rig.dev.on_time(now);
    rig.host.on_time(now);
    rig.check();
  }
  return 0;
}
