// Adapter: the device side of the proxy sync — EXTENSION ([docs/proxy-protocol.md],
// [RS4 manual §7.1, §7.2, §5.1.1] bit 2, [RS4 manual §5.2.1] flow state 011): Proxy-Request and
// its reason, PROFI_CMD_PROXY_BEGIN / _END, the transfer commands, and the failure path
// (factory settings, error memory, Proxy-Request again).
#include "rs4/adapter/adapter.h"
#include "rs4/protocol/parameter_transfer.h"

namespace rs4sim::rs4::adapter {

namespace {
// The proxy's own commands: they never abort a sync.
bool proxy_command(std::span<const std::uint8_t> command) noexcept {
  if (command.empty()) return true;  // not a command at all (kTelegramNotProcessed)
  const auto code = command[0];
  return protocol::is_transfer_code(code) ||
         code == static_cast<std::uint8_t>(protocol::AdapterCommandCode::kProxyBegin) ||
         code == static_cast<std::uint8_t>(protocol::AdapterCommandCode::kProxyEnd);
}
}  // namespace

// [RS4 manual §5.1.1] bit 2 = 1, remembering why for PROFI_CMD_PROXY_BEGIN; not while the PC
// adapter is attached ([RS4 manual §7.1.2] "Das Proxy-Request-Bit wird nicht gesetzt solange der
// PC-Adapter angeschlossen bleibt"): its removal requests the sync.
void Adapter::request_sync(protocol::SyncReason why) {
  if (pc_.attached()) return;
  gate_.request();
  proxy_.request(why);
}

std::error_code Adapter::proxy_sync_started(TimePoint now) {
  if (!powered_) return AdapterApiError::kPoweredOff;
  // [RS4 manual §5.1.1] bit 2: reset when the check begins
  if (!gate_.sync_start()) return AdapterApiError::kNoSyncRequested;
  proxy_.start(scanner_, now);  // flow state 011 on both channels from now on
  refresh_input(now);
  return {};
}

std::error_code Adapter::proxy_sync_succeeded(TimePoint now) {
  if (!powered_) return AdapterApiError::kPoweredOff;
  if (!proxy_.running()) return AdapterApiError::kNoSyncRunning;
  proxy_.stop(scanner_, now);
  // [RS4 manual §7.1, §7.2]: Proxy-Enable 1 → OSSD released after a successful sync. The only
  // place besides Proxy-Enable 0 that grants the release.
  gate_.sync_succeeded();  // "Die Parameter werden im Hintergrund verifiziert" [RS4 manual §7.1.1]
  pc_.sync_ended();        // switched through at the next on_time/READ
  refresh_input(now);
  return {};
}

// [RS4 manual §5.1.1] bit 3: a PC adapter attached during a sync is switched through once the
// sync has ended — DECISION: and the proxy has fetched the answer of its last command (99), which
// a switched-through adapter would no longer hand out (flow state 010).
void Adapter::switch_through_after_sync(TimePoint now) {
  if (pc_.pending() && c1_.answers.empty() && c1_.reading.done()) pc_.last_answer_read();
  refresh_input(now);
}

std::error_code Adapter::proxy_sync_failed(TimePoint now, std::uint16_t error) {
  if (!powered_) return AdapterApiError::kPoweredOff;
  if (!proxy_.running()) return AdapterApiError::kNoSyncRunning;
  fail_sync(error, now);
  return {};
}

// Every failure of a running sync ([RS4 manual §7.1, §7.2]: "if an upload or download fails, the
// device is reset to factory settings"): the error (if any) into the error memory with a
// diagnosis alarm ([RS4 manual §5.3.2]), the RS4 at factory settings, the sync over and
// Proxy-Request set again (reason retry; seen by the master in its next data exchange).
void Adapter::fail_sync(std::uint16_t error, TimePoint now) {
  proxy_.stop(scanner_, now);
  if (error != 0) {
    // A table 5.3-3 proxy error (0x2B0x) is an error of the adapter: input bit 5 until its going
    // alarm, as every one-shot adapter error [docs/decisions.md#rs4-error-bit].
    adapter_error_active_ = true;
    report_error(error, error, now);
  }
  scanner_.reset_to_factory_default(now);
  request_sync(protocol::SyncReason::kRetry);
  gate_.set_in_doubt();  // OSSD unaffected unless the sync fails (Proxy-Enable 1: withdrawn)
  pc_.sync_ended();      // switched through at the next on_time/READ
  refresh_input(now);
}

// PROFI_CMD_PROXY_BEGIN: `98 reason direction flags`; without a pending Proxy-Request
// `98 00 00 flags` and nothing starts.
void Adapter::proxy_begin(Channel& ch, TimePoint now) {
  protocol::ProxyBeginAnswer a;
  if (gate_.rs4_up() && !proxy_sync_started(now)) {
    a.reason = proxy_.reason();
    a.direction = proxy_.direction();
  }
  a.factory_default = scanner_.factory_settings();
  ch.answers.push_back(protocol::encode_proxy_begin_answer(a));
}

// PROFI_CMD_PROXY_END: `99 accepted flags`; accepted 0 when no sync was running. After a
// release `99 01` is still accepted until the next sync starts: the proxy's background verify
// failed, and [RS4 manual §5.1.1] bit 2 "Tritt während der Parameterkontrolle ein Fehler auf, wird
// es wieder auf 1 gesetzt" — the same failure path as a sync (factory settings, Proxy-Request,
// OSSD bit 0 with Proxy-Enable 1) [docs/proxy-protocol.md].
void Adapter::proxy_end(const protocol::ProxyEndCommand& end, Channel& ch, TimePoint now) {
  const bool running = proxy_.running();
  const bool failed = end.outcome != protocol::ProxyOutcome::kSucceeded;
  const bool verify_failed = !running && failed && gate_.check_open();
  if (running && !failed) {
    (void)proxy_sync_succeeded(now);
  } else if (running) {
    (void)proxy_sync_failed(now, end.error);
  } else if (verify_failed) {
    gate_.verify_failed();
    fail_sync(end.error, now);
  }
  ch.answers.push_back(
      protocol::encode_proxy_end_answer({running || verify_failed, scanner_.factory_settings()}));
}

// [RS4 manual §5.2] "a user command while the proxy is still syncing aborts the proxy with an
// error": any class 2 request, any class 1 command but the proxy's own → 0x2B01, failure path.
// The command itself is then served as usual.
void Adapter::abort_on_user_command(std::span<const std::uint8_t> command,
                                    dp::slave::AcyclicChannel which, TimePoint now) {
  if (!proxy_.running()) return;
  if (which == dp::slave::AcyclicChannel::kC1 && proxy_command(command)) return;
  fail_sync(protocol::to_wire(protocol::AdapterError::kProxyStateUnknown), now);
}

// A transfer command for the RS4. A set written during the sync (commit, break) is not yet
// confirmed by the proxy: with Proxy-Enable 1 the release waits for PROFI_CMD_PROXY_END ok.
// `authorised`: the command carried an accepted password (a user's download outside a sync).
std::vector<std::uint8_t> Adapter::transfer(std::span<const std::uint8_t> command, TimePoint now,
                                            bool authorised) {
  const auto before = scanner_.change_counter();
  auto answer = proxy_.answer(command, scanner_, now, authorised);
  if (scanner_.change_counter() != before) {
    if (!proxy_.running()) {
      // DECISION: a user's parametrisation over PROFIBUS asks the proxy to take the new set,
      // as the removal of the PC adapter does after one over RS232 ([RS4 manual §7.2.2]);
      // the OSSD bit is not withdrawn for it ([RS4 manual §7.1.2] "Das OSSD-Bit wird davon
      // nicht beeinflusst solange bei dem Parameterabgleich keine Fehler auftreten").
      // Its own reason 4 [docs/decisions.md#rs4-user-parametrisation-reason].
      if (gate_.rs4_up() && !pc_.attached()) {
        request_sync(protocol::SyncReason::kUserParametrisation);
      }
    } else {
      gate_.set_in_doubt();  // the set changed during the sync: with Proxy-Enable 1 not released
    }
    refresh_input(now);
  }
  return answer;
}

}  // namespace rs4sim::rs4::adapter
