// Feeds the input to a Polaris slave on the shared line rig (stream/testing/line_rig.h) as
// chunks with gaps taken from the input itself (a gap byte, a length byte, the chunk), the
// line running the device's deadlines, and checks what it sends as it gives it out: only
// whole RTU frames with a good CRC for its own address, at most one answer per received
// frame, and the device idle at the end. The first byte picks the data mode, the NAK switch,
// the direction, and (bit 4) whether the harness appends a good CRC to each chunk, so that
// the PDUs behind the CRC (the FC 6/16 configuration writes, FC 3/4 reads of both blocks)
// are reached.
#include "modbus/crc16.h"
#include "modbus/rtu_frame.h"
#include "polaris/device.h"
#include "stream/testing/line_rig.h"

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


}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  std::uint64_t sent = 0;
  const auto on_sent = [&sent](std::span<const std::uint8_t> frame, rs4sim::stream::TimePoint,
                               rs4sim::stream::FrameDirection d) {
    if (d != rs4sim::stream::FrameDirection::kSent) return;
    rs4sim::modbus::RtuFrame f;
    check(!rs4sim::modbus::decode(frame, f));
    check(f.address == 1);
    ++sent;
  };
  rs4sim::stream::testing::LineRig<polaris::Device> rig(on_sent, options_from(data[0]));
  polaris::Device& device = rig.device();
  const std::uint16_t scene[] = {3, 4, 5, 40, 41, 127};
  check(!device.set_interrupted(scene, rig.now()));
  std::size_t at = 1;
  while (at + 2 <= size) {
    rig.run_for(std::chrono::microseconds(100 * data[at]));  // 0..25.5 ms: inside or after t3.5
    const std::size_t length = std::min<std::size_t>(data[at + 1], size - at - 2);
    std::vector<std::uint8_t> chunk(data + at + 2, data + at + 2 + length);
    if ((data[0] & 16U) != 0) {
      const std::uint16_t crc = rs4sim::modbus::crc16(chunk);
      chunk.push_back(static_cast<std::uint8_t>(crc & 0xFFU));
      chunk.push_back(static_cast<std::uint8_t>(crc >> 8U));
    }
    rig.send(chunk);
    (void)rig.take();  // checked as given out
    at += 2 + length;
  }
  // The last frame's t3.5, the scan, the answer's wire time, an auto-calibration's end.
  rig.run_for(device.calibration_time() + std::chrono::seconds(1));
  check(!device.next_deadline());
  check(!rig.on_the_wire());
  const auto& c = device.counters();
  const std::uint64_t frames = c.requests + c.crc_errors + c.too_short + c.oversized +
                               c.broadcasts + c.foreign_address + c.bad_function + c.bad_request +
                               c.bad_start + c.busy + c.writes + c.refused_writes;
  check(sent <= frames);
  check(sent == c.frames_sent);
  return 0;
}
