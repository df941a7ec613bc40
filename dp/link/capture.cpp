#include "dp/link/capture.h"

namespace rs4sim::dp::link {

std::error_code Capture::open(const std::filesystem::path& path, PcapLinkType type,
                              std::chrono::nanoseconds offset) {
  offset_ = offset;
  error_ = PcapFile::open(path, type, file_);
  return error_;
}

void Capture::on_bus_event(const BusEvent& e) {
  switch (e.fate) {
    case Fate::kDropped:
    case Fate::kSilenced: return;  // never on the wire
    case Fate::kDelayed: write(e.wire, e.arrival); return;
    case Fate::kDelivered:
    case Fate::kCorrupted:
    case Fate::kUnroutable: write(e.wire, e.time); return;
  }
}

void Capture::on_frame(std::span<const std::uint8_t> frame, TimePoint now, FrameDirection) {
  write(frame, now);
}

void Capture::write(std::span<const std::uint8_t> frame, TimePoint at) {
  if (error_ || !file_.is_open()) return;
  const auto since = std::chrono::duration_cast<std::chrono::nanoseconds>(at.time_since_epoch());
  error_ = file_.write(frame, since + offset_);
}

}  // namespace rs4sim::dp::link
