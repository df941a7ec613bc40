// The commands of the GridScan device ([GridScan manual §9.2.3, §9.2.4, §10]).
#include "gridscan/device.h"

namespace rs4sim::gridscan {

using stream::TimePoint;

// [GridScan manual §10.2] "If the sequence counter, ID or the check sum is incorrect no
// data will be responded"; the communication test 0x23 is processed anyway and reports
// what was wrong ([GridScan manual §10.3]). DECISION: a bad sync alone suppresses the reply
// like a bad CRC; a request with the direction bit set counts as a wrong ID.
void Device::answer_request(const RawFrame& raw, TimePoint cycle_end) {
  const Frame& f = raw.frame;
  const bool seq_ok = f.seq == static_cast<std::uint8_t>(last_seq_ + 1U);
  if (f.id == request_id(CommandId::kInfoCommunicationTest)) {
    std::uint8_t bits = 0;
    if (!raw.crc_ok()) bits |= kCommTestCrcWrong;
    if (!seq_ok) bits |= kCommTestSeqCntWrong;
    if (!raw.sync_ok) bits |= kCommTestSyncWrong;
    ++counters_.comm_tests;
    send_answer(CommandId::kInfoCommunicationTest, f.seq, encode_u8(bits));
    return;
  }
  const auto command = command_of(f.id);
  if ((f.id & kDirectionBit) != 0) {
    ++counters_.direction_bit;
  } else if (!command) {
    ++counters_.unknown_id;
  } else if (!raw.sync_ok) {
    ++counters_.bad_sync;
  } else if (!raw.crc_ok()) {
    ++counters_.bad_crc;
  } else if (!seq_ok) {
    ++counters_.bad_seq;
  } else {
    const Reaction r = execute(*command, cycle_end);
    if (r.payload) send_answer(*command, f.seq, *r.payload);
    if (r.restart) {
      ++counters_.restarts;
      power_up(cycle_end);
    }
  }
}

Device::Reaction Device::execute(CommandId c, TimePoint cycle_end) {
  switch (c) {
    case CommandId::kModeSetPolling: return set_mode(CommMode::kPolling);
    case CommandId::kModeSetFullStreaming: return set_mode(CommMode::kFullStreaming);
    case CommandId::kModeSetReducedStreaming: return set_mode(CommMode::kReducedStreaming);
    case CommandId::kModeSetStandBy: return set_mode(CommMode::kStandBy);
    case CommandId::kModeGetCurrent: return {encode_u8(static_cast<std::uint8_t>(mode_))};
    case CommandId::kInfoGetVersion:
      return {encode_version(options_.sw_version, options_.hw_version).value()};
    case CommandId::kInfoGetProductInformation:
      return {encode_product_information(options_.part_number, elements()).value()};
    case CommandId::kInfoGetCountOfElements:
      return {encode_u8(static_cast<std::uint8_t>(elements()))};
    case CommandId::kInfoGetAlignmentValue: return {encode_u16_le(scene_.alignment_value)};
    case CommandId::kInfoRequestAlignmentMode:
      alignment_armed_ = true;  // effective at the next interrupted power-up
      return {Payload{}};
    case CommandId::kDataReducedState: return {state_payload(false)};
    case CommandId::kDataFullState: return {state_payload(true)};
    case CommandId::kSafetyTestInput:
      test_pending_ = !faults_.test_ignored;  // a fault: answered, but no test
      return {Payload{}};
    case CommandId::kConfigAllowChange: return allow_change(cycle_end);
    case CommandId::kConfigSetStatic: return set_configuration(Configuration::kStatic, cycle_end);
    case CommandId::kConfigSetBlanking:
      return set_configuration(Configuration::kBlanking, cycle_end);
    case CommandId::kConfigGetCurrent:
      if (change_allowed_) config_read_ = true;
      return {encode_u8(static_cast<std::uint8_t>(configuration_))};
    case CommandId::kInfoCommunicationTest: break;  // answered in answer_request
  }
  return {};
}

// DECISION: the commands "with no data" answer with an empty payload; leaving stand-by
// ends a configuration sequence; the streaming SeqCnt starts at 0 when streaming starts.
Device::Reaction Device::set_mode(CommMode m) {
  const auto streaming = [](CommMode x) {
    return x == CommMode::kFullStreaming || x == CommMode::kReducedStreaming;
  };
  // [GridScan manual §10.1.1]: "In case of a failure in the activation of the
  // communication mode, the light curtain switches automatically to the polling mode"
  // (DECISION: the request is answered as a success would be; the controller sees the
  // failure in Mode: Get current or in the missing stream).
  if (m != CommMode::kPolling && faults_.mode_activation_fails) {
    ++counters_.mode_fallbacks;
    m = CommMode::kPolling;
  }
  if (streaming(m) && !streaming(mode_)) stream_seq_ = 0;
  if (m == CommMode::kStandBy && mode_ != CommMode::kStandBy) {
    standby_door_ = scene_.door_position;
  }
  if (m != CommMode::kStandBy) change_allowed_ = config_read_ = false;
  mode_ = m;
  return {Payload{}};
}

bool Device::window_over(TimePoint t) const {
  return t - power_up_at_ > options_.config_window;
}

// [GridScan manual §10.4] step 3. DECISION: the checks in the order of the sequence
// (window, stand-by, allowed, read) when several fail.
Device::Reaction Device::allow_change(TimePoint cycle_end) {
  AllowChange code = AllowChange::kAllowed;
  if (window_over(cycle_end)) {
    code = AllowChange::kWindowOver;
  } else if (mode_ != CommMode::kStandBy) {
    code = AllowChange::kNotInStandBy;
  }
  change_allowed_ = code == AllowChange::kAllowed;
  if (!change_allowed_) config_read_ = false;
  return {encode_u8(static_cast<std::uint8_t>(code))};
}

// [GridScan manual §10.4] step 5: no answer on success, the curtain restarts in the new
// mode (DECISION: also when it is the current one); an answer with the code on failure.
Device::Reaction Device::set_configuration(Configuration target,
                                                           TimePoint cycle_end) {
  std::optional<SetConfigResult> failure;
  if (window_over(cycle_end)) {
    failure = SetConfigResult::kWindowOver;
  } else if (mode_ != CommMode::kStandBy) {
    failure = SetConfigResult::kNotInStandBy;
  } else if (!change_allowed_) {
    failure = SetConfigResult::kNotAllowed;
  } else if (!config_read_) {
    failure = SetConfigResult::kNotRead;
  } else if (faults_.config_not_set) {
    failure = SetConfigResult::kNotSet;
  }
  if (failure) return {encode_u8(static_cast<std::uint8_t>(*failure))};
  configuration_ = target;
  return {std::nullopt, true};
}

// [GridScan manual §10.1.1] stand-by reports every element interrupted;
// [GridScan manual §10.1.2] the first state message after a test too (DECISION, docs/gridscan.md).
Payload Device::state_payload(bool full) {
  StateReport r = current_report();
  if (test_pending_) {
    const std::uint8_t door = r.door_position;
    r = test_report();
    if (mode_ == CommMode::kStandBy) r.door_position = door;
    test_pending_ = false;
  }
  return full ? encode_full_state(r, elements()) : encode_reduced_state(r);
}

}  // namespace rs4sim::gridscan
