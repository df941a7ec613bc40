#pragma once
// Telegram captures in the classic libpcap file format, nanosecond variant (magic
// 0xA1B23C4D), for Wireshark/tshark (docs/capture.md). Each record is one FDL telegram
// exactly as on the wire, from the start delimiter to the end delimiter (or the single
// short-acknowledge byte E5) [IEC 61158-4-3 frame formats] — the payload LINKTYPE_PROFIBUS_DL
// (257) defines. Wireshark has no dissector for 257, so the default link type is
// LINKTYPE_USER0 (147) with the same payload, which the project's Lua dissector
// (tools/wireshark/rs4sim.lua) binds to.
//
// The byte builders are pure; PcapFile adds the file. Timestamps come from the caller.

#include <array>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <optional>
#include <span>
#include <system_error>
#include <vector>

namespace rs4sim::dp::link {

enum class PcapLinkType : std::uint32_t {
  kUser0 = 147,       // LINKTYPE_USER0: the project's dissector
  kProfibusDl = 257,  // LINKTYPE_PROFIBUS_DL
};

inline constexpr std::size_t kPcapFileHeaderSize = 24;
inline constexpr std::size_t kPcapRecordHeaderSize = 16;
inline constexpr std::uint32_t kPcapSnapLength = 65535;

// Global header: magic, version 2.4, zone 0, sigfigs 0, snap length, link type; little-endian.
std::array<std::uint8_t, kPcapFileHeaderSize> pcap_file_header(PcapLinkType type);
// Appends one record: seconds, nanoseconds, captured length, original length, the frame.
// `since_epoch` below 0 is written as 0.
void append_pcap_record(std::vector<std::uint8_t>& out, std::span<const std::uint8_t> frame,
                        std::chrono::nanoseconds since_epoch);

// A capture file. Writes the header at open; every record is flushed at once so that a
// capture of a process that is killed stays readable up to the last telegram.
class PcapFile {
 public:
  // Errors: the open/write error of the file (std::errc from the stream).
  static std::error_code open(const std::filesystem::path& path, PcapLinkType type, PcapFile& out);
  // Buffered: the file is flushed at the first record and then whenever kFlushInterval of
  // record time has passed, and when this object is destroyed.
  std::error_code write(std::span<const std::uint8_t> frame, std::chrono::nanoseconds since_epoch);
  std::error_code flush();
  static constexpr std::chrono::nanoseconds kFlushInterval = std::chrono::milliseconds(100);
  [[nodiscard]] std::uint64_t records() const noexcept { return records_; }
  [[nodiscard]] bool is_open() const noexcept { return file_.is_open(); }

 private:
  std::ofstream file_;
  std::vector<std::uint8_t> buffer_;
  std::uint64_t records_ = 0;
  std::optional<std::chrono::nanoseconds> flushed_at_;
};

}  // namespace rs4sim::dp::link
