#pragma once
// A telegram capture of a link into a pcap file (dp/link/pcap.h, docs/capture.md): plugs into
// MemoryBus::add_observer (simulated time) or StationRunner::set_frame_tap (real time).
//
// What a sniffer on the line would see: a telegram dropped or silenced by fault injection
// never reached the wire and is not written; a delayed one is written at its arrival; a
// corrupted one is written as sent (the capture shows what the station transmitted).
// Timestamps: the link's TimePoint since its clock's epoch, plus `offset` (e.g. the wall
// clock at the start of a simulated run, so Wireshark shows a sensible date).

#include "dp/link/memory_bus.h"
#include "dp/link/pcap.h"
#include "dp/link/station_runner.h"

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <system_error>

namespace rs4sim::dp::link {

class Capture {
 public:
  // Errors: the file's open error.
  std::error_code open(const std::filesystem::path& path, PcapLinkType type,
                       std::chrono::nanoseconds offset = {});
  void on_bus_event(const BusEvent& e);
  void on_frame(std::span<const std::uint8_t> frame, TimePoint now, FrameDirection dir);
  // The first write error (the capture stops writing after it); empty while all is well.
  [[nodiscard]] std::error_code error() const noexcept { return error_; }
  [[nodiscard]] std::uint64_t records() const noexcept { return file_.records(); }

 private:
  void write(std::span<const std::uint8_t> frame, TimePoint at);

  PcapFile file_;
  std::chrono::nanoseconds offset_{};
  std::error_code error_;
};

}  // namespace rs4sim::dp::link
