// One command/answer exchange in the block protocol ([RS4 manual §5.2.1]).
#include "proxy/exchange.h"

#include "rs4/protocol/block.h"

#include <algorithm>

namespace rs4sim::proxy {

namespace protocol = rs4::protocol;

namespace {
constexpr std::uint8_t kRs4ErrorTelegram = 0x53;  // COM_CMD_ERROR_OCCURE ([RS4 manual §5.2.3])
constexpr std::uint8_t kErrorInTelegram = 0x93;  // adapter: error in telegram ([RS4 manual §5.2.2])

bool is_foreign(std::span<const std::uint8_t> answer, std::uint8_t expected) {
  return !answer.empty() && answer[0] != expected && answer[0] != kRs4ErrorTelegram &&
         answer[0] != kErrorInTelegram;
}
}  // namespace

void Exchange::start(std::span<const std::uint8_t> command, dp::TimePoint now,
                     ExchangeTiming timing) {
  reset();
  timing_ = timing;
  status_ = Status::kBusy;
  deadline_ = now + timing_.answer_timeout;
  if (command.empty() || command.size() > protocol::kMaxCommandSize) {
    status_ = Status::kBadRecord;
    return;
  }
  expected_ = command[0];
  for (std::size_t offset = 0; offset < command.size(); offset += protocol::kMaxBlockPayload) {
    const std::size_t n = std::min(protocol::kMaxBlockPayload, command.size() - offset);
    const bool last = offset + n == command.size();
    const auto number =
        last ? protocol::kLastBlockNumber : static_cast<std::uint16_t>(writes_.size());
    std::vector<std::uint8_t> record;
    (void)protocol::encode_block(0x00, number, command.subspan(offset, n), record);
    writes_.push_back(std::move(record));
  }
}

void Exchange::reset() noexcept {
  status_ = Status::kIdle;
  writes_.clear();
  next_write_ = 0;
  outstanding_ = false;
  answer_.clear();
  next_block_ = 0;
  expected_ = 0;
  sfc_ = 0;
  pc_adapter_ = false;
}

std::optional<RecordRequest> Exchange::take_request(dp::TimePoint now) {
  if (status_ != Status::kBusy || outstanding_) return std::nullopt;
  if (next_write_ < writes_.size()) {
    outstanding_ = true;
    return RecordWrite{writes_[next_write_]};
  }
  if (now < read_due_) return std::nullopt;
  outstanding_ = true;
  return RecordRead{};
}

void Exchange::on_result(const RecordResult& result, dp::TimePoint now) {
  if (status_ != Status::kBusy || !outstanding_) return;  // stale: ignored
  outstanding_ = false;
  if (next_write_ < writes_.size()) {
    on_write_result(result, now);
  } else {
    on_read_result(result, now);
  }
}

void Exchange::on_write_result(const RecordResult& result, dp::TimePoint now) {
  if (!result.ok) {
    sfc_ = result.sfc;
    status_ = Status::kWriteFailed;
    return;
  }
  ++next_write_;
  if (next_write_ == writes_.size()) {
    read_due_ = now;
    deadline_ = now + timing_.answer_timeout;
  }
}

void Exchange::on_read_result(const RecordResult& result, dp::TimePoint now) {
  if (!result.ok) {
    sfc_ = result.sfc;
    status_ = Status::kReadFailed;
    return;
  }
  const auto block = protocol::decode_block(result.data, protocol::Direction::kRead);
  if (!block || (block.value().header.number != protocol::kLastBlockNumber &&
                 block.value().header.number != next_block_)) {
    status_ = Status::kBadRecord;
    return;
  }
  const auto& view = block.value();
  const auto flow = protocol::decode_flow_control(view.header.flow_control);
  if (flow && flow.value().state == protocol::FlowState::kPcAdapterAttached) {
    pc_adapter_ = true;  // no answer will come while the PC adapter is attached
    sfc_ = 0;
    status_ = Status::kReadFailed;
    return;
  }
  if (view.payload.empty() && view.header.is_last() && next_block_ == 0) {
    read_due_ = now + timing_.poll_interval;  // not ready yet
    return;
  }
  answer_.insert(answer_.end(), view.payload.begin(), view.payload.end());
  if (answer_.size() > protocol::kMaxCommandSize) {
    status_ = Status::kBadRecord;
    return;
  }
  read_due_ = now;
  if (!view.header.is_last()) {
    ++next_block_;
    return;
  }
  if (is_foreign(answer_, expected_)) {  // not our answer: keep reading
    answer_.clear();
    next_block_ = 0;
    return;
  }
  status_ = Status::kDone;
}

void Exchange::tick(dp::TimePoint now) {
  if (status_ == Status::kBusy && !outstanding_ && next_write_ == writes_.size() &&
      now >= deadline_) {
    sfc_ = 0;
    status_ = Status::kReadFailed;
  }
}

std::optional<dp::TimePoint> Exchange::next_wakeup() const noexcept {
  if (status_ != Status::kBusy || outstanding_ || next_write_ < writes_.size()) return std::nullopt;
  return std::min(read_due_, deadline_);
}

}  // namespace rs4sim::proxy
