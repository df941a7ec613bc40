#include "app/runtime/capture_option.h"

#include "app/runtime/cli_words.h"

#include <CLI/CLI.hpp>

#include <chrono>
#include <stdexcept>

namespace rs4sim::app {

void add_capture_options(CLI::App& cmd, CaptureOptions& options, bool byte_devices) {
  cmd.add_option("--capture", options.file,
                 std::string("write every telegram") +
                     (byte_devices ? " (a byte device: every frame, with its direction)" : "") +
                     " to this pcap file (open it in Wireshark with tools/wireshark/rs4sim.lua)");
  cmd.add_option("--capture-linktype", options.linktype,
                 std::string("user0 (LINKTYPE_USER0 147, default, the project's dissector) or 257 "
                             "(LINKTYPE_PROFIBUS_DL)") +
                     (byte_devices ? "; a byte device's file is always LINKTYPE_USER1" : ""))
      ->check(one_of("a capture link type", {"user0", "257"}));
}

void add_rs232_capture_option(CLI::App& cmd, CaptureOptions& options) {
  cmd.add_option("--capture-rs232", options.rs232_file,
                 "write the frames of the RS4's RS232 port (--rs232), with their direction, to "
                 "this pcap file (open it with tools/wireshark/rs4sim.lua)");
}

std::unique_ptr<dp::link::Capture> open_capture(const CaptureOptions& options) {
  return open_capture(options, dp::TimePoint{});
}

std::unique_ptr<dp::link::Capture> open_capture(const CaptureOptions& options,
                                                dp::TimePoint clock_now) {
  if (options.file.empty()) return nullptr;
  const auto type = options.linktype == "257" ? dp::link::PcapLinkType::kProfibusDl
                                              : dp::link::PcapLinkType::kUser0;
  const auto offset = std::chrono::duration_cast<std::chrono::nanoseconds>(
      std::chrono::system_clock::now().time_since_epoch() - clock_now.time_since_epoch());
  auto capture = std::make_unique<dp::link::Capture>();
  if (const auto ec = capture->open(options.file, type, offset)) {
    throw std::runtime_error("--capture: cannot write '" + options.file + "': " + ec.message());
  }
  return capture;
}

void attach_capture(dp::link::Capture* capture, dp::link::MemoryBus& bus) {
  if (capture == nullptr) return;
  bus.add_observer([capture](const dp::link::BusEvent& e) { capture->on_bus_event(e); });
}

}  // namespace rs4sim::app
