#include "polaris/device.h"

#include "codec/endian.h"
#include "modbus/error.h"
#include "modbus/pdu.h"
#include "modbus/timing.h"
#include "stream/transmit_queue.h"

#include <algorithm>
#include <utility>

namespace rs4sim::polaris {

namespace {

constexpr std::uint16_t kPadWord = 0xFFFF;  // 485MB beyond the beams: "not interrupted"
// "approximately ... 0.4 seconds * N beams" [Polaris manual §7.2].
constexpr std::chrono::milliseconds kCalibrationPerBeam{400};
// "close the SW1 contact for at least 0.5 seconds and no more than 3 seconds"; "keeping the
// SW1 contact closed for more than 3 seconds": manual adjustment [Polaris manual §7.2].
constexpr std::chrono::milliseconds kSw1Min{500};
constexpr std::chrono::seconds kSw1Max{3};

bool is_write(std::uint8_t function) {
  return function == modbus::kWriteSingleRegister || function == modbus::kWriteMultipleRegisters;
}

// Whether a write's registers overlap the configuration block: FC 6 its register, FC 16
// start..start+quantity-1 (a PDU too short to say is the block's to refuse: 03).
bool writes_config_block(const modbus::RtuFrame& request) {
  if (request.data.size() < 4) return true;
  const std::uint16_t start = codec::be16(request.data[0], request.data[1]);
  std::uint32_t count = 1;
  if (request.function == modbus::kWriteMultipleRegisters) {
    count = std::max<std::uint32_t>(1, codec::be16(request.data[2], request.data[3]));
  }
  return start < kConfigEnd && start + count > kConfigBase;
}

// The refusal a write gets: a PDU that does not parse is a bad quantity/length (03).
ConfigError config_error(const std::error_code& ec) {
  if (ec.category() == codec::category_of<ConfigError>()) {
    return static_cast<ConfigError>(ec.value());
  }
  return ConfigError::kBadQuantity;
}

// The words a read of `r` gets from `block` at `offset` (inside the block): 485MB the
// asked count, padded with free beams (DECISION); FL the rest of the block, the count
// being ignored [Polaris manual §8.2.2].
std::vector<std::uint16_t> read_words(DataMode mode, const std::vector<std::uint16_t>& block,
                                      std::size_t offset, std::uint16_t quantity) {
  if (mode != DataMode::k485Mb) {
    return {block.begin() + static_cast<std::ptrdiff_t>(offset), block.end()};
  }
  std::vector<std::uint16_t> words(quantity, kPadWord);
  for (std::size_t i = 0; i < words.size() && offset + i < block.size(); ++i) {
    words[i] = block[offset + i];
  }
  return words;
}

}  // namespace

Device::Device(Options options)
    : options_(options),
      scan_(scan_duration(options_)),
      framer_(modbus::t3_5(polaris::line_settings(options_)), modbus::kMaxFrameSize),
      scene_(options_.beams) {
  (void)scene_.set_interrupted(options_.blocked);  // validate() has checked the beams
  storage_.observe(options_.storage, scene_.flags());
}

stream::LineSettings Device::line_settings() const { return polaris::line_settings(options_); }

void Device::on_bytes(std::span<const std::uint8_t> bytes, stream::TimePoint now) {
  start(now);
  framer_.feed(bytes, now);
  advance(now);
}

void Device::on_time(stream::TimePoint now) {
  start(now);
  advance(now);
}

std::optional<stream::TimePoint> Device::next_deadline() const {
  std::optional<stream::TimePoint> next = framer_.deadline();
  const auto earliest = [&next](stream::TimePoint t) {
    if (!next || t < *next) next = t;
  };
  if (const auto due = pending_.next_due()) earliest(*due);
  if (next_push_) earliest(*next_push_);
  if (calibration_end_) earliest(*calibration_end_);
  return next;
}

std::optional<std::vector<std::uint8_t>> Device::take_transmit() {
  return stream::take_front(transmit_);
}

std::error_code Device::set_interrupted(std::span<const std::uint16_t> beams,
                                        stream::TimePoint now) {
  if (const std::error_code ec = scene_.set_interrupted(beams)) return ec;
  scene_since_ = now;
  storage_.observe(options_.storage, scene_.flags());
  if (calibrating(now) && scene_.any_interrupted()) {
    // "check that there are no obstacles in the detection area" [Polaris manual §7.2]:
    // an obstacle during the procedure makes it fail (DECISION,
    // [docs/decisions.md#polaris-calibration-obstacles]).
    calibration_end_.reset();
    ++calibrations_failed_;
    wake();
  }
  return {};
}

std::error_code Device::set_response_time(stream::Duration response_time, ResponseColumn column,
                                          stream::TimePoint now) {
  Options next = options_;
  next.response_time = response_time;
  next.response_column = column;
  if (!next.validate().empty()) return ConfigError::kInvalidOptions;
  start(now);
  advance(now);
  options_ = next;
  scan_ = scan_duration(options_);
  epoch_ = now;
  wake();
  return {};
}

std::error_code Device::set_sw1(bool closed, stream::TimePoint now) {
  if (closed) {
    if (!sw1_closed_) sw1_closed_ = now;
    return {};
  }
  if (!sw1_closed_) return {};
  const stream::Duration held = now - *sw1_closed_;
  sw1_closed_.reset();
  if (held > kSw1Max) {
    manual_adjustment_ = true;
    return {};
  }
  if (held < kSw1Min) return {};
  return start_calibration(now);
}

Leds Device::leds(stream::TimePoint now) const {
  std::optional<std::chrono::nanoseconds> running;
  if (calibrating(now)) running = now - (*calibration_end_ - calibration_time());
  return leds_for(scene_.any_interrupted(), running);
}

std::error_code Device::start_calibration(stream::TimePoint now) {
  // What was due before `now` happens first (a real-time runner's timer may fire late): a
  // request that ended before the pulse is answered with data, a push due before it goes.
  start(now);
  advance(now);
  if (calibrating(now)) return std::make_error_code(std::errc::device_or_resource_busy);
  if (scene_.any_interrupted()) return ConfigError::kBeamsInterrupted;
  finish_calibration(now);
  begin_calibration(now);
  wake();
  return {};
}

void Device::begin_calibration(stream::TimePoint start) {
  calibration_end_ = start + calibration_time();
  manual_adjustment_ = false;
}

bool Device::calibrating(stream::TimePoint now) const {
  return calibration_end_ && now < *calibration_end_;
}

stream::Duration Device::calibration_time() const {
  return kCalibrationPerBeam * static_cast<int>(options_.beams);
}

void Device::finish_calibration(stream::TimePoint now) {
  if (!calibration_end_ || now < *calibration_end_) return;
  calibration_end_.reset();
  ++calibrations_;  // wraps at 65535 like its register
}

std::vector<std::uint16_t> Device::data_block() const {
  return data_words(options_, storage_.scan(options_, scene_.flags()));
}

std::vector<std::uint16_t> Device::transmit_block() {
  std::vector<std::uint16_t> words = data_block();
  storage_.transmitted(options_, scene_.flags());
  return words;
}

std::vector<Object> Device::objects() const { return find_objects(options_, scene_.flags()); }

std::vector<std::uint16_t> Device::interrupted() const { return scene_.interrupted(); }

bool Device::pn1() const { return scene_.any_interrupted(); }

bool Device::pn2(stream::TimePoint now) const {
  const bool two_or_hole = objects().size() >= 2;  // a free run between interrupted beams
  if (options_.detection == Detection::kObject) return two_or_hole;
  return two_or_hole && now >= scene_since_ + scan_ * options_.pn2_filter;
}

void Device::start(stream::TimePoint now) {
  if (epoch_) return;
  epoch_ = now;
  scene_since_ = std::max(scene_since_, now);  // a scene set before is seen from here on
  if (options_.role == Role::kMaster) next_push_ = now + options_.scan_time;
}

void Device::advance(stream::TimePoint now) {
  while (std::optional<stream::GapFrame> frame = framer_.poll(now)) handle(*frame);
  while (next_push_ && *next_push_ <= now) {
    finish_calibration(*next_push_);
    if (!calibrating(*next_push_)) push_data(*next_push_);  // DECISION: no data meanwhile
    *next_push_ += options_.scan_time;
  }
  finish_calibration(now);
  while (std::optional<std::vector<std::uint8_t>> frame = pending_.pop_due(now)) {
    transmit_.push_back(std::move(*frame));
    ++counters_.frames_sent;
  }
}

void Device::handle(const stream::GapFrame& frame) {
  if (frame.oversized) {
    ++counters_.oversized;
    return;
  }
  if (options_.role == Role::kMaster) {
    ++counters_.answers_ignored;  // [Polaris manual §8.1.1]: the answer is not checked
    return;
  }
  const stream::TimePoint end = frame.last_byte + framer_.gap();
  finish_calibration(end);
  modbus::RtuFrame request;
  const std::error_code ec = modbus::decode(frame.bytes, request);
  if (ec == modbus::ModbusError::kBadCrc) {
    ++counters_.crc_errors;
    if (options_.nak_on_error && frame.bytes[0] == options_.address) {
      answer(modbus::make_exception(options_.address, frame.bytes[1],
                                    modbus::ExceptionCode::kNegativeAcknowledge),
             end);
    }
    return;
  }
  if (ec) {
    ++counters_.too_short;  // kTooLong cannot pass the framer
    return;
  }
  if (request.address == modbus::kBroadcastAddress) {
    // "Broadcast is not supported" [Polaris manual §8.1]: a configuration write meant for
    // the other slaves of a shared line must not reconfigure this one either.
    ++counters_.broadcasts;
  } else if (request.address != options_.address) {
    ++counters_.foreign_address;
  } else {
    handle_request(request, end);
  }
}

void Device::handle_request(const modbus::RtuFrame& request, stream::TimePoint end) {
  using modbus::ExceptionCode;
  if (is_write(request.function) && !writes_config_block(request)) {
    // The manual's barrier takes no write: "In case of CRC error or incorrect function
    // code, the Exception code ... will be 'Negative Acknowledgment' (0x07)"
    // [Polaris manual §8.1.2]. Only the configuration block (EXTENSION) takes FC 6/16; a
    // write that touches none of its registers is the incorrect function the manual speaks
    // of (standard Modbus, nak_on_error = false: the register does not exist, 02)
    // [docs/decisions.md#polaris-write-outside-config].
    refuse_function(request, end, ExceptionCode::kIllegalDataAddress);
    return;
  }
  if (is_write(request.function)) {
    handle_write(request, end);
    return;
  }
  if (request.function != modbus::kReadHoldingRegisters &&
      request.function != modbus::kReadInputRegisters) {
    refuse_function(request, end, ExceptionCode::kIllegalFunction);
    return;
  }
  handle_read(request, end);
}

void Device::refuse_function(const modbus::RtuFrame& request, stream::TimePoint end,
                             modbus::ExceptionCode standard) {
  ++counters_.bad_function;
  answer(modbus::make_exception(options_.address, request.function,
                                options_.nak_on_error ? modbus::ExceptionCode::kNegativeAcknowledge
                                                      : standard),
         end);
}

void Device::handle_read(const modbus::RtuFrame& request, stream::TimePoint end) {
  using modbus::ExceptionCode;
  const auto refuse = [&](ExceptionCode code) {
    answer(modbus::make_exception(options_.address, request.function, code), end);
  };
  modbus::ReadRequest read;
  std::error_code ec = modbus::parse_read_request(request, read);
  if (request.data.size() == 4 && in_config_block(codec::be16(request.data[0], request.data[1]))) {
    std::vector<std::uint16_t> words;
    if (!ec) {
      ec = read_config(options_,
                       CalibrationStatus{calibrating(end), calibrations_, manual_adjustment_},
                       read.start, read.quantity, words);
    }
    if (ec == ConfigError::kUnknownRegister) {
      ++counters_.bad_start;
      refuse(ExceptionCode::kIllegalDataAddress);
    } else if (ec) {
      ++counters_.bad_request;
      refuse(ExceptionCode::kIllegalDataValue);
    } else {
      ++counters_.requests;
      answer(modbus::make_read_response(options_.address, request.function, words), end);
    }
    return;
  }
  if (ec == modbus::ModbusError::kBadQuantity && options_.mode != DataMode::k485Mb) {
    read = {request.function, codec::be16(request.data[0], request.data[1]), 0};
    ec = {};
  }
  if (ec) {
    ++counters_.bad_request;
    refuse(ExceptionCode::kIllegalDataValue);
    return;
  }
  const std::vector<std::uint16_t> block = data_block();
  const std::uint16_t base = start_address(options_);
  if (read.start < base || read.start - base >= static_cast<int>(block.size())) {
    ++counters_.bad_start;
    refuse(ExceptionCode::kIllegalDataAddress);
    return;
  }
  if (calibrating(end)) {  // DECISION: no measurement while the beams are adjusted
    ++counters_.busy;
    refuse(ExceptionCode::kServerDeviceBusy);
    return;
  }
  ++counters_.requests;
  storage_.transmitted(options_, scene_.flags());  // [Polaris manual §7.4.2]
  const auto words = read_words(options_.mode, block, read.start - base, read.quantity);
  answer(modbus::make_read_response(options_.address, request.function, words), end);
}

void Device::handle_write(const modbus::RtuFrame& request, stream::TimePoint end) {
  std::uint16_t start = 0;
  std::vector<std::uint16_t> words;
  std::error_code ec;
  if (request.function == modbus::kWriteSingleRegister) {
    modbus::WriteSingleRequest single;
    ec = modbus::parse_write_single(request, single);
    start = single.address;
    words.push_back(single.value);
  } else {
    modbus::WriteMultipleRequest multiple;
    ec = modbus::parse_write_multiple(request, multiple);
    start = multiple.start;
    words = std::move(multiple.words);
  }
  ConfigWrite write;
  if (!ec) ec = write_config(options_, start, words, write);
  if (!ec && write.start_calibration && calibrating(end)) ec = ConfigError::kBusy;
  if (!ec && write.start_calibration && scene_.any_interrupted()) {
    ec = ConfigError::kBeamsInterrupted;
  }
  if (ec) {
    ++counters_.refused_writes;
    answer(modbus::make_exception(options_.address, request.function,
                                  exception_for(config_error(ec))),
           end);
    return;
  }
  // Only settings that leave the line and the scan as they are: the framer and scan_ stay.
  options_ = write.options;
  if (write.manual_adjustment) manual_adjustment_ = true;
  if (write.start_calibration) begin_calibration(end);
  ++counters_.writes;
  if (request.function == modbus::kWriteSingleRegister) {
    answer(modbus::make_write_single_response(options_.address, {start, words.front()}), end);
  } else {
    answer(modbus::make_write_multiple_response(options_.address, start,
                                                static_cast<std::uint16_t>(words.size())),
           end);
  }
}

void Device::answer(const modbus::RtuFrame& reply, stream::TimePoint end) {
  if (modbus::is_exception(reply)) ++counters_.exceptions_sent;
  schedule(modbus::encode(reply), scan_end_after(end));
}

void Device::push_data(stream::TimePoint due) {
  std::vector<std::uint16_t> words = transmit_block();
  if (words.size() > modbus::kMaxWriteQuantity) words.resize(modbus::kMaxWriteQuantity);
  schedule(
      modbus::encode(modbus::make_write_multiple(options_.address, start_address(options_), words)),
      due);
}

void Device::schedule(std::vector<std::uint8_t> bytes, stream::TimePoint due) {
  if (faults_.bad_crc) bytes.back() = static_cast<std::uint8_t>(~bytes.back());
  if (!pending_.schedule(std::move(bytes), due, faults_.transmit)) ++counters_.suppressed;
}

stream::TimePoint Device::scan_end_after(stream::TimePoint t) const {
  const stream::Duration since = t - *epoch_;
  const auto scans = (since + scan_ - stream::Duration{1}) / scan_;
  return *epoch_ + scan_ * scans;
}

}  // namespace rs4sim::polaris
