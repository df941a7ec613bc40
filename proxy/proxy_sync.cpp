// ProxySync: inputs, exchanges, failures, the retentive record (docs/proxy.md).
#include "proxy/proxy_sync.h"

#include "rs4/protocol/adapter_command.h"

#include <utility>

namespace rs4sim::proxy {

namespace protocol = rs4::protocol;

namespace {
storage::SyncDirection archive_direction(protocol::SyncDirection d) noexcept {
  switch (d) {
    case protocol::SyncDirection::kUpload: return storage::SyncDirection::kUpload;
    case protocol::SyncDirection::kDownload: return storage::SyncDirection::kDownload;
    case protocol::SyncDirection::kVerify: return storage::SyncDirection::kVerify;
    case protocol::SyncDirection::kNone: break;
  }
  return storage::SyncDirection::kNone;
}
std::string reason_text(protocol::SyncReason r) {
  switch (r) {
    case protocol::SyncReason::kPowerUp: return "power-up";
    case protocol::SyncReason::kPcAdapterRemoved: return "pc-adapter-removed";
    case protocol::SyncReason::kRetry: return "retry";
    case protocol::SyncReason::kUserParametrisation: return "user-parametrisation";
    case protocol::SyncReason::kNone: break;
  }
  return "none";
}
}  // namespace

storage::Timestamp wall_time(const ProxySyncConfig& config, dp::TimePoint now) {
  if (config.wall_clock) return config.wall_clock();
  return storage::Timestamp{
      std::chrono::duration_cast<std::chrono::milliseconds>(now.time_since_epoch())};
}

ProxySync::ProxySync(ProxySyncConfig config, storage::ParameterArchive& archive)
    : config_(std::move(config)), archive_(archive) {}

bool ProxySync::ready(dp::TimePoint now) const noexcept {
  if (pc_adapter_) return false;  // nothing reaches the device while bit 3 is 1
  if (abort_pending_) return true;
  if (!enabled_ || !request_) return false;
  if (step_ == Step::kRetryWait) return now >= retry_until_;
  return step_ == Step::kIdle;
}

bool ProxySync::active() const noexcept {
  return step_ != Step::kIdle && step_ != Step::kRetryWait;
}

void ProxySync::start(dp::TimePoint now) {
  if (!ready(now)) return;
  started_at_ = now;
  if (abort_pending_) {  // restart mid-sync: fail it safely (docs/proxy.md)
    abort_pending_ = false;
    out_.fb_busy = true;
    sync_open_ = true;
    adapter_error_ = 0;
    report_failure(now);
    return;
  }
  // [RS4 manual §6.4] "Bei erneutem Bearbeiten des Proxy-FB werden ERROR_NUMBER_FB,
  // ERROR_CODE_SFC und ERROR_NUMBER_RS4 auf den Wert Null zurückgesetzt": those three only.
  // CONFIG_SET_TO_DEFAULT "kommt direkt vom Scanner": it keeps the device's last word until
  // the next answer to 98 or 99 brings a new one.
  out_.error_number_fb = out_.error_code_sfc = out_.error_number_rs4 = 0;
  out_.fb_busy = true;
  begin_ = {};
  transfer_.reset();
  ident_.reset();
  first_.reset();
  current_.reset();
  known_serial_.clear();
  set_.clear();
  restore_version_.reset();
  sync_open_ = download_open_ = downloaded_ = verify_after_end_ = background_ = false;
  adapter_error_ = 0;
  chunk_ = chunk_count_ = chunk_size_ = 0;
  load_current(now);
}

void ProxySync::begin_exchange(Step step, std::vector<std::uint8_t> command, dp::TimePoint now) {
  step_ = step;
  exchange_.start(command, now, config_.timing);
  exchange_finished(now);  // a command the codecs could not produce
}

std::optional<RecordRequest> ProxySync::take_request(dp::TimePoint now) {
  exchange_.tick(now);
  exchange_finished(now);
  return exchange_.take_request(now);
}

void ProxySync::on_record_result(const RecordResult& result, dp::TimePoint now) {
  exchange_.on_result(result, now);
  exchange_finished(now);
}

void ProxySync::tick(dp::TimePoint now) {
  exchange_.tick(now);
  exchange_finished(now);
}

std::optional<dp::TimePoint> ProxySync::next_wakeup() const noexcept {
  if (step_ == Step::kRetryWait && request_ && enabled_) return retry_until_;
  return exchange_.next_wakeup();
}

// Dispatches a finished exchange; the failure report's own failures are ignored (the first
// error stays on the outputs).
void ProxySync::exchange_finished(dp::TimePoint now) {
  using S = Exchange::Status;
  const auto status = exchange_.status();
  if (status == S::kIdle || status == S::kBusy) return;
  const std::vector<std::uint8_t> answer(exchange_.answer().begin(), exchange_.answer().end());
  const auto sfc = exchange_.sfc();
  const bool pc_adapter = exchange_.pc_adapter_attached();
  exchange_.reset();
  if (pc_adapter) {
    // Flow state 010: the adapter ignored the WRITEs, so no sync is open on the device (one
    // that runs defers the switch-through, [RS4 manual §5.1.1] bit 3) and nothing is reported
    // to it; a failure report in progress ends here. The machine stops with the step's READ
    // position (KK 01, sfc 0) and waits for bit 3 to drop.
    if (step_ != Step::kBreak && step_ != Step::kEndFailed) {
      out_.error_number_fb = error_number_fb(step_, FailureKind::kRead);
      out_.error_code_sfc = 0;
    }
    sync_open_ = download_open_ = false;
    finish(storage::SyncOutcome::kFailed, now);
    return;
  }
  if (step_ == Step::kBreak) {
    download_open_ = false;
    report_failure(now);
    return;
  }
  if (step_ == Step::kEndFailed) {
    // DECISION (docs/proxy.md "Failures"): without a readable answer (the link is gone) the
    // device has rolled back by itself ([RS4 manual §7.1, §7.2]: a failed sync resets it to
    // factory settings; docs/proxy-protocol.md: so does a lost connection), so the FB reports
    // CONFIG_SET_TO_DEFAULT rather than leave the user believing the old set is active.
    // A failure report the device accepted rolled it back ([docs/proxy-protocol.md]): its flag is
    // 1 by contract, and a stale 99 answer left by an unreadable 99 success (position 41) must
    // not say otherwise. Only "not accepted" (no sync was open) leaves the device's own flag.
    out_.config_set_to_default = true;
    if (status == S::kDone) {
      if (auto a = protocol::decode_proxy_end_answer(answer))
        out_.config_set_to_default = a.value().accepted || a.value().factory_default;
    }
    sync_open_ = false;
    finish(storage::SyncOutcome::kFailed, now);
    return;
  }
  switch (status) {
    case S::kDone: on_answer(answer, now); return;
    case S::kWriteFailed:
      out_.error_code_sfc = sfc;
      fail(FailureKind::kWrite, now);
      return;
    case S::kReadFailed:
      out_.error_code_sfc = sfc;
      fail(FailureKind::kRead, now);
      return;
    default: fail(FailureKind::kBadRecord, now); return;
  }
}

// Stop on error ([RS4 manual §6.4]): the outputs show where, the device is told (DOWNLOAD_BREAK
// when a download is open, then 99 failed), then the machine waits for the next request.
void ProxySync::fail(FailureKind kind, dp::TimePoint now, std::uint16_t adapter_error,
                     std::uint16_t rs4) {
  out_.error_number_fb = error_number_fb(step_, kind);
  if (rs4 != 0) out_.error_number_rs4 = rs4;
  adapter_error_ = adapter_error;
  // After the release (background verify) the device is told too: [RS4 manual §5.1.1] bit 2 "Tritt
  // während der Parameterkontrolle ein Fehler auf, wird es wieder auf 1 gesetzt". Its `99 01`
  // rolls the device back like any failed sync (OSSD bit 0, Proxy-Request, reason retry), and the
  // retry downloads the stored set [docs/proxy-protocol.md].
  if (background_) sync_open_ = true;
  report_failure(now);
}

void ProxySync::report_failure(dp::TimePoint now) {
  if (download_open_) {
    begin_exchange(Step::kBreak, protocol::encode_request(protocol::DownloadBreakRequest{}).value(),
                   now);
    return;
  }
  if (sync_open_) {
    const protocol::ProxyEndCommand end{protocol::ProxyOutcome::kFailed, adapter_error_};
    begin_exchange(Step::kEndFailed, protocol::encode_command(end), now);
    return;
  }
  finish(storage::SyncOutcome::kFailed, now);
}

void ProxySync::finish(storage::SyncOutcome outcome, dp::TimePoint now) {
  if (outcome != storage::SyncOutcome::kSucceeded || background_) log_sync(outcome, now);
  out_.fb_busy = false;
  background_ = false;
  if (outcome == storage::SyncOutcome::kSucceeded) {
    step_ = Step::kIdle;
  } else {
    step_ = Step::kRetryWait;
    retry_until_ = now + config_.retry_delay;
  }
}

void ProxySync::log_sync(storage::SyncOutcome outcome, dp::TimePoint now) {
  storage::SyncLogEntry e;
  e.station = config_.station;
  e.at = wall_time(config_, now);
  e.reason = background_ ? "background-verify" : reason_text(begin_.reason);
  e.direction = transfer_ ? *transfer_ : archive_direction(begin_.direction);
  e.outcome = outcome;
  e.error_number_fb = out_.error_number_fb;
  e.error_code_sfc = out_.error_code_sfc;
  e.error_number_device = out_.error_number_rs4;
  e.duration = std::chrono::duration_cast<std::chrono::milliseconds>(now - started_at_);
  if (!archive_.log_sync(e) && out_.error_number_fb == 0)
    out_.error_number_fb = error_number_fb(Step::kStoreSerial, FailureKind::kCopy);
}

SyncProgress ProxySync::progress() const noexcept {
  SyncProgress p;
  p.step = step_;
  const auto at = positions(step_);
  p.position = at.write != 0 ? at.write : at.copy;
  p.direction = begin_.direction;
  if (ident_ && (step_ >= Step::kUpload1 && step_ <= Step::kStoreUpload)) {
    p.bytes_total = ident_->set_size;
    p.bytes_done = set_.size();
  } else if (step_ >= Step::kLoadDownload && step_ <= Step::kDownloadCommit) {
    p.bytes_total = set_.size();
    p.bytes_done = std::min(set_.size(), chunk_ * chunk_size_);
  } else if (step_ >= Step::kVerifyUpload1 && step_ <= Step::kVerifyUpload2 && ident_) {
    p.bytes_total = ident_->set_size;
    p.bytes_done = set_.size();
  }
  return p;
}

RetentiveRecord ProxySync::snapshot() const noexcept {
  RetentiveRecord r;
  if (sync_open_ || abort_pending_) {
    r.state = RetentiveState::kSyncOpen;
  } else if (background_) {
    r.state = RetentiveState::kBackgroundVerify;
  }
  r.step = static_cast<std::uint8_t>(abort_pending_ ? abort_step_ : step_);
  r.config_set_to_default = out_.config_set_to_default;
  r.fb_busy = out_.fb_busy;
  r.download_open = download_open_;
  r.error_number_fb = out_.error_number_fb;
  r.error_code_sfc = out_.error_code_sfc;
  r.error_number_rs4 = out_.error_number_rs4;
  r.direction = static_cast<std::uint8_t>(begin_.direction);
  r.reason = static_cast<std::uint8_t>(begin_.reason);
  r.serial_number = ident_ ? ident_->serial_number : 0;
  r.set_crc32 = set_crc_;
  return r;
}

void ProxySync::restore(const RetentiveRecord& record) noexcept {
  exchange_.reset();
  step_ = Step::kIdle;
  background_ = false;
  out_.config_set_to_default = record.config_set_to_default;
  out_.error_number_fb = record.error_number_fb;
  out_.error_code_sfc = record.error_code_sfc;
  out_.error_number_rs4 = record.error_number_rs4;
  out_.fb_busy = false;
  abort_pending_ = record.state == RetentiveState::kSyncOpen;
  download_open_ = abort_pending_ && record.download_open;
  sync_open_ = false;
  if (abort_pending_) {
    // The interrupted step is the failure's position; KK 01: its record exchange was cut.
    const auto step = record.step < kStepCount ? static_cast<Step>(record.step) : Step::kIdle;
    abort_step_ = step;
    const auto at = positions(step);
    const std::uint8_t pp = at.write != 0 ? at.write : (at.copy != 0 ? at.copy : at.read);
    out_.error_number_fb = pp != 0 ? static_cast<std::uint16_t>((pp << 8) | 0x01) : 0;
  }
}

}  // namespace rs4sim::proxy
