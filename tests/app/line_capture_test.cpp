// A byte line's capture (app/runtime/line_capture.h) byte for byte: the Polaris's P3 request
// and P4 answer [Polaris manual §8.2.3] over the in-memory line, each record with its
// direction and protocol byte, in the pcap nanosecond format (tcpdump.org "pcap-savefile",
// LINKTYPE_USER1 = 148 from "linktypes").
#include "app/runtime/line_capture.h"
#include "polaris/device.h"
#include "stream/memory_line.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

namespace rs4sim::app {
namespace {

using Bytes = std::vector<std::uint8_t>;

Bytes read_all(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::uint32_t le32(const Bytes& b, std::size_t at) {
  std::uint32_t v = 0;
  for (std::size_t i = 0; i < 4; ++i) v |= static_cast<std::uint32_t>(b[at + i]) << (8 * i);
  return v;
}

TEST(LineCapture, RecordIsDirectionProtocolThenBytes) {
  const Bytes frame{0x02, 0x01, 0x0C, 0xF3};  // METRON "Request OSSD status"
  EXPECT_EQ(line_capture_record(frame, stream::FrameDirection::kReceived,
                                stream::LineProtocol::kMetron),
            (Bytes{0x00, 0x02, 0x02, 0x01, 0x0C, 0xF3}));
  EXPECT_EQ(line_capture_record(frame, stream::FrameDirection::kSent,
                                stream::LineProtocol::kRs4Rs232),
            (Bytes{0x01, 0x04, 0x02, 0x01, 0x0C, 0xF3}));
}

TEST(LineCapture, PolarisExchangeOnTheMemoryLine) {
  const auto path = std::filesystem::temp_directory_path() /
                    ("rs4sim-line-capture-" + std::to_string(::getpid()) + ".pcap");
  polaris::Options o;
  o.family = polaris::Family::kPl10;
  o.beams = 40;
  o.mode = polaris::DataMode::kFl4;
  o.address = 1;
  polaris::Device device(o);
  stream::ManualClock clock;
  const std::array<std::uint16_t, 15> beams{9, 10, 11, 12, 13, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34};
  ASSERT_FALSE(device.set_interrupted(beams, clock.now()));
  std::vector<stream::LineFrame> replies;
  {
    LineCapture capture;
    ASSERT_FALSE(capture.open(path, stream::LineProtocol::kModbusRtu));
    stream::MemoryLine line(clock, device);
    line.set_frame_tap(capture.tap());
    line.start();
    const Bytes p3{0x01, 0x03, 0x20, 0x00, 0x00, 0x0A, 0xCE, 0x0D};
    line.write(p3);
    line.run_for(std::chrono::milliseconds(200));
    replies = line.take_received();
    EXPECT_EQ(capture.records(), 2U);
    EXPECT_FALSE(capture.error());
  }
  ASSERT_EQ(replies.size(), 1U);
  const Bytes file = read_all(path);
  std::filesystem::remove(path);
  const Bytes header{0x4D, 0x3C, 0xB2, 0xA1,  // magic, nanosecond timestamps
                     0x02, 0x00, 0x04, 0x00,  // version 2.4
                     0x00, 0x00, 0x00, 0x00,  // zone
                     0x00, 0x00, 0x00, 0x00,  // sigfigs
                     0xFF, 0xFF, 0x00, 0x00,  // snap length 65535
                     0x94, 0x00, 0x00, 0x00};  // LINKTYPE_USER1
  ASSERT_GE(file.size(), header.size());
  EXPECT_EQ(Bytes(file.begin(), file.begin() + 24), header);
  const Bytes record1{0x00, 0x03,  // master → device, Modbus RTU
                      0x01, 0x03, 0x20, 0x00, 0x00, 0x0A, 0xCE, 0x0D};  // P3
  const Bytes record2{0x01, 0x03,                                        // device → master
                      0x01, 0x03, 0x14,        // slave 1, FC 3, 20 bytes (P4)
                      0x00, 0x09, 0x00, 0x0D,  // object 1: 9..13
                      0x00, 0x19, 0x00, 0x22,  // object 2: 25..34
                      0x00, 0x00, 0x00, 0x00,  // objects 3 and 4: none
                      0x00, 0x00, 0x00, 0x00,  //
                      0x00, 0x09, 0x00, 0x22,  // overall 9..34
                      0x19, 0x5A};             // CRC
  ASSERT_EQ(file.size(), 24 + 16 + record1.size() + 16 + record2.size());
  EXPECT_EQ(le32(file, 32), record1.size());  // captured length
  EXPECT_EQ(le32(file, 36), record1.size());  // original length
  EXPECT_EQ(Bytes(file.begin() + 40, file.begin() + 40 + 10), record1);
  const std::size_t r2 = 40 + record1.size();
  EXPECT_EQ(le32(file, r2 + 8), record2.size());
  EXPECT_EQ(Bytes(file.begin() + static_cast<std::ptrdiff_t>(r2 + 16), file.end()), record2);
  // Timestamps: the clock's time since its epoch (offset 0); the answer's when it went out.
  const auto ns = [&](std::size_t at) {
    return std::chrono::seconds(le32(file, at)) + std::chrono::nanoseconds(le32(file, at + 4));
  };
  EXPECT_EQ(ns(r2), replies[0].start.time_since_epoch());
  EXPECT_LT(ns(24), ns(r2));
  EXPECT_GT(ns(24), std::chrono::hours(1));  // after the request's wire time from the start
}

TEST(LineCapture, UnwritableFileIsAClearError) {
  EXPECT_THROW(
      {
        try {
          (void)open_line_capture("--capture", "/nonexistent-dir/x.pcap",
                                  stream::LineProtocol::kGridScan, stream::TimePoint{});
        } catch (const std::runtime_error& e) {
          EXPECT_NE(std::string(e.what()).find("--capture: cannot write '/nonexistent-dir/x.pcap'"),
                    std::string::npos);
          throw;
        }
      },
      std::runtime_error);
  EXPECT_EQ(open_line_capture("--capture", "", stream::LineProtocol::kGridScan,
                              stream::TimePoint{}),
            nullptr);
}

}  // namespace
}  // namespace rs4sim::app
