#pragma once
// The RS4 commands of the proxy parameter service — EXTENSION
// ([docs/decisions.md#rs4-extensions], byte layout and examples in docs/proxy-protocol.md).
//
// The manual describes what the Proxy-FB achieves ([RS4 manual §6.4, §6.5, §7.1, §7.2]) but not
// the RS4 commands behind it. rs4sim defines them as RS4 commands carried in the acyclic block
// protocol ([RS4 manual §5.2.1]) like any other RS4 command: a request body is
//   CMD | option 1 (0x01: one option byte, state "none") | fields
// and the RS4 answers with the same CMD, its current option bytes ([RS4 manual §5.2.3]),
// a status byte and the fields. A status other than kOk is the RS4's error number the
// proxy reports as ERROR_NUMBER_RS4 ([RS4 manual §6.4]).
//
//   60 IDENTIFY          → identification: device type, serial number, firmware, format
//                          version, set size, chunk size, set CRC-32, flags, change counter
//   61 UPLOAD_CHUNK x    → chunk x of the encoded set with its CRC-32 (read in chunks;
//                          the proxy repeats each read and compares, 0x2B2x)
//   62 DOWNLOAD_BEGIN    → opens a download of `size` bytes with whole-set CRC-32
//   63 DOWNLOAD_CHUNK x  → chunk x written; the answer echoes the CRC-32 of what arrived
//                          (the proxy compares it, 0x2B1x)
//   64 DOWNLOAD_COMMIT   → the RS4 checks the whole CRC, decodes and validates the set,
//                          keeps its own user passwords and identity, and applies it; the
//                          answer carries the CRC-32 of the set now active (re-read, 0x2B09)
//   65 DOWNLOAD_BREAK    → explicit break: the RS4 rolls back to factory settings and says so
//
// Every whole command and answer stays below the block protocol's 1100 bytes
// ([RS4 manual §5.2.1], error 0x2A06): chunks carry at most kMaxChunkSize bytes.

#include "rs4/protocol/errors.h"
#include "rs4/protocol/option_bytes.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <variant>
#include <vector>

