#include "app/runtime/line_capture.h"

#include <memory>
#include <stdexcept>

namespace rs4sim::app {

std::vector<std::uint8_t> line_capture_record(std::span<const std::uint8_t> bytes,
                                              stream::FrameDirection dir,
                                              stream::LineProtocol protocol) {
  std::vector<std::uint8_t> out;
  out.reserve(kLineRecordHeader + bytes.size());
  out.push_back(dir == stream::FrameDirection::kReceived ? 0 : 1);
  out.push_back(static_cast<std::uint8_t>(protocol));
  out.insert(out.end(), bytes.begin(), bytes.end());
  return out;
}

std::error_code LineCapture::open(const std::filesystem::path& path,
                                  stream::LineProtocol protocol, std::chrono::nanoseconds offset) {
  protocol_ = protocol;
  offset_ = offset;
  return dp::link::PcapFile::open(path, static_cast<dp::link::PcapLinkType>(kLinktypeUser1),
                                  file_);
}

void LineCapture::on_frame(std::span<const std::uint8_t> bytes, stream::TimePoint now,
                           stream::FrameDirection dir) {
  if (error_ || !file_.is_open() || bytes.empty()) return;
  const auto record = line_capture_record(bytes, dir, protocol_);
  const auto since = std::chrono::duration_cast<std::chrono::nanoseconds>(now.time_since_epoch());
  error_ = file_.write(record, since + offset_);
}

stream::FrameTap LineCapture::tap() {
  return [this](std::span<const std::uint8_t> bytes, stream::TimePoint now,
                stream::FrameDirection dir) { on_frame(bytes, now, dir); };
}

std::unique_ptr<LineCapture> open_line_capture(const std::string& option, const std::string& file,
                                               stream::LineProtocol protocol,
                                               stream::TimePoint clock_now) {
  if (file.empty()) return nullptr;
  const auto offset = std::chrono::duration_cast<std::chrono::nanoseconds>(
      std::chrono::system_clock::now().time_since_epoch() - clock_now.time_since_epoch());
  auto capture = std::make_unique<LineCapture>();
  if (const auto ec = capture->open(file, protocol, offset)) {
    throw std::runtime_error(option + ": cannot write '" + file + "': " + ec.message());
  }
  return capture;
}

}  // namespace rs4sim::app
