#pragma once
// The steps of a proxy sync and the manual's error positions they report
// ([RS4 manual §6.4]: ERROR_NUMBER_FB = 0xPPKK, PP the position 01..50 where the Proxy-FB
// failed, KK 01 = a write/read/copy system function failed, 02 = bad record content).
// Each step has the positions the manual lists for its kind of failure; the whole map is
// the table in docs/proxy.md "Position map".

#include <cstdint>
#include <string_view>

namespace rs4sim::proxy {

enum class Step : std::uint8_t {
  kIdle = 0,
  kLoadCurrent,      // archive: the station's current set (copy load → work memory)
  kBegin,            // 98 PROFI_CMD_PROXY_BEGIN
  kIdentify1,        // 60 IDENTIFY
  kIdentify2,        // 60 IDENTIFY repeated and compared
  kUpload1,          // 61 UPLOAD_CHUNK x
  kUpload2,          // 61 UPLOAD_CHUNK x repeated and compared (0x2B2x)
  kStoreUpload,      // archive: store the uploaded set (copy work → load memory)
  kLoadDownload,     // archive: the set to download (copy load → work memory)
  kDownloadBegin,    // 62 DOWNLOAD_BEGIN
  kDownloadChunk,    // 63 DOWNLOAD_CHUNK x (echo CRC compared, 0x2B1x)
  kDownloadCommit,   // 64 DOWNLOAD_COMMIT (active CRC compared, 0x2B09)
  kReidentify1,      // 60 IDENTIFY after the download (checksum re-read)
  kReidentify2,      // 60 IDENTIFY after the download repeated and compared
  kStoreSerial,      // archive: new serial number / restore done (copy work → load memory)
  kEnd,              // 99 PROFI_CMD_PROXY_END success: OSSD release
  kVerifyIdentify1,  // background verify after the release: 60 IDENTIFY
  kVerifyIdentify2,  // background verify: 60 IDENTIFY repeated and compared
  kVerifyUpload1,    // background verify: 61 UPLOAD_CHUNK x
  kVerifyUpload2,    // background verify: 61 UPLOAD_CHUNK x repeated, compared with archive
  kBreak,            // 65 DOWNLOAD_BREAK after a failed download (failure report)
  kEndFailed,        // 99 PROFI_CMD_PROXY_END failed (failure report)
  kRetryWait,        // after a failure: wait for the retry delay and the next request
};
inline constexpr std::size_t kStepCount = 23;

// The positions of one step; 0 where the step has no such failure.
struct StepPositions {
  std::uint8_t write = 0;  // a WRITE record was refused          → 0xPP01
  std::uint8_t read = 0;   // a READ record was refused / no answer → 0xPP01
  std::uint8_t bad = 0;    // the answer is malformed or wrong     → 0xPP02
  std::uint8_t copy = 0;   // the archive failed                   → 0xPP01
};

StepPositions positions(Step step) noexcept;
std::string_view to_string(Step step) noexcept;

enum class FailureKind : std::uint8_t { kWrite, kRead, kBadRecord, kCopy };

// 0xPPKK for a failure of `kind` in `step`; 0 when the step has no position for it.
std::uint16_t error_number_fb(Step step, FailureKind kind) noexcept;

}  // namespace rs4sim::proxy
