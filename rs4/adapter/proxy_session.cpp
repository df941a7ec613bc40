// ProxySession: sync start/stop and the RS4's transfer commands 0x60..0x65 — EXTENSION
// ([docs/proxy-protocol.md], [RS4 manual §7.1, §7.2]).
#include "rs4/adapter/proxy_session.h"

#include "rs4/adapter/rs4_commands.h"
#include "rs4/scanner/crc32.h"
#include "rs4/scanner/parameter_codec.h"

#include <algorithm>
#include <utility>

namespace rs4sim::rs4::adapter {

namespace {

using protocol::TransferStatus;

constexpr std::size_t kChunkSize = protocol::kMaxChunkSize;
constexpr auto kSetSize = static_cast<std::uint16_t>(scanner::kParameterSetSize);
constexpr std::size_t kChunkCount = (scanner::kParameterSetSize + kChunkSize - 1) / kChunkSize;
static_assert(scanner::kParameterSetSize <= 0xFFFF, "the set size travels in 16 bits");
static_assert(kChunkCount <= protocol::kMaxChunkCount, "x of 0x2B1x/0x2B2x is one hex digit");

// Off, initialising or in its error state, the RS4 answers no transfer command.
bool operational(scanner::ScannerState s) noexcept {
  return s == scanner::ScannerState::kMeasuring || s == scanner::ScannerState::kConfiguration;
}

bool is_download(const protocol::TransferRequest& r) noexcept {
  return !std::holds_alternative<protocol::IdentifyRequest>(r) &&
         !std::holds_alternative<protocol::UploadChunkRequest>(r);
}

// A request that does not decode: too short/long → kWrongLength; an empty or oversized
// chunk → kSizeMismatch.
TransferStatus status_of(std::error_code decode_error) noexcept {
  return decode_error == protocol::ProtocolError::kBadAnswerValue ? TransferStatus::kSizeMismatch
                                                                  : TransferStatus::kWrongLength;
}

protocol::TransferAnswer refused(TransferStatus s) {
  protocol::TransferAnswer a;
  a.status = s;
  return a;
}

protocol::TransferAnswer ok(protocol::TransferAnswerBody body) {
  protocol::TransferAnswer a;
  a.body = std::move(body);
  return a;
}

}  // namespace

protocol::SyncDirection sync_direction(protocol::SyncReason why, bool factory_settings) noexcept {
  if (why == protocol::SyncReason::kPcAdapterRemoved ||
      why == protocol::SyncReason::kUserParametrisation) {
    return protocol::SyncDirection::kUpload;
  }
  if (factory_settings) return protocol::SyncDirection::kDownload;
  return protocol::SyncDirection::kVerify;
}

void ProxySession::reset() noexcept { *this = ProxySession{}; }

void ProxySession::start(scanner::Scanner& rs4, scanner::TimePoint now) {
  close_download(rs4, now);
  running_ = true;
  direction_ = sync_direction(reason_, rs4.factory_settings());
}

void ProxySession::stop(scanner::Scanner& rs4, scanner::TimePoint now) {
  running_ = false;
  close_download(rs4, now);
}

void ProxySession::close_download(scanner::Scanner& rs4, scanner::TimePoint now) {
  const bool was_open = std::exchange(download_, Download{}).open;
  if (was_open && rs4.status().state == scanner::ScannerState::kConfiguration) {
    (void)rs4.leave_configuration(now);
  }
}

std::vector<std::uint8_t> ProxySession::answer(std::span<const std::uint8_t> command,
                                               scanner::Scanner& rs4, scanner::TimePoint now,
                                               bool authorised) {
  const auto request = protocol::decode_request(command);
  Answer a = request ? dispatch(request.value(), rs4, now, authorised)
                     : refused(status_of(request.error()));
  a.code = !command.empty() && protocol::is_transfer_code(command[0])
               ? static_cast<protocol::TransferCode>(command[0])
               : protocol::TransferCode::kIdentify;
  a.options = rs4_prefix(rs4).options;
  auto bytes = protocol::encode_answer(a);
  if (bytes) return std::move(bytes.value());
  a.status = TransferStatus::kNotOperational;  // not reached: the options come from the model
  a.body.reset();
  a.options = protocol::OptionBytes{};
  auto fallback = protocol::encode_answer(a);
  return fallback ? std::move(fallback.value()) : std::vector<std::uint8_t>{};
}

ProxySession::Answer ProxySession::dispatch(const protocol::TransferRequest& request,
                                            scanner::Scanner& rs4, scanner::TimePoint now,
                                            bool authorised) {
  if (!operational(rs4.status().state)) return refused(TransferStatus::kNotOperational);
  // The proxy in a sync it was asked for ([RS4 manual §7.1, §7.2]), or a user with the
  // password, may write a set.
  if (is_download(request) && !running_ && !authorised) {
    return refused(TransferStatus::kNoSyncRunning);
  }
  if (std::holds_alternative<protocol::IdentifyRequest>(request)) return identify(rs4);
  if (const auto* up = std::get_if<protocol::UploadChunkRequest>(&request)) {
    return upload_chunk(*up, rs4);
  }
  if (const auto* begin = std::get_if<protocol::DownloadBeginRequest>(&request)) {
    return download_begin(*begin, rs4, now);
  }
  if (const auto* chunk = std::get_if<protocol::DownloadChunkRequest>(&request)) {
    return download_chunk(*chunk);
  }
  if (std::holds_alternative<protocol::DownloadCommitRequest>(request)) {
    return download_commit(rs4, now);
  }
  return download_break(rs4, now);
}

ProxySession::Answer ProxySession::identify(const scanner::Scanner& rs4) const {
  const auto& id = rs4.parameters().identity;
  protocol::Identification i;
  i.device_type = id.device_type;
  i.serial_number = id.serial_number;
  i.firmware_major = id.firmware_major;
  i.firmware_minor = id.firmware_minor;
  i.format_version = scanner::kParameterFormatVersion;
  i.set_size = kSetSize;
  i.chunk_size = static_cast<std::uint16_t>(kChunkSize);
  i.set_crc32 = rs4.transfer_checksum();
  i.flags = static_cast<std::uint8_t>((rs4.factory_settings() ? protocol::kFlagFactoryDefault : 0) |
                                      (download_.open ? protocol::kFlagDownloadOpen : 0));
  i.change_counter = rs4.change_counter();
  return ok(protocol::IdentifyAnswer{i});
}

ProxySession::Answer ProxySession::upload_chunk(const protocol::UploadChunkRequest& r,
                                                const scanner::Scanner& rs4) {
  if (r.chunk >= kChunkCount) return refused(TransferStatus::kBadChunk);
  const auto blob = scanner::encode_for_transfer(rs4.parameters());
  const std::size_t offset = std::size_t{r.chunk} * kChunkSize;
  const std::size_t length = std::min(kChunkSize, blob.size() - offset);
  protocol::UploadChunkAnswer a;
  a.chunk = r.chunk;
  a.chunk_count = static_cast<std::uint8_t>(kChunkCount);
  a.data.assign(blob.begin() + static_cast<std::ptrdiff_t>(offset),
                blob.begin() + static_cast<std::ptrdiff_t>(offset + length));
  a.crc32 = scanner::crc32_iso_hdlc(a.data);
  return ok(std::move(a));
}

// [RS4 manual §7.1.2]: the OSSDs go off when the download starts, not at its commit: the RS4
// enters its configuration mode here (a repeated BEGIN restarts the download inside it).
ProxySession::Answer ProxySession::download_begin(const protocol::DownloadBeginRequest& r,
                                                  scanner::Scanner& rs4, scanner::TimePoint now) {
  if (r.size != kSetSize) return refused(TransferStatus::kSizeMismatch);
  if (!download_.open && !rs4.enter_configuration(now)) {
    return refused(TransferStatus::kNotOperational);
  }
  download_ = Download{true, r.size, r.crc32, 0, {}};
  download_.bytes.reserve(r.size);
  return ok(protocol::DownloadBeginAnswer{static_cast<std::uint8_t>(kChunkCount),
                                          static_cast<std::uint16_t>(kChunkSize)});
}

ProxySession::Answer ProxySession::download_chunk(const protocol::DownloadChunkRequest& r) {
  if (!download_.open) return refused(TransferStatus::kNoDownload);
  if (r.chunk != download_.next_chunk || r.chunk >= kChunkCount) {
    return refused(TransferStatus::kBadChunk);  // strictly in order
  }
  const std::size_t length = std::min(kChunkSize, download_.size - download_.bytes.size());
  if (r.data.size() != length) return refused(TransferStatus::kSizeMismatch);
  download_.bytes.insert(download_.bytes.end(), r.data.begin(), r.data.end());
  ++download_.next_chunk;
  return ok(protocol::DownloadChunkAnswer{r.chunk, scanner::crc32_iso_hdlc(r.data)});
}

// Every refusal leaves the RS4's set as it was; the download is closed either way and the RS4
// leaves its configuration mode (the start interlock applies as at every start).
ProxySession::Answer ProxySession::download_commit(scanner::Scanner& rs4, scanner::TimePoint now) {
  if (!download_.open) return refused(TransferStatus::kNoDownload);
  const Download& d = download_;  // closed below, after the last use
  const auto answer = [&]() -> Answer {
    if (d.bytes.size() != d.size) return refused(TransferStatus::kSizeMismatch);
    if (scanner::crc32_iso_hdlc(d.bytes) != d.crc32) return refused(TransferStatus::kCrcMismatch);
    const auto decoded = scanner::decode(d.bytes);
    if (!decoded) return refused(TransferStatus::kInvalidSet);
    const auto merged = scanner::merge_download(rs4.parameters(), decoded.value());
    if (scanner::validate(merged)) return refused(TransferStatus::kInvalidSet);
    if (rs4.status().state != scanner::ScannerState::kConfiguration) {
      return refused(TransferStatus::kNotOperational);  // left configuration meanwhile
    }
    if (!rs4.set_parameters(merged, now)) return refused(TransferStatus::kInvalidSet);
    return ok(protocol::DownloadCommitAnswer{rs4.transfer_checksum()});
  }();
  close_download(rs4, now);
  return answer;
}

// [docs/proxy-protocol.md]: an explicit break rolls the RS4 back to factory settings.
ProxySession::Answer ProxySession::download_break(scanner::Scanner& rs4, scanner::TimePoint now) {
  if (!download_.open) return refused(TransferStatus::kNoDownload);
  download_ = Download{};
  rs4.reset_to_factory_default(now);
  return ok(protocol::DownloadBreakAnswer{
      static_cast<std::uint8_t>(rs4.factory_settings() ? protocol::kFlagFactoryDefault : 0)});
}

}  // namespace rs4sim::rs4::adapter
