#include "dp/link/pcap.h"

#include "codec/writer.h"

#include <cerrno>

namespace rs4sim::dp::link {
namespace {

constexpr std::uint32_t kMagicNanoseconds = 0xA1B23C4D;
constexpr std::uint16_t kVersionMajor = 2;
constexpr std::uint16_t kVersionMinor = 4;

}  // namespace

std::array<std::uint8_t, kPcapFileHeaderSize> pcap_file_header(PcapLinkType type) {
  std::array<std::uint8_t, kPcapFileHeaderSize> out{};
  codec::Writer w(out);
  w.u32_le(kMagicNanoseconds);
  w.u16_le(kVersionMajor);
  w.u16_le(kVersionMinor);
  w.u32_le(0);  // thiszone: timestamps are UTC
  w.u32_le(0);  // sigfigs
  w.u32_le(kPcapSnapLength);
  w.u32_le(static_cast<std::uint32_t>(type));
  return out;
}

void append_pcap_record(std::vector<std::uint8_t>& out, std::span<const std::uint8_t> frame,
                        std::chrono::nanoseconds since_epoch) {
  const auto ns = since_epoch.count() < 0 ? std::int64_t{0} : since_epoch.count();
  const auto length = static_cast<std::uint32_t>(frame.size());
  codec::Appender w(out);
  w.u32_le(static_cast<std::uint32_t>(ns / 1'000'000'000));
  w.u32_le(static_cast<std::uint32_t>(ns % 1'000'000'000));
  w.u32_le(length);
  w.u32_le(length);
  w.bytes(frame);
}

std::error_code PcapFile::open(const std::filesystem::path& path, PcapLinkType type,
                               PcapFile& out) {
  errno = 0;
  out.file_.open(path, std::ios::binary | std::ios::trunc);
  // The OS's reason when the library left it (e.g. "No such file or directory").
  if (!out.file_) return {errno != 0 ? errno : EIO, std::generic_category()};
  out.flushed_at_.reset();
  const auto header = pcap_file_header(type);
  out.file_.write(reinterpret_cast<const char*>(header.data()),
                  static_cast<std::streamsize>(header.size()));
  out.file_.flush();
  if (!out.file_) return std::make_error_code(std::errc::io_error);
  out.records_ = 0;
  return {};
}

std::error_code PcapFile::write(std::span<const std::uint8_t> frame,
                                std::chrono::nanoseconds since_epoch) {
  if (!file_.is_open()) return std::make_error_code(std::errc::bad_file_descriptor);
  buffer_.clear();
  append_pcap_record(buffer_, frame, since_epoch);
  file_.write(reinterpret_cast<const char*>(buffer_.data()),
              static_cast<std::streamsize>(buffer_.size()));
  // The file follows the link within kFlushInterval of record time (a viewer reading the
  // growing file, a process killed hard) without a system call per telegram.
  if (!flushed_at_ || since_epoch - *flushed_at_ >= kFlushInterval ||
      since_epoch < *flushed_at_) {
    file_.flush();
    flushed_at_ = since_epoch;
  }
  if (!file_) return std::make_error_code(std::errc::io_error);
  ++records_;
  return {};
}

std::error_code PcapFile::flush() {
  if (!file_.is_open()) return std::make_error_code(std::errc::bad_file_descriptor);
  file_.flush();
  return file_ ? std::error_code{} : std::make_error_code(std::errc::io_error);
}

}  // namespace rs4sim::dp::link
