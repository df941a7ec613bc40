#include "rs4/device/rs4_segment.h"

#include "rs4/protocol/block.h"

#include <stdexcept>
#include <type_traits>

namespace rs4sim::rs4::device {

namespace {

Rs4MasterEntry make_entry(const Rs4MasterOptions& options) {
  auto e = rs4_master_entry(options);
  if (!e) throw std::invalid_argument("RS4 master configuration from the GSD: " + e.error().what());
  return std::move(e).value();
}

dp::master::MasterConfig master_config(const Rs4SegmentConfig& c, const Rs4MasterEntry& e) {
  dp::master::MasterConfig m;
  m.address = c.master_address;
  m.bus = dp::master::BusParameters::defaults_for(c.baud);
  m.cycle_target = c.cycle_target;
  m.slaves.push_back(e.slave);
  return m;
}

}  // namespace

Rs4Segment::Rs4Segment(const Rs4SegmentConfig& config)
    : entry_(make_entry(config.master)),
      device_(std::make_unique<Rs4Device>(config.device)),
      master_(std::make_unique<dp::master::Master>(master_config(config, entry_))),
      fhost_(std::make_unique<profisafe::FHost>(rs4_fhost_config(entry_))),
      bus_(std::make_unique<dp::link::MemoryBus>(clock_, config.bus)),
      output_(config.output_byte),
      auto_ack_rei_(config.auto_ack_rei),
      keep_events_(config.keep_events) {
  fhost_->set_output(std::span<const std::uint8_t>(&output_, 1));
  bus_->attach(*master_);
  bus_->attach(*device_);
  bus_->start();
  safety_cycle();
}

void Rs4Segment::set_output_byte(std::uint8_t out) {
  output_ = out;
  fhost_->set_output(std::span<const std::uint8_t>(&output_, 1));
}

std::uint8_t Rs4Segment::input_byte() const {
  const auto in = fhost_->input();
  return in.empty() ? 0 : in[0];
}

bool Rs4Segment::in_data_exchange() const {
  return master_->poll_state(rs4_address()) == dp::master::PollState::kDataExchange;
}

// One PROFIsafe step per master cycle: answer in, next request out
// ([PROFIsafe V1.30 F-Device behaviour]). The F-host starts with the first data exchange (its
// watchdog runs from the first PDU).
void Rs4Segment::safety_cycle() {
  if (!in_data_exchange()) return;
  const auto now = clock_.now();
  const auto in = master_->inputs(rs4_address());
  if (in.size() == adapter::kPduSize) fhost_->on_pdu(in, now);
  fhost_->on_time(now);
  if (auto_ack_rei_ && fhost_->ack_req()) fhost_->ack_rei();
  const auto out = fhost_->request(now);
  if (out.size() == adapter::kPduSize) (void)master_->set_outputs(rs4_address(), out);
}

void Rs4Segment::collect() {
  scratch_.clear();
  master_->take_events(scratch_);
  for (auto& e : scratch_) {
    if (std::holds_alternative<dp::master::CycleCompleted>(e)) safety_cycle();
    if (observer_) observer_(e);
    if (keep_events_ || awaiting_ > 0) events_.push_back(std::move(e));
  }
}

bool Rs4Segment::run_until(const std::function<bool()>& done, dp::Duration timeout) {
  return bus_->run_until(done, clock_.now() + timeout, [this] { collect(); });
}

void Rs4Segment::run_for(dp::Duration d) {
  run_until([] { return false; }, d);
}

std::optional<dp::master::Dpv1Result> Rs4Segment::await(dp::master::Dpv1RequestId id,
                                                        dp::Duration timeout) {
  std::optional<dp::master::Dpv1Result> result;
  const auto size_before = events_.size();
  ++awaiting_;
  run_until(
      [&] {
        for (std::size_t i = size_before; i < events_.size(); ++i) {
          const auto* r = std::get_if<dp::master::Dpv1Result>(&events_[i]);
          if (r && r->id == id) {
            result = *r;
            return true;
          }
        }
        return false;
      },
      timeout);
  if (--awaiting_ == 0 && !keep_events_) events_.clear();
  return result;
}

std::optional<dp::master::Dpv1Result> Rs4Segment::write_record(std::span<const std::uint8_t> record,
                                                               dp::Duration timeout) {
  auto id = master_->write(rs4_address(), 0, 2, record);
  if (!id) return std::nullopt;
  return await(id.value(), timeout);
}

std::optional<dp::master::Dpv1Result> Rs4Segment::read_record(std::uint8_t length,
                                                              dp::Duration timeout) {
  auto id = master_->read(rs4_address(), 0, 2, length);
  if (!id) return std::nullopt;
  return await(id.value(), timeout);
}

boost::outcome_v2::std_result<std::vector<std::uint8_t>> Rs4Segment::command(
    std::span<const std::uint8_t> payload, dp::Duration timeout) {
  std::vector<std::uint8_t> record;
  if (auto ec = protocol::encode_block(0x00, protocol::kLastBlockNumber, payload, record))
    return ec;
  const auto written = write_record(record, timeout);
  if (!written) return std::make_error_code(std::errc::timed_out);
  if (written->error) return written->error;
  const auto end = now() + timeout;
  std::vector<std::uint8_t> answer;
  while (now() < end) {
    const auto read = read_record(240, end - now());
    if (!read) break;
    if (read->error) return read->error;
    const std::span<const std::uint8_t> bytes(read->data.data(), read->data.size());
    auto block = protocol::decode_block(bytes, protocol::Direction::kRead);
    if (!block) return block.error();
    const bool has_payload = !block.value().payload.empty();
    answer.insert(answer.end(), block.value().payload.begin(), block.value().payload.end());
    if (block.value().header.is_last() && (has_payload || !answer.empty())) return answer;
    if (!has_payload) run_for(master_->config().cycle_target);  // not ready yet
  }
  return std::make_error_code(std::errc::timed_out);
}

std::vector<dp::master::MasterEvent> Rs4Segment::take_events() {
  collect();
  return std::exchange(events_, {});
}

}  // namespace rs4sim::rs4::device
