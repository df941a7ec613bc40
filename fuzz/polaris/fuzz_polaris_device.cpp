// Feeds the input to a Polaris slave as chunks with gaps taken from the input itself (a
// gap byte, a length byte, the chunk), runs the device's deadlines, and checks what it
// sends: only whole RTU frames with a good CRC for its own address, at most one answer
// per received frame. The first byte picks the data mode, the NAK switch, the direction,
// and (bit 4) whether the harness appends a good CRC to each chunk, so that the PDUs behind
// the CRC (the FC 6/16 configuration writes, FC 3/4 reads of both blocks) are reached.
#include "modbus/crc16.h"
#include "modbus/rtu_frame.h"
#include "polaris/device.h"

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>
#include <vector>

namespace {

namespace polaris = rs4sim::polaris;

void check(bool ok) {
  if (!ok) std::abort();
}

polaris::Options options_from(std::uint8_t selector) {
  polaris::Options o;
  o.family = polaris::Family::kPli02;
  o.beams = 127;
  o.address = 1;
  constexpr polaris::DataMode kModes[] = {polaris::DataMode::k485Mb, polaris::DataMode::kFl1,
                                          polaris::DataMode::kFl4, polaris::DataMode::kFl10};
  o.mode = kModes[selector % 4U];
  o.nak_on_error = (selector & 4U) != 0;
  o.direction =
      (selector & 8U) != 0 ? polaris::ScanDirection::kReverse : polaris::ScanDirection::kDirect;
  return o;
}

std::uint64_t drain(polaris::Device& d) {
  std::uint64_t sent = 0;
  while (auto frame = d.take_transmit()) {
    rs4sim::modbus::RtuFrame f;
    check(!rs4sim::modbus::decode(*frame, f));
    check(f.address == 1);
    ++sent;
  }
  return sent;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  polaris::Device device(options_from(data[0]));
  rs4sim::stream::TimePoint now{std::chrono::hours(1)};
  device.on_time(now);
  const std::uint16_t scene[] = {3, 4, 5, 40, 41, 127};
  check(!device.set_interrupted(scene, now));
  std::uint64_t sent = 0;
  std::size_t at = 1;
  while (at + 2 <= size) {
    now += std::chrono::microseconds(100 * data[at]);  // 0..25.5 ms: inside or after t3.5
    const std::size_t length = std::min<std::size_t>(data[at + 1], size - at - 2);
    std::vector<std::uint8_t> chunk(data + at + 2, data + at + 2 + length);
    if ((data[0] & 16U) != 0) {
      const std::uint16_t crc = rs4sim::modbus::crc16(chunk);
      chunk.push_back(static_cast<std::uint8_t>(crc & 0xFFU));
      chunk.push_back(static_cast<std::uint8_t>(crc >> 8U));
    }
    device.on_bytes(chunk, now);
    sent += drain(device);
    at += 2 + length;
  }
  for (int i = 0; i < 16; ++i) {  // framer, answers, the end of an auto-calibration
    const auto next = device.next_deadline();
    if (!next) break;
    now = std::max(now, *next);
    device.on_time(now);
    sent += drain(device);
  }
  check(!device.next_deadline());
  const auto& c = device.counters();
  const std::uint64_t frames = c.requests + c.crc_errors + c.too_short + c.oversized +
                               c.broadcasts + c.foreign_address + c.bad_function + c.bad_request +
                               c.bad_start + c.busy + c.writes + c.refused_writes;
  check(sent <= frames);
  check(sent == c.frames_sent);
  return 0;
}
