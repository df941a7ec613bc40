#include "rs4/device/rs4_master_station.h"

#include "rs4/adapter/cyclic_bytes.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

namespace rs4sim::rs4::device {

namespace {

constexpr std::size_t kPduSize = 5;  // 1 F-data byte + status/control + 2 CRC2 + consecutive nr
constexpr std::uint8_t kRecordSlot = 0;
constexpr std::uint8_t kRecordIndex = 2;  // [RS4 manual §5.2]
constexpr std::size_t kStandardDiagBytes = 6;

Rs4MasterEntry make_entry(const Rs4MasterOptions& options) {
  auto e = rs4_master_entry(options);
  if (!e) {
    throw std::invalid_argument("RS4 " + std::to_string(options.address) +
                                ", configuration from the GSD: " + e.error().what());
  }
  return std::move(e).value();
}

}  // namespace

std::optional<std::uint8_t> f_diagnosis_number(std::span<const std::uint8_t> diag) {
  // [RS4 manual §6.3]: byte 7 = block length 5, byte 8 = 0x81 status message, byte 9 = slot 0,
  // byte 10 = no differentiation, byte 11 = the error number.
  if (diag.size() < kStandardDiagBytes + 5) return std::nullopt;
  const auto block = diag.subspan(kStandardDiagBytes, 5);
  if (block[0] != 0x05 || block[1] != 0x81) return std::nullopt;
  return block[4];
}

struct Rs4MasterStation::Slave {
  Rs4MasterEntry entry;
  profisafe::FHost fhost;
  std::uint8_t output = 0;
  Rs4SlaveView published;  // what the last events said
  std::error_code reason;  // the last fault reported by the master, cleared in data exchange
  std::error_code published_reason;
  std::uint8_t f_diagnosis = 0;
  std::size_t index = 0;  // in slaves_ (configuration order)
  bool changed = false;   // listed in changed_

