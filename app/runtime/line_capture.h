#pragma once
// `--capture FILE` of a byte device's line and `--capture-rs232 FILE` of the RS4's RS232 port
// (docs/capture.md#byte-lines): what a sniffer on the line would see, into a pcap file
// (dp/link/pcap.h, nanosecond format) with LINKTYPE_USER1 (148), which the project's Lua
// dissector (tools/wireshark/rs4sim.lua) binds to. Each record is
//
//   offset 0   direction: 0 = master → device (received by the device), 1 = device → master
//   offset 1   the line's protocol (stream::LineProtocol: 1 GridScan, 2 METRON, 3 Modbus RTU,
//              4 RS4 RS232, 0 raw)
//   offset 2.. the bytes, as the runner saw them: a frame the device sent, whole; the
//              master's bytes as the OS delivered them (a chunk may hold part of a frame or
//              several; on the in-memory line, one frame)
//
// Timestamps: the runner's `now` plus `offset` (wall clock at the start of a simulated run).

#include "dp/link/pcap.h"
#include "stream/frame_tap.h"

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <system_error>
#include <vector>

namespace rs4sim::app {

inline constexpr std::uint32_t kLinktypeUser1 = 148;
inline constexpr std::size_t kLineRecordHeader = 2;  // direction, protocol

// The record's bytes (header + frame), pure.
[[nodiscard]] std::vector<std::uint8_t> line_capture_record(std::span<const std::uint8_t> bytes,
                                                            stream::FrameDirection dir,
                                                            stream::LineProtocol protocol);

class LineCapture {
 public:
  // Errors: the file's open error.
  std::error_code open(const std::filesystem::path& path, stream::LineProtocol protocol,
                       std::chrono::nanoseconds offset = {});
  void on_frame(std::span<const std::uint8_t> bytes, stream::TimePoint now,
                stream::FrameDirection dir);
  // A tap for stream::ByteRunner / stream::MemoryLine writing into this capture.
  [[nodiscard]] stream::FrameTap tap();
  // The first write error (writing stops after it); empty while all is well.
  [[nodiscard]] std::error_code error() const noexcept { return error_; }
  [[nodiscard]] std::uint64_t records() const noexcept { return file_.records(); }
  std::error_code flush() { return file_.flush(); }

 private:
  dp::link::PcapFile file_;
  stream::LineProtocol protocol_ = stream::LineProtocol::kRaw;
  std::chrono::nanoseconds offset_{};
  std::error_code error_;
};

// Opens `file` for a run whose clock reads `clock_now` now (timestamps are then wall-clock
// time); nullptr for an empty name. Throws std::runtime_error naming `option` when the file
// cannot be written.
std::unique_ptr<LineCapture> open_line_capture(const std::string& option, const std::string& file,
                                               stream::LineProtocol protocol,
                                               stream::TimePoint clock_now);

}  // namespace rs4sim::app