namespace rs4sim::rs4::protocol {

enum class TransferCode : std::uint8_t {
  kIdentify = 0x60,
  kUploadChunk = 0x61,
  kDownloadBegin = 0x62,
  kDownloadChunk = 0x63,
  kDownloadCommit = 0x64,
  kDownloadBreak = 0x65,
};
[[nodiscard]] bool is_transfer_code(std::uint8_t code) noexcept;

inline constexpr std::size_t kMaxChunkSize = 1024;  // 1037-byte answer < 1100
inline constexpr std::size_t kMaxChunkCount = 16;   // x of 0x2B1x / 0x2B2x is one hex digit
inline constexpr std::uint8_t kRequestOption1 = 0x01;

// Status byte of every answer (ERROR_NUMBER_RS4 when not kOk).
enum class TransferStatus : std::uint8_t {
  kOk = 0,
  kWrongLength = 1,      // request too short or too long for its command
  kBadChunk = 2,         // chunk number outside 0..count-1, or out of order in a download
  kNoDownload = 3,       // chunk/commit/break without DOWNLOAD_BEGIN
  kSizeMismatch = 4,     // DOWNLOAD_BEGIN size not the device's set size; chunk length wrong
  kCrcMismatch = 5,      // commit: the received bytes do not have the announced CRC-32
  kInvalidSet = 6,       // commit: the set does not decode or does not validate
  kNotOperational = 7,   // the RS4 is off, initialising or in its error state
  kNoSyncRunning = 8,    // download outside a sync without an accepted password
  kAdapterAttached = 9,  // the PC adapter is switched through ([RS4 manual §7.1, §7.2])
};
[[nodiscard]] const char* to_string(TransferStatus s) noexcept;

// ---- requests (master → RS4) -----------------------------------------------------------
struct IdentifyRequest {
  static constexpr TransferCode kCode = TransferCode::kIdentify;
  friend bool operator==(const IdentifyRequest&, const IdentifyRequest&) = default;
};
struct UploadChunkRequest {
  static constexpr TransferCode kCode = TransferCode::kUploadChunk;
  std::uint8_t chunk = 0;
  friend bool operator==(const UploadChunkRequest&, const UploadChunkRequest&) = default;
};
struct DownloadBeginRequest {
  static constexpr TransferCode kCode = TransferCode::kDownloadBegin;
  std::uint16_t size = 0;   // bytes of the encoded set
  std::uint32_t crc32 = 0;  // CRC-32/ISO-HDLC of those bytes
  friend bool operator==(const DownloadBeginRequest&, const DownloadBeginRequest&) = default;
};
struct DownloadChunkRequest {
  static constexpr TransferCode kCode = TransferCode::kDownloadChunk;
  std::uint8_t chunk = 0;
  std::span<const std::uint8_t> data;  // views the input when decoded
  friend bool operator==(const DownloadChunkRequest& a, const DownloadChunkRequest& b) {
    return a.chunk == b.chunk &&
           std::equal(a.data.begin(), a.data.end(), b.data.begin(), b.data.end());
  }
};
struct DownloadCommitRequest {
  static constexpr TransferCode kCode = TransferCode::kDownloadCommit;
  friend bool operator==(const DownloadCommitRequest&, const DownloadCommitRequest&) = default;
};
struct DownloadBreakRequest {
  static constexpr TransferCode kCode = TransferCode::kDownloadBreak;
  friend bool operator==(const DownloadBreakRequest&, const DownloadBreakRequest&) = default;
};
using TransferRequest =
    std::variant<IdentifyRequest, UploadChunkRequest, DownloadBeginRequest, DownloadChunkRequest,
                 DownloadCommitRequest, DownloadBreakRequest>;

[[nodiscard]] TransferCode request_code(const TransferRequest& request) noexcept;
// The one encoder of a request body, for both framings: behind the block header on
// PROFIBUS (option 1 = kRequestOption1, no password) and inside the RS232 frame behind the
// optical PC adapter, where `prefix` may carry option 1 bit 5 with the 8-byte password and
// bit 6 "acknowledge" ([roboticslibrary/rl LeuzeRs4.cpp], docs/rs232.md).
// kBadAnswerValue (used for "bad argument") for a chunk larger than kMaxChunkSize;
// kBadFieldPair from the prefix's options.
Result<std::vector<std::uint8_t>> encode_request(const TransferRequest& request,
                                                 const TelegramPrefix& prefix);
// The PROFIBUS form: option 1 = kRequestOption1.
Result<std::vector<std::uint8_t>> encode_request(const TransferRequest& request);

// Device side. Errors: kBadCommandByte (not a transfer code), the prefix errors of
// decode_prefix, kTruncated / kTrailingBytes for a wrong length (the device answers
// TransferStatus::kWrongLength), kBadAnswerValue for an empty or oversized chunk.
Result<TransferRequest> decode_request(std::span<const std::uint8_t> body);

// ---- answers (RS4 → master) ------------------------------------------------------------
inline constexpr std::uint8_t kFlagFactoryDefault = 0x01;  // the set is the factory setting
inline constexpr std::uint8_t kFlagDownloadOpen = 0x02;    // a download is open
inline constexpr std::uint8_t kFlagsDefined = 0x03;

struct Identification {
  std::uint16_t device_type = 0;
  std::uint32_t serial_number = 0;
  std::uint8_t firmware_major = 0;
  std::uint8_t firmware_minor = 0;
  std::uint8_t format_version = 0;  // of the parameter set encoding
  std::uint16_t set_size = 0;
  std::uint16_t chunk_size = 0;  // 1..kMaxChunkSize
  std::uint32_t set_crc32 = 0;
  std::uint8_t flags = 0;            // kFlag…
  std::uint16_t change_counter = 0;  // counts every change of the set since manufacture
  [[nodiscard]] bool factory_default() const noexcept { return (flags & kFlagFactoryDefault) != 0; }
  // ceil(set_size / chunk_size)
  [[nodiscard]] std::size_t chunk_count() const noexcept;
  friend bool operator==(const Identification&, const Identification&) = default;
};
inline constexpr std::size_t kIdentificationSize = 20;

struct IdentifyAnswer {
  static constexpr TransferCode kCode = TransferCode::kIdentify;
  Identification identification;
  friend bool operator==(const IdentifyAnswer&, const IdentifyAnswer&) = default;
};
struct UploadChunkAnswer {
  static constexpr TransferCode kCode = TransferCode::kUploadChunk;
  std::uint8_t chunk = 0;
  std::uint8_t chunk_count = 0;
  std::uint32_t crc32 = 0;  // of data
  std::vector<std::uint8_t> data;
  friend bool operator==(const UploadChunkAnswer&, const UploadChunkAnswer&) = default;
};
struct DownloadBeginAnswer {
  static constexpr TransferCode kCode = TransferCode::kDownloadBegin;
  std::uint8_t chunk_count = 0;
  std::uint16_t chunk_size = 0;
  friend bool operator==(const DownloadBeginAnswer&, const DownloadBeginAnswer&) = default;
};
struct DownloadChunkAnswer {
  static constexpr TransferCode kCode = TransferCode::kDownloadChunk;
  std::uint8_t chunk = 0;
  std::uint32_t echo_crc32 = 0;  // of the bytes the RS4 received
  friend bool operator==(const DownloadChunkAnswer&, const DownloadChunkAnswer&) = default;
};
struct DownloadCommitAnswer {
  static constexpr TransferCode kCode = TransferCode::kDownloadCommit;
  std::uint32_t active_crc32 = 0;  // of the set now active (passwords kept)
  friend bool operator==(const DownloadCommitAnswer&, const DownloadCommitAnswer&) = default;
};
struct DownloadBreakAnswer {
  static constexpr TransferCode kCode = TransferCode::kDownloadBreak;
  std::uint8_t flags = 0;  // kFlagFactoryDefault once rolled back
  friend bool operator==(const DownloadBreakAnswer&, const DownloadBreakAnswer&) = default;
};
using TransferAnswerBody =
    std::variant<IdentifyAnswer, UploadChunkAnswer, DownloadBeginAnswer, DownloadChunkAnswer,
                 DownloadCommitAnswer, DownloadBreakAnswer>;

// An answer: the code it answers, the RS4's option bytes, the status, and the body (only
// for kOk; a refused request carries the status alone).
struct TransferAnswer {
  TransferCode code = TransferCode::kIdentify;
  OptionBytes options;
  TransferStatus status = TransferStatus::kOk;
  std::optional<TransferAnswerBody> body;
  friend bool operator==(const TransferAnswer&, const TransferAnswer&) = default;
};

// Device side: CMD, option bytes, status, fields. A kOk answer needs the body matching
// `code` (kBadAnswerValue otherwise); kBadFieldPair from the options.
Result<std::vector<std::uint8_t>> encode_answer(const TransferAnswer& answer);

// Master side. Errors: kBadAnswerCode (not a transfer code), prefix errors, kTruncated,
// kTrailingBytes, kBadAnswerValue (status undefined, flags reserved bits, chunk number
// ≥ count, chunk longer than kMaxChunkSize, chunk size 0 or > kMaxChunkSize).
Result<TransferAnswer> decode_answer(std::span<const std::uint8_t> body);

}  // namespace rs4sim::rs4::protocol
