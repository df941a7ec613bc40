// Adapter: power, start-up, Set_Prm/Chk_Cfg, DP state, LED, observation.
// [RS4 manual §2.3, §2.4, §4.5, §7.1, §7.2, §6.2, §6.3, §4.4].
#include "rs4/adapter/adapter.h"

#include "rs4/adapter/rs4_gsd.h"
#include "rs4/safety/diagnosis.h"
#include "rs4/safety/profile.h"

#include <algorithm>
#include <string>

namespace rs4sim::rs4::adapter {

namespace {

profisafe::FDeviceConfig fdevice_config(std::optional<std::uint8_t> address) {
  profisafe::FDeviceConfig c;
  // [RS4 manual §4.5]: F_Dest_Add = 500 + address. Without a valid address the profile has no
  // F_Dest_Add and every block is refused with 65 (internal F_Dest_Add error).
  c.profile = safety::device_profile(address ? *address : 127U);
  c.data_size = 1;
  return c;
}

}  // namespace

std::string_view to_string(AdapterApiError e) noexcept {
  switch (e) {
    case AdapterApiError::kPoweredOff: return "the RS4/PROFIsafe has no power";
    case AdapterApiError::kNoSyncRequested:
      return "proxy sync started although the device does not request one (Proxy-Request 0)";
    case AdapterApiError::kNoSyncRunning: return "no proxy sync is running";
  }
  return "unknown adapter API error";
}

const char* to_string(LedState s) noexcept {
  switch (s) {
    case LedState::kDark: return "dark";
    case LedState::kSteadyInit: return "steady (init)";
    case LedState::kFastBlink: return "fast blink (ready for PROFIBUS)";
    case LedState::kOffConnected: return "off (connected)";
    case LedState::kSteadyFault: return "steady (fault)";
    case LedState::kSlowBlink: return "slow blink (fault)";
  }
  return "unknown";
}

std::string_view to_token(LedState s) noexcept {
  switch (s) {
    case LedState::kDark: return "dark";
    case LedState::kSteadyInit: return "steady-init";
    case LedState::kFastBlink: return "fast-blink";
    case LedState::kOffConnected: return "off-connected";
    case LedState::kSteadyFault: return "steady-fault";
    case LedState::kSlowBlink: return "slow-blink";
  }
  return "?";
}

LedPattern led_pattern(LedState s) noexcept {
  using std::chrono::milliseconds;
  switch (s) {
    case LedState::kSteadyInit:
    case LedState::kSteadyFault: return {milliseconds(1), milliseconds(0)};
    case LedState::kFastBlink: return {milliseconds(100), milliseconds(200)};
    case LedState::kSlowBlink: return {milliseconds(500), milliseconds(1000)};
    case LedState::kDark:
    case LedState::kOffConnected: break;
  }
  return {};
}

bool led_lit(LedState s, Duration in_state) noexcept {
  const auto p = led_pattern(s);
  if (p.period.count() == 0) return p.on.count() != 0;
  if (in_state < Duration::zero()) return false;
  return in_state % p.period < p.on;
}

const char* to_string(ProxyPhase p) noexcept {
  switch (p) {
    case ProxyPhase::kWaitRs4: return "wait for RS4";
    case ProxyPhase::kRequested: return "Proxy-Request";
    case ProxyPhase::kSyncRunning: return "sync running";
    case ProxyPhase::kDone: return "done";
  }
  return "unknown";
}

std::string_view to_token(ProxyPhase p) noexcept {
  switch (p) {
    case ProxyPhase::kWaitRs4: return "wait-rs4";
    case ProxyPhase::kRequested: return "requested";
    case ProxyPhase::kSyncRunning: return "sync-running";
    case ProxyPhase::kDone: return "done";
  }
  return "?";
}

void Adapter::Channel::clear() {
  assembler.reset();
  processing.clear();
  answers.clear();
  reading = protocol::BlockSplitter{};
}

Adapter::Adapter(AdapterConfig config)
    : config_(config), scanner_(config.scanner), fdevice_(fdevice_config(std::nullopt)) {}

void Adapter::power_on(TimePoint now) {
  if (powered_) return;
  powered_ = true;
  gate_.power_change();
  proxy_.reset();
  scanner_.power_on(now);
  signal_line_.clear();
  seen_ = sample_rs4();
  start_adapter(now, /*keep_errors=*/false);
}

bool Adapter::exchange_scanner(const scanner::ScannerConfig& unit) {
  if (powered_) return false;
  scanner::ScannerConfig c = unit;
  c.boot_duration = config_.scanner.boot_duration;  // the simulation's setting, not the unit's
  scanner_ = scanner::Scanner(c);
  restart_driven_ = false;  // the new unit's restart input is low until the power-on drives it
  return true;
}

void Adapter::power_off(TimePoint now) {
  powered_ = false;
  scanner_.power_off(now);
  signal_line_.clear();
  seen_ = {};
  errors_.clear();  // [RS4 manual §5.2.2]: the error memory does not survive power-off
  address_.reset();
  fdevice_ = profisafe::FDevice(fdevice_config(std::nullopt));
  link_down_until_.reset();
  connected_ = false;
  proxy_.reset();
  gate_.power_change();
  error_active_ = false;
  adapter_error_active_ = false;
  inconsistent_output_.reset();
  input_byte_ = output_byte_ = 0;
  c1_.clear();
  c2_.clear();
  event_buffer_.clear();
  track_led(now);
}

void Adapter::power_cycle(TimePoint now) {
  power_off(now);
  power_on(now);
}

// The adapter part of power-on, also run by PROFI_CMD_RESET (RS4 not affected, error
// memory kept). [RS4 manual §4.4]: the adapter initialises for a few seconds (LED steady 2–3 s).
void Adapter::start_adapter(TimePoint now, bool keep_errors) {
  const auto addr = adapter::station_address(config_.switches);
  address_ = addr ? std::optional<std::uint8_t>(addr.value()) : std::nullopt;
  fdevice_ = profisafe::FDevice(fdevice_config(address_));
  if (!keep_errors) errors_.clear();
  init_end_.reset();
  if (config_.init_duration > decltype(config_.init_duration)::zero()) {
    init_end_ = now + config_.init_duration;
  }
  connected_ = false;
  prm_refused_ = false;
  proxy_.stop(scanner_, now);
  pc_.adapter_start();
  if (gate_.rs4_up() && !pc_.attached()) {  // a restarted adapter checks again
    request_sync(gate_.proxy_request() ? proxy_.reason() : protocol::SyncReason::kPowerUp);
  }
  gate_.adapter_start(pc_.attached());
  field_pair_error_ = false;
  field_pair_release_at_.reset();
  if (!keep_errors) {
    // Power-on: restart input low, field pair 1 ([RS4 manual §5.1.2]). PROFI_CMD_RESET leaves the
    // RS4 untouched ([RS4 manual §5.2.2]): its inputs change only when the link goes down (the
    // restart input drops with the connection) and at the next PROFIBUS start-up (pair 1).
    restart_bus_ = false;
    drive_restart_input(now);
    field_pair_ = 1;
    scanner_.select_field_pair(1, now);
  }
  output_byte_ = 0;
  output_pdu_.fill(0);
  input_pdu_.fill(0);
  c1_.clear();
  c2_.clear();
  forwarding_ = Forwarding{};
  event_buffer_.clear();
  reported_.clear();
  update_rs4_phase(now);
  refresh_input(now);
}

std::optional<TimePoint> Adapter::wants_link_down_until() const noexcept {
  return link_down_until_;
}

// ---- Set_Prm / Chk_Cfg ([RS4 manual §6.2, §6.3], docs/gsd.md) -----------------------------------
dp::slave::PrmVerdict Adapter::check_parameters(const dp::pdu::SetPrm& prm, TimePoint now) {
  // Not ready (no power, invalid address switches, adapter still initialising): refused
  // without a PROFIsafe diagnosis; the master repeats the start-up.
  if (!powered_ || !address_ || (init_end_ && now < *init_end_) || link_down_until_) {
    ++counters_.prm_refused;
    return dp::slave::PrmVerdict::kPrmFault;
  }
  const std::span<const std::uint8_t> user(prm.user_data.data(), prm.user_data.size());
  const GsdProfile& g = gsd();
  const auto header = user.subspan(std::min(g.f_block_offset, user.size()));
  const bool shaped = user.size() == g.user_prm_len &&
                      g.f_block_offset + g.f_block_header.size() + profisafe::kFParametersSize <=
                          user.size() &&
                      std::equal(g.f_block_header.begin(), g.f_block_header.end(), header.begin());
  if (!shaped) {  // not the GSD's layout (docs/gsd.md): Prm_Fault, no status PDU
    ++counters_.prm_refused;
    if (control_) control_->set_device_diagnosis({}, false, false);
    return dp::slave::PrmVerdict::kPrmFault;
  }
  const auto v = fdevice_.set_parameters(
      user.subspan(g.f_block_offset + g.f_block_header.size(), profisafe::kFParametersSize));
  // [RS4 manual §6.2, §6.3]: the status PDU 05 81 00 00 nn follows the 6 standard diagnosis bytes;
  // a refused block sets Ext_Diag, the slave reports Prm_Fault and stays out of data exchange.
  const auto pdu = safety::status_pdu(safety::diagnosis(v.fault));
  if (control_) control_->set_device_diagnosis(pdu, !v.ok(), false);
  prm_refused_ = !v.ok();
  track_led(now);  // a refused block: slow blink from now
  if (!v.ok()) {
    ++counters_.prm_refused;
    return dp::slave::PrmVerdict::kPrmFault;
  }
  ++counters_.prm_accepted;
  return dp::slave::PrmVerdict::kAccept;
}

dp::slave::CfgVerdict Adapter::check_config(std::span<const std::uint8_t> cfg, bool user_check,
                                            TimePoint now) {
  // The RS4 has one module: the Cfg must be exactly its GSD's (built in: C0 84 84).
  (void)user_check, (void)now;
  const auto& expected = gsd().cfg;
  if (std::equal(cfg.begin(), cfg.end(), expected.begin(), expected.end())) {
    return dp::slave::CfgVerdict::kAccept;
  }
  ++counters_.cfg_refused;
  return dp::slave::CfgVerdict::kCfgFault;
}

void Adapter::on_state_change(dp::slave::State from, dp::slave::State to,
                              dp::slave::TransitionReason why, TimePoint now) {
  (void)why;
  if (!powered_) return;
  if (to == dp::slave::State::kDataExch && from != dp::slave::State::kDataExch) {
    enter_data_exchange(now);
  } else if (from == dp::slave::State::kDataExch && to != dp::slave::State::kDataExch) {
    connected_ = false;
    restart_bus_ = false;
    drive_restart_input(now);
    c1_.clear();
    // [docs/proxy-protocol.md] step 6: the class 1 connection lost during a sync ends it.
    if (proxy_.running()) fail_sync(0, now);
    refresh_input(now);
  }
}

// PROFIBUS start-up ([RS4 manual §5.1.2, §7.1, §7.2, §5.3.2]): field pair 1, Proxy-Enable evaluated
// from the first process output, the last error re-reported when still present.
void Adapter::enter_data_exchange(TimePoint now) {
  connected_ = true;
  gate_.forget_proxy_enable();
  field_pair_ = 1;
  field_pair_error_ = false;
  field_pair_release_at_.reset();
  scanner_.select_field_pair(1, now);
  reported_.clear();
  if (error_active_) {
    reported_.push_back(last_uc2_error_ != 0 ? last_uc2_error_ : last_uc1_error_);
    submit_diagnosis_alarm(protocol::AlarmDifferentiation::kAppears);
  }
  refresh_input(now);
}

void Adapter::on_c2_event(dp::slave::C2Event ev, std::uint8_t master, TimePoint now) {
  (void)ev, (void)master, (void)now;
  // A new or ended class 2 connection starts without leftover blocks or answers.
  c2_.clear();
}

// ---- time ----------------------------------------------------------------------------------
std::optional<TimePoint> Adapter::next_deadline() const {
  if (!powered_) return std::nullopt;
  std::optional<TimePoint> next = scanner_.next_deadline();
  const auto fold = [&next](std::optional<TimePoint> t) {
    if (t && (!next || *t < *next)) next = t;
  };
  fold(fdevice_.next_deadline());
  fold(init_end_);
  fold(link_down_until_);
  fold(field_pair_release_at_);
  if (!signal_line_.empty()) fold(signal_line_.front().first);
  for (const auto* ch : {&c1_, &c2_}) {
    if (!ch->processing.empty()) fold(ch->processing.front().due);
  }
  if (error_active_) fold(last_error_at_ + config_.going_alarm_delay);
  return next;
}

void Adapter::on_time(TimePoint now) {
  if (!powered_) return;
  if (init_end_ && now >= *init_end_) init_end_.reset();
  if (link_down_until_ && now >= *link_down_until_) link_down_until_.reset();
  fdevice_.on_time(now);
  collect_rs4(now);
  finish_processing(now);
  if (field_pair_release_at_ && now >= *field_pair_release_at_) field_pair_release_at_.reset();
  check_going_alarm(now);
  switch_through_after_sync(now);  // refreshes the input byte
}

// ---- observation ---------------------------------------------------------------------------
LedState Adapter::led() const noexcept {
  if (!powered_) return LedState::kDark;
  if (!address_) return LedState::kSteadyFault;  // steady > 3 s: not addressable
  if (init_end_ || link_down_until_) return LedState::kSteadyInit;
  if (prm_refused_) return LedState::kSlowBlink;
  return connected_ ? LedState::kOffConnected : LedState::kFastBlink;
}

// Called wherever a cause of led() changes (refresh_input follows every such path, Set_Prm and
// power-off call it themselves).
void Adapter::track_led(TimePoint now) noexcept {
  const auto s = led();
  if (s == led_state_) return;
  led_state_ = s;
  led_since_ = now;
}

bool Adapter::led_lit(TimePoint now) const noexcept {
  const auto s = led();
  // A state not yet tracked began now (cannot happen through the public calls; safe anyway).
  return adapter::led_lit(s, s == led_state_ ? now - led_since_ : Duration::zero());
}

ProxyPhase Adapter::proxy_phase() const noexcept {
  if (!gate_.rs4_up()) return ProxyPhase::kWaitRs4;
  if (proxy_.running()) return ProxyPhase::kSyncRunning;
  if (gate_.proxy_request()) return ProxyPhase::kRequested;
  return ProxyPhase::kDone;
}

AdapterView Adapter::view() const {
  AdapterView v;
  v.powered = powered_;
  v.station_address = address_;
  v.f_dest_add = address_ ? f_dest_add(*address_) : 0;
  v.led = led();
  v.proxy = proxy_phase();
  v.proxy_enable = gate_.proxy_enable();
  v.pc_adapter_attached = pc_.attached();
  v.connected = connected_;
  v.input_byte = input_byte_;
  v.input = decode_input_byte(input_byte_);
  v.output_byte = output_byte_;
  v.output = decode_output_byte(output_byte_);
  v.input_pdu = input_pdu_;
  v.output_pdu = output_pdu_;
  v.fdevice = fdevice_.state();
  v.rs4 = scanner_.status().state;
  v.field_pair_error = field_pair_error_;
  v.error_active = error_active_;
  return v;
}

}  // namespace rs4sim::rs4::adapter