  Slave(Rs4MasterEntry e, std::uint8_t out, std::size_t i)
      : entry(std::move(e)), fhost(rs4_fhost_config(entry)), output(out), index(i) {
    fhost.set_output(std::span<const std::uint8_t>(&output, 1));
    published.address = entry.slave.address;
    published.output_byte = out;
  }
  [[nodiscard]] std::uint8_t address() const { return entry.slave.address; }
};

namespace {

dp::master::MasterConfig master_config(const Rs4MasterStationConfig& c,
                                       const std::vector<dp::master::SlaveEntry>& slaves) {
  dp::master::MasterConfig m;
  m.address = c.master_address;
  m.bus = c.bus;
  m.cycle_target = c.cycle_target;
  m.claim_token = c.claim_token;
  m.slaves = slaves;
  return m;
}

}  // namespace

Rs4MasterStation::Rs4MasterStation(const Rs4MasterStationConfig& config)
    : auto_ack_rei_(config.auto_ack_rei), keep_master_events_(config.keep_master_events) {
  if (config.slaves.empty() && config.other_slaves.empty()) {
    throw std::invalid_argument("no RS4 or other slave configured");
  }
  std::vector<dp::master::SlaveEntry> entries;
  for (const auto& options : config.slaves) {
    slaves_.push_back(
        std::make_unique<Slave>(make_entry(options), config.output_byte, slaves_.size()));
    entries.push_back(slaves_.back()->entry.slave);
  }
  entries.insert(entries.end(), config.other_slaves.begin(), config.other_slaves.end());
  master_ = std::make_unique<dp::master::Master>(master_config(config, entries));
  // After the master: its configuration check names a duplicate or out-of-range address.
  index_.fill(-1);
  for (const auto& s : slaves_) index_[s->address()] = static_cast<std::int16_t>(s->index);
  master_->set_wake_handler([this] { wake(); });
}

Rs4MasterStation::~Rs4MasterStation() = default;

void Rs4MasterStation::on_telegram(const dp::fdl::Telegram& t, dp::TimePoint now) {
  master_->on_telegram(t, now);
  after_call(now);
}

void Rs4MasterStation::on_time(dp::TimePoint now) {
  master_->on_time(now);
  after_call(now);
}

std::optional<dp::TimePoint> Rs4MasterStation::next_deadline() const {
  return master_->next_deadline();
}

std::optional<dp::fdl::Telegram> Rs4MasterStation::take_transmit() {
  return master_->take_transmit();
}

void Rs4MasterStation::on_malformed_frame(std::error_code why) { master_->on_malformed_frame(why); }

std::vector<std::uint8_t> Rs4MasterStation::slave_addresses() const {
  std::vector<std::uint8_t> out;
  out.reserve(slaves_.size());
  for (const auto& s : slaves_) out.push_back(s->address());
  return out;
}

Rs4MasterStation::Slave* Rs4MasterStation::find(std::uint8_t address) {
  return const_cast<Slave*>(std::as_const(*this).find(address));
}

const Rs4MasterStation::Slave* Rs4MasterStation::find(std::uint8_t address) const {
  if (address >= index_.size() || index_[address] < 0) return nullptr;
  return slaves_[static_cast<std::size_t>(index_[address])].get();
}

Rs4SlaveView Rs4MasterStation::view_of(const Slave& s) const {
  Rs4SlaveView v;
  v.address = s.address();
  v.dp_state = master_->poll_state(v.address).value_or(dp::master::PollState::kStatusRequest);
  v.dp_error = s.reason;
  v.safety = s.fhost.state();
  v.f_diagnosis = s.f_diagnosis;
  const auto in = s.fhost.input();
  v.input_byte = in.empty() ? 0 : in[0];
  v.output_byte = s.output;
  return v;
}

std::optional<Rs4SlaveView> Rs4MasterStation::view(std::uint8_t address) const {
  const Slave* s = find(address);
  if (s == nullptr) return std::nullopt;
  return view_of(*s);
}

std::uint8_t Rs4MasterStation::input_byte(std::uint8_t address) const {
  const Slave* s = find(address);
  if (s == nullptr) return 0;
  const auto in = s->fhost.input();
  return in.empty() ? 0 : in[0];
}

bool Rs4MasterStation::in_data_exchange(std::uint8_t address) const {
  return master_->poll_state(address) == dp::master::PollState::kDataExchange;
}

bool Rs4MasterStation::set_output_byte(std::uint8_t address, std::uint8_t out) {
  Slave* s = find(address);
  if (s == nullptr) return false;
  s->output = out;
  s->fhost.set_output(std::span<const std::uint8_t>(&s->output, 1));
  mark_changed(s);
  return true;
}

bool Rs4MasterStation::set_proxy_enable(std::uint8_t address, bool on) {
  const Slave* s = find(address);
  if (s == nullptr) return false;
  const auto bit = adapter::kOutputProxyEnable;
  return set_output_byte(address,
                         static_cast<std::uint8_t>(on ? (s->output | bit) : (s->output & ~bit)));
}

bool Rs4MasterStation::ack_rei(std::uint8_t address) {
  Slave* s = find(address);
  if (s == nullptr) return false;
  s->fhost.ack_rei();
  mark_changed(s);  // published after the next link call, as before
  return true;
}

boost::outcome_v2::std_result<dp::master::Dpv1RequestId> Rs4MasterStation::write_record(
    std::uint8_t address, std::span<const std::uint8_t> record) {
  return master_->write(address, kRecordSlot, kRecordIndex, record);
}

boost::outcome_v2::std_result<dp::master::Dpv1RequestId> Rs4MasterStation::read_record(
    std::uint8_t address, std::uint8_t length) {
  return master_->read(address, kRecordSlot, kRecordIndex, length);
}

const profisafe::FHost* Rs4MasterStation::fhost(std::uint8_t address) const {
  const Slave* s = find(address);
  return s == nullptr ? nullptr : &s->fhost;
}

const Rs4MasterEntry* Rs4MasterStation::entry(std::uint8_t address) const {
  const Slave* s = find(address);
  return s == nullptr ? nullptr : &s->entry;
}

void Rs4MasterStation::take_events(std::vector<Rs4MasterEvent>& out) {
  out.insert(out.end(), std::make_move_iterator(events_.begin()),
             std::make_move_iterator(events_.end()));
  events_.clear();
}

void Rs4MasterStation::take_master_events(std::vector<dp::master::MasterEvent>& out) {
  out.insert(out.end(), std::make_move_iterator(master_events_.begin()),
             std::make_move_iterator(master_events_.end()));
  master_events_.clear();
}

// ---- per call: the master's events, the safety cycle, the changes --------------------------

// Only a master event about an RS4, the safety cycle and the user calls change what its
// view shows: those mark it, and after the call the marked ones are compared with what was
// published, in configuration order (as one pass over all of them would).
void Rs4MasterStation::mark_changed(Slave* s) {
  if (s == nullptr || s->changed) return;
  s->changed = true;
  changed_.push_back(s->index);
}

void Rs4MasterStation::after_call(dp::TimePoint now) {
  scratch_.clear();
  master_->take_events(scratch_);
  if (keep_master_events_)
    master_events_.insert(master_events_.end(), scratch_.begin(), scratch_.end());
  for (auto& e : scratch_) on_master_event(e, now);
  if (all_changed_) {
    for (auto& s : slaves_) publish_changes(*s);
  } else {
    std::sort(changed_.begin(), changed_.end());
    for (const std::size_t i : changed_) publish_changes(*slaves_[i]);
  }
  for (const std::size_t i : changed_) slaves_[i]->changed = false;
  changed_.clear();
  all_changed_ = false;
}

void Rs4MasterStation::on_master_event(dp::master::MasterEvent& e, dp::TimePoint now) {
  if (const auto* cycle = std::get_if<dp::master::CycleCompleted>(&e)) {
    for (auto& s : slaves_) safety_cycle(*s, now);
    all_changed_ = true;
    // Ticks not drained yet collapse into the newest: the queue does not grow by one per
    // cycle for an owner that drains rarely.
    auto* last = events_.empty() ? nullptr : std::get_if<MasterCycle>(&events_.back());
    if (last != nullptr) {
      *last = MasterCycle{cycle->cycle, now};
    } else {
      events_.push_back(MasterCycle{cycle->cycle, now});
    }
  } else if (auto* result = std::get_if<dp::master::Dpv1Result>(&e)) {
    events_.push_back(std::move(*result));
  } else if (const auto* left = std::get_if<dp::master::SlaveLeftDataExchange>(&e)) {
    Slave* s = find(left->address);
    if (s != nullptr) s->reason = left->reason;
    mark_changed(s);
  } else if (const auto* fault = std::get_if<dp::master::SlaveFault>(&e)) {
    Slave* s = find(fault->address);
    if (s != nullptr) s->reason = fault->reason;
    mark_changed(s);
  } else if (const auto* diag = std::get_if<dp::master::DiagReceived>(&e)) {
    Slave* s = find(diag->address);
    const auto number = f_diagnosis_number(std::span(diag->diag.data(), diag->diag.size()));
    if (s != nullptr) s->f_diagnosis = number.value_or(0);
    mark_changed(s);
  } else if (const auto* entered = std::get_if<dp::master::SlaveEnteredDataExchange>(&e)) {
    Slave* s = find(entered->address);
    if (s != nullptr) s->reason = {};
    mark_changed(s);
  }
}

// One PROFIsafe step per master cycle: answer in, next request out ([PROFIsafe V1.30 F-Device
// behaviour]). The F-host starts with the first data exchange; its watchdog keeps running
// while the RS4 is out of data exchange, so a lost RS4 passivates it.
void Rs4MasterStation::safety_cycle(Slave& s, dp::TimePoint now) {
  const bool dx = in_data_exchange(s.address());
  if (dx) {
    const auto in = master_->inputs(s.address());
    if (in.size() == kPduSize) s.fhost.on_pdu(in, now);
  }
  s.fhost.on_time(now);
  if (auto_ack_rei_ && s.fhost.ack_req()) s.fhost.ack_rei();
  if (!dx) return;
  const auto out = s.fhost.request(now);
  if (out.size() == kPduSize) (void)master_->set_outputs(s.address(), out);
}

void Rs4MasterStation::publish_changes(Slave& s) {
  const Rs4SlaveView v = view_of(s);
  Rs4SlaveView& old = s.published;
  // Data exchange entered/left, or a new start-up fault: not every start-up step.
  if (v.data_exchange() != old.data_exchange() || s.reason != s.published_reason) {
    events_.push_back(DpStateChanged{v.address, v.dp_state, s.reason});
    s.published_reason = s.reason;
  }
  if (v.safety != old.safety) events_.push_back(SafetyStateChanged{v.address, v.safety});
  if (v.f_diagnosis != old.f_diagnosis) {
    events_.push_back(FDiagnosisChanged{v.address, v.f_diagnosis});
  }
  if (v.input_byte != old.input_byte) {
    events_.push_back(InputByteChanged{v.address, old.input_byte, v.input_byte});
  }
  old = v;
}

}  // namespace rs4sim::rs4::device
