// ProxySync: the steps of a sync and the scenario decision ([RS4 manual §7.1, §7.2];
// sequence in docs/proxy-protocol.md, position map in docs/proxy.md).
#include "proxy/proxy_sync.h"
#include "proxy/set_summary.h"
#include "rs4/scanner/identity_text.h"
#include "rs4/protocol/adapter_command.h"
#include "rs4/protocol/telegram.h"
#include "storage/crc32.h"

#include <algorithm>
#include <string>
#include <utility>

namespace rs4sim::proxy {

namespace protocol = rs4::protocol;

namespace {
constexpr std::uint16_t kAdapterCrcCompare = 0x2B09;  // [RS4 manual §5.3] table 5.3-3
constexpr std::uint16_t kAdapterEchoCrc = 0x2B10;     // + chunk: echo CRC of chunk x wrong
constexpr std::uint16_t kAdapterReadRepeat = 0x2B20;  // + chunk: read repetition differs

std::uint16_t with_chunk(std::uint16_t base, std::size_t chunk) {
  return static_cast<std::uint16_t>(base | (chunk & 0x0F));
}
std::vector<std::uint8_t> identify_command() {
  return protocol::encode_request(protocol::IdentifyRequest{}).value();
}
bool is_first_read(Step s) {
  return s == Step::kIdentify1 || s == Step::kReidentify1 || s == Step::kVerifyIdentify1 ||
         s == Step::kUpload1 || s == Step::kVerifyUpload1;
}
Step repeat_of(Step s) {  // the step that repeats a first read
  return static_cast<Step>(static_cast<std::uint8_t>(s) + 1);
}
}  // namespace

void ProxySync::load_current(dp::TimePoint now) {
  step_ = Step::kLoadCurrent;
  auto current = archive_.current(config_.station);
  if (current) {
    current_ = std::move(current).value();
    known_serial_ = current_->version.serial_number;
    if (known_serial_.empty() && !load_known_serial()) {  // a restore carries no serial
      fail(FailureKind::kCopy, now);
      return;
    }
  } else if (current.error().code != storage::ArchiveError::kNotFound &&
             current.error().code != storage::ArchiveError::kUnknownStation) {
    fail(FailureKind::kCopy, now);
    return;
  }
  sync_open_ = true;  // from the 98 WRITE on the device may run a sync
  begin_exchange(Step::kBegin, protocol::encode_command(protocol::ProxyBeginCommand{}), now);
}

// The serial number seen last on the station (storage/types.h StationInfo::serials).
bool ProxySync::load_known_serial() {
  const auto stations = archive_.stations();
  if (!stations) return false;
  for (const auto& s : stations.value()) {
    if (s.key != config_.station) continue;
    const auto last =
        std::max_element(s.serials.begin(), s.serials.end(),
                         [](const auto& a, const auto& b) { return a.last_seen < b.last_seen; });
    if (last != s.serials.end()) known_serial_ = last->serial_number;
  }
  return true;
}

void ProxySync::on_answer(std::span<const std::uint8_t> answer, dp::TimePoint now) {
  switch (step_) {
    case Step::kBegin: on_begin(answer, now); return;
    case Step::kIdentify1:
    case Step::kIdentify2:
    case Step::kReidentify1:
    case Step::kReidentify2:
    case Step::kVerifyIdentify1:
    case Step::kVerifyIdentify2: on_identify(answer, now); return;
    case Step::kUpload1:
    case Step::kUpload2:
    case Step::kVerifyUpload1:
    case Step::kVerifyUpload2: on_upload(answer, now); return;
    case Step::kDownloadBegin:
    case Step::kDownloadChunk:
    case Step::kDownloadCommit: on_download(answer, now); return;
    case Step::kEnd: on_end(answer, now); return;
    default: return;
  }
}

void ProxySync::on_begin(std::span<const std::uint8_t> answer, dp::TimePoint now) {
  const auto a = protocol::decode_proxy_begin_answer(answer);
  if (!a || (a.value().reason != protocol::SyncReason::kNone &&
             a.value().direction == protocol::SyncDirection::kNone)) {
    fail(FailureKind::kBadRecord, now);
    return;
  }
  // [RS4 manual §6.4] CONFIG_SET_TO_DEFAULT "kommt direkt vom Scanner": the flag of every 98
  // answer (during the retry download of a device that rolled back it reads 1).
  out_.config_set_to_default = a.value().factory_default;
  if (a.value().reason == protocol::SyncReason::kNone) {
    // Nothing started (a stale Proxy-Request bit): no error, but wait the retry delay.
    sync_open_ = false;
    out_.fb_busy = false;
    step_ = Step::kRetryWait;
    retry_until_ = now + config_.retry_delay;
    return;
  }
  begin_ = a.value();
  begin_exchange(Step::kIdentify1, identify_command(), now);
}

// An answer of `code` with status kOk and its body, else the failure (an RS4 error telegram
// 0x53 or a refusing status give ERROR_NUMBER_RS4).
std::optional<protocol::TransferAnswer> ProxySync::transfer_answer(
    std::span<const std::uint8_t> answer, protocol::TransferCode code, dp::TimePoint now) {
  if (!answer.empty() && answer[0] == 0x53) {
    const auto t = protocol::decode_telegram(answer);
    const auto* e = t ? std::get_if<protocol::ErrorTelegram>(&t.value()) : nullptr;
    fail(FailureKind::kBadRecord, now, 0, e != nullptr ? e->report.number : 0);
    return std::nullopt;
  }
  auto a = protocol::decode_answer(answer);
  if (!a || a.value().code != code) {
    fail(FailureKind::kBadRecord, now);
    return std::nullopt;
  }
  if (a.value().status != protocol::TransferStatus::kOk || !a.value().body) {
    fail(FailureKind::kBadRecord, now, 0, static_cast<std::uint16_t>(a.value().status));
    return std::nullopt;
  }
  return std::move(a).value();
}

void ProxySync::on_identify(std::span<const std::uint8_t> answer, dp::TimePoint now) {
  const auto a = transfer_answer(answer, protocol::TransferCode::kIdentify, now);
  if (!a) return;
  const auto* body = std::get_if<protocol::IdentifyAnswer>(&*a->body);
  const auto count = body != nullptr ? body->identification.chunk_count() : 0;
  if (body == nullptr || count == 0 || count > protocol::kMaxChunkCount) {
    fail(FailureKind::kBadRecord, now);
    return;
  }
  const auto& id = body->identification;
  if (is_first_read(step_)) {
    first_ = id;
    begin_exchange(repeat_of(step_), identify_command(), now);
    return;
  }
  if (!first_ || !(*first_ == id)) {
    fail(FailureKind::kBadRecord, now, kAdapterCrcCompare);
    return;
  }
  ident_ = id;
  if (step_ == Step::kIdentify2) {
    decide(now);
  } else if (id.set_crc32 != set_crc_) {  // checksum re-read / background verify
    fail(FailureKind::kBadRecord, now, kAdapterCrcCompare);
  } else if (step_ == Step::kReidentify2) {
    store_serial(now);
  } else {
    start_upload(true, now);
  }
}

// The four scenarios of [RS4 manual §7.1, §7.2] (docs/proxy.md "Decisions").
void ProxySync::decide(dp::TimePoint now) {
  const bool has_set = current_.has_value();
  const auto dir = begin_.direction;
  if (dir == protocol::SyncDirection::kUpload) {
    start_upload(false, now);  // parameter change: the device's set replaces the stored one
    return;
  }
  if (has_set && current_->version.pending_download) {
    restore_version_ = current_->version.id;  // a restore waits for this sync
    start_download(now);
    return;
  }
  if (dir == protocol::SyncDirection::kVerify) {
    if (!has_set) {
      start_upload(false, now);  // the proxy learns the set
    } else if (known_serial_ != std::to_string(ident_->serial_number) ||
               current_->set.crc32 != ident_->set_crc32) {
      start_download(now);  // device exchange (or a set that is not the stored one)
    } else {
      transfer_ = storage::SyncDirection::kVerify;
      set_crc_ = current_->set.crc32;  // consistent: release at once, verify afterwards
      verify_after_end_ = config_.background_verify;
      send_end(now);
    }
    return;
  }
  if (has_set) {
    start_download(now);  // factory settings: the stored set goes back
  } else {
    transfer_ = storage::SyncDirection::kNone;  // nothing stored: nothing to download
    send_end(now);  // first commissioning: CONFIG_SET_TO_DEFAULT from the 99 answer
  }
}

void ProxySync::start_upload(bool background, dp::TimePoint now) {
  background_ = background;
  transfer_ = background ? storage::SyncDirection::kVerify : storage::SyncDirection::kUpload;
  set_.clear();
  chunk_ = 0;
  chunk_count_ = ident_->chunk_count();
  chunk_size_ = ident_->chunk_size;
  request_chunk(now);
}

void ProxySync::request_chunk(dp::TimePoint now) {
  const auto chunk = static_cast<std::uint8_t>(chunk_);
  begin_exchange(background_ ? Step::kVerifyUpload1 : Step::kUpload1,
                 protocol::encode_request(protocol::UploadChunkRequest{chunk}).value(), now);
}

void ProxySync::on_upload(std::span<const std::uint8_t> answer, dp::TimePoint now) {
  const auto a = transfer_answer(answer, protocol::TransferCode::kUploadChunk, now);
  if (!a) return;
  const auto* u = std::get_if<protocol::UploadChunkAnswer>(&*a->body);
  const std::size_t expected = std::min(chunk_size_, ident_->set_size - chunk_ * chunk_size_);
  if (u == nullptr || u->chunk != chunk_ || u->chunk_count != chunk_count_ ||
      u->data.size() != expected) {
    fail(FailureKind::kBadRecord, now);
    return;
  }
  if (storage::crc32(u->data) != u->crc32) {
    fail(FailureKind::kBadRecord, now, with_chunk(kAdapterReadRepeat, chunk_));
    return;
  }
  if (is_first_read(step_)) {
    first_chunk_ = u->data;
    begin_exchange(repeat_of(step_),
                   protocol::encode_request(protocol::UploadChunkRequest{u->chunk}).value(), now);
    return;
  }
  if (first_chunk_ != u->data) {
    fail(FailureKind::kBadRecord, now, with_chunk(kAdapterReadRepeat, chunk_));
    return;
  }
  set_.insert(set_.end(), u->data.begin(), u->data.end());
  if (++chunk_ < chunk_count_) {
    request_chunk(now);
  } else {
    upload_complete(now);
  }
}

void ProxySync::upload_complete(dp::TimePoint now) {
  if (storage::crc32(set_) != ident_->set_crc32) {
    fail(FailureKind::kBadRecord, now, kAdapterCrcCompare);
    return;
  }
  set_crc_ = ident_->set_crc32;
  if (background_) {
    if (!current_ || current_->set.blob != set_) {
      fail(FailureKind::kBadRecord, now);
      return;
    }
    finish(storage::SyncOutcome::kSucceeded, now);
    return;
  }
  step_ = Step::kStoreUpload;
  if (!store_set(storage::VersionSource::kUpload, set_summary(set_), upload_note(), now)) {
    fail(FailureKind::kCopy, now);
    return;
  }
  send_end(now);
}

std::string ProxySync::upload_note() const {
  if (begin_.direction == protocol::SyncDirection::kUpload) {
    return "scenario 2, parameter change: the device's set uploaded by the proxy";
  }
  return "the proxy learnt the device's set (no set stored for the station)";
}

// The synchronised set as a new current version of the station, with the device's serial.
bool ProxySync::store_set(storage::VersionSource source, std::string summary, std::string note,
                          dp::TimePoint now) {
  storage::StoreRequest req;
  req.station = config_.station;
  req.device_type = rs4::scanner::device_type_text(ident_->device_type);
  req.serial_number = rs4::scanner::serial_number_text(ident_->serial_number);
  req.blob = set_;
  req.crc32 = set_crc_;
  req.summary = std::move(summary);
  req.source = source;
  req.at = wall_time(config_, now);
  if (config_.simulated) {
    req.simulated = std::chrono::duration_cast<std::chrono::milliseconds>(now.time_since_epoch());
  }
  req.note = std::move(note);
  req.user = config_.recording.author.user;
  req.host = config_.recording.author.host;
  req.site = config_.recording.site;
  req.line = config_.recording.line;
  req.skip_identical = config_.recording.skip_identical;
  return archive_.store(req).has_value();
}

void ProxySync::start_download(dp::TimePoint now) {
  step_ = Step::kLoadDownload;
  transfer_ = storage::SyncDirection::kDownload;
  const auto got = archive_.get(restore_version_ ? *restore_version_ : current_->version.id);
  if (!got || got.value().set.blob.empty() ||
      got.value().set.blob.size() > protocol::kMaxChunkCount * protocol::kMaxChunkSize ||
      storage::crc32(got.value().set.blob) != got.value().set.crc32) {
    fail(FailureKind::kCopy, now);
    return;
  }
  set_ = got.value().set.blob;
  set_crc_ = got.value().set.crc32;
  download_open_ = true;
  const protocol::DownloadBeginRequest begin{static_cast<std::uint16_t>(set_.size()), set_crc_};
  begin_exchange(Step::kDownloadBegin, protocol::encode_request(begin).value(), now);
}

void ProxySync::send_download_chunk(dp::TimePoint now) {
  const std::size_t offset = chunk_ * chunk_size_;
  const std::size_t n = std::min(chunk_size_, set_.size() - offset);
  const protocol::DownloadChunkRequest req{static_cast<std::uint8_t>(chunk_),
                                           std::span(set_).subspan(offset, n)};
  begin_exchange(Step::kDownloadChunk, protocol::encode_request(req).value(), now);
}

void ProxySync::on_download(std::span<const std::uint8_t> answer, dp::TimePoint now) {
  const auto code = step_ == Step::kDownloadBegin   ? protocol::TransferCode::kDownloadBegin
                    : step_ == Step::kDownloadChunk ? protocol::TransferCode::kDownloadChunk
                                                    : protocol::TransferCode::kDownloadCommit;
  const auto a = transfer_answer(answer, code, now);
  if (!a) return;
  if (const auto* b = std::get_if<protocol::DownloadBeginAnswer>(&*a->body)) {
    chunk_size_ = b->chunk_size;
    chunk_count_ = (set_.size() + chunk_size_ - 1) / chunk_size_;
    chunk_ = 0;
    if (b->chunk_count != chunk_count_ || chunk_count_ > protocol::kMaxChunkCount) {
      fail(FailureKind::kBadRecord, now);
      return;
    }
    send_download_chunk(now);
  } else if (const auto* c = std::get_if<protocol::DownloadChunkAnswer>(&*a->body)) {
    const std::size_t offset = chunk_ * chunk_size_;
    const auto sent = std::span(set_).subspan(offset, std::min(chunk_size_, set_.size() - offset));
    if (c->chunk != chunk_ || c->echo_crc32 != storage::crc32(sent)) {
      fail(FailureKind::kBadRecord, now, with_chunk(kAdapterEchoCrc, chunk_));
      return;
    }
    if (++chunk_ < chunk_count_) {
      send_download_chunk(now);
    } else {
      begin_exchange(Step::kDownloadCommit,
                     protocol::encode_request(protocol::DownloadCommitRequest{}).value(), now);
    }
  } else if (const auto* m = std::get_if<protocol::DownloadCommitAnswer>(&*a->body)) {
    if (m->active_crc32 != set_crc_) {
      fail(FailureKind::kBadRecord, now, kAdapterCrcCompare);
      return;
    }
    download_open_ = false;
    downloaded_ = true;
    begin_exchange(Step::kReidentify1, identify_command(), now);
  } else {
    fail(FailureKind::kBadRecord, now);
  }
}

// After a download: the restore is done, a new device's serial number is stored.
void ProxySync::store_serial(dp::TimePoint now) {
  step_ = Step::kStoreSerial;
  if (restore_version_ && !archive_.mark_downloaded(*restore_version_)) {
    fail(FailureKind::kCopy, now);
    return;
  }
  const auto serial = std::to_string(ident_->serial_number);
  if (current_ && known_serial_ != serial &&
      !store_set(storage::VersionSource::kDownload, current_->set.summary,
                 "scenario 4, device exchange: the stored set downloaded to serial " + serial,
                 now)) {
    fail(FailureKind::kCopy, now);
    return;
  }
  send_end(now);
}

void ProxySync::send_end(dp::TimePoint now) {
  const protocol::ProxyEndCommand end{protocol::ProxyOutcome::kSucceeded, 0};
  begin_exchange(Step::kEnd, protocol::encode_command(end), now);
}

void ProxySync::on_end(std::span<const std::uint8_t> answer, dp::TimePoint now) {
  const auto a = protocol::decode_proxy_end_answer(answer);
  if (!a || !a.value().accepted) {
    fail(FailureKind::kBadRecord, now);
    return;
  }
  sync_open_ = false;  // the adapter released the OSSD bit
  out_.config_set_to_default = a.value().factory_default;
  log_sync(storage::SyncOutcome::kSucceeded, now);
  if (verify_after_end_) {
    background_ = true;
    begin_exchange(Step::kVerifyIdentify1, identify_command(), now);
    return;
  }
  finish(storage::SyncOutcome::kSucceeded, now);
}

}  // namespace rs4sim::proxy
