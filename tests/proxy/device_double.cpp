// The device double of the proxy tests.
#include "tests/proxy/device_double.h"

#include "rs4/protocol/telegram.h"
#include "rs4/scanner/parameter_codec.h"
#include "storage/crc32.h"

#include <algorithm>

namespace rs4sim::proxy::testing {

namespace protocol = rs4::protocol;

DeviceDouble::DeviceDouble() : set(factory_set()) {}

std::vector<std::uint8_t> DeviceDouble::factory_set() {
  static const auto kSet = rs4::scanner::encode(rs4::scanner::factory_default());
  return kSet;
}

RecordResult DeviceDouble::write(std::span<const std::uint8_t> record) {
  if (pc_adapter) return RecordResult::success();  // ignored without an error
  const auto progress = assembler_.push(record);
  if (!progress) return RecordResult::negative(0xB6, 0x00);  // access denied: a bad block
  if (progress.value().complete) {
    ++commands;
    const std::vector<std::uint8_t> command(assembler_.command().begin(),
                                            assembler_.command().end());
    auto answer = execute(command);
    if (answer_hook) answer_hook(command[0], answer);
    if (!answer.empty()) answers_.push_back(std::move(answer));
    not_ready_left_ = not_ready_reads;
  }
  return RecordResult::success();
}

RecordResult DeviceDouble::read(std::uint8_t length) {
  if (pc_adapter) {  // 0 010 000 0: state 010, no payload, not ready
    return RecordResult::success({0x20, 0x04, 0xFF, 0xFF});
  }
  const protocol::FlowControl flow{
      true, false, sync_running ? protocol::FlowState::kProxyBusy : protocol::FlowState::kNormal};
  if (reading_.done() && !answers_.empty() && not_ready_left_ == 0) {
    reading_ = protocol::BlockSplitter(std::move(answers_.front()), length);
    answers_.pop_front();
  }
  if (reading_.done()) {
    if (not_ready_left_ > 0) --not_ready_left_;
    std::vector<std::uint8_t> header;
    (void)protocol::encode_block(protocol::encode_flow_control(flow), protocol::kLastBlockNumber,
                                 {}, header);
    return RecordResult::success(std::move(header));
  }
  return RecordResult::success(reading_.next(flow));
}

void DeviceDouble::rollback() {
  set = factory_set();
  factory = true;
  open_.reset();
}

std::vector<std::uint8_t> DeviceDouble::execute(std::span<const std::uint8_t> command) {
  const auto parsed = protocol::parse_write_command(command);
  if (!parsed) return {};
  if (std::holds_alternative<protocol::ProxyBeginCommand>(parsed.value())) {
    if (!request) return protocol::encode_proxy_begin_answer({{}, {}, factory});
    request = false;
    sync_running = true;
    check_after_release = false;
    return protocol::encode_proxy_begin_answer({reason, direction, factory});
  }
  if (const auto* end = std::get_if<protocol::ProxyEndCommand>(&parsed.value())) {
    // After a release a failure report is still taken (the background verify failed).
    const bool failed = end->outcome != protocol::ProxyOutcome::kSucceeded;
    const bool accepted = sync_running || (failed && check_after_release);
    if (accepted) {
      last_end = *end;
      sync_running = false;
      check_after_release = !failed;
      if (!failed) {
        released = true;
      } else {  // failed: factory settings, ask again
        released = false;
        rollback();
        request = true;
        reason = protocol::SyncReason::kRetry;
        direction = protocol::SyncDirection::kDownload;
      }
    }
    return protocol::encode_proxy_end_answer({accepted, factory});
  }
  return transfer(command);
}

std::vector<std::uint8_t> DeviceDouble::transfer(std::span<const std::uint8_t> command) {
  // As the adapter answers a download command outside a sync (no password: the proxy holds
  // none): the RS4's error telegram 0x53, error 0x0503 (wrong password), parameter = the
  // command, function 0x0005 (command interpreter) ([RS4 manual §7.2.4], rs4_commands.h).
  const std::uint8_t code = command.empty() ? 0 : command[0];
  if (code >= 0x62 && code <= 0x65 && !sync_running) {
    protocol::ErrorTelegram e;
    e.prefix.options.state = protocol::Option1State::kMeasuring;
    e.report = {0x0503, code, 0x0005};
    return protocol::encode_telegram(e).value();
  }
  const auto request_or = protocol::decode_request(command);
  if (!request_or) return {};
  const auto& req = request_or.value();
  protocol::TransferAnswer a;
  a.code = protocol::request_code(req);
  a.options.state = protocol::Option1State::kMeasuring;
  if (std::holds_alternative<protocol::IdentifyRequest>(req)) {
    protocol::Identification id;
    id.device_type = device_type;
    id.serial_number = serial;
    id.firmware_major = 1;
    id.format_version = 1;
    id.set_size = static_cast<std::uint16_t>(set.size());
    id.chunk_size = static_cast<std::uint16_t>(protocol::kMaxChunkSize);
    id.set_crc32 = storage::crc32(set);
    id.flags = factory ? protocol::kFlagFactoryDefault : 0;
    a.body = protocol::IdentifyAnswer{id};
  } else if (const auto* up = std::get_if<protocol::UploadChunkRequest>(&req)) {
    const std::size_t count = (set.size() + protocol::kMaxChunkSize - 1) / protocol::kMaxChunkSize;
    const std::size_t offset = std::size_t{up->chunk} * protocol::kMaxChunkSize;
    if (up->chunk >= count) {
      a.status = protocol::TransferStatus::kBadChunk;
    } else {
      protocol::UploadChunkAnswer u;
      u.chunk = up->chunk;
      u.chunk_count = static_cast<std::uint8_t>(count);
      const auto n = std::min(protocol::kMaxChunkSize, set.size() - offset);
      u.data.assign(set.begin() + static_cast<std::ptrdiff_t>(offset),
                    set.begin() + static_cast<std::ptrdiff_t>(offset + n));
      u.crc32 = storage::crc32(u.data);
      a.body = u;
    }
  } else {
    a = download(req);
  }
  return protocol::encode_answer(a).value();
}

protocol::TransferAnswer DeviceDouble::download(const protocol::TransferRequest& req) {
  protocol::TransferAnswer a;
  a.code = protocol::request_code(req);
  if (std::holds_alternative<protocol::DownloadBreakRequest>(req)) {
    download_broken = true;
    rollback();
    a.body = protocol::DownloadBreakAnswer{protocol::kFlagFactoryDefault};
    return a;
  }
  if (const auto* begin = std::get_if<protocol::DownloadBeginRequest>(&req)) {
    open_ = *begin;
    received_.clear();
    const auto count = (begin->size + protocol::kMaxChunkSize - 1) / protocol::kMaxChunkSize;
    a.body = protocol::DownloadBeginAnswer{static_cast<std::uint8_t>(count),
                                           static_cast<std::uint16_t>(protocol::kMaxChunkSize)};
  } else if (const auto* chunk = std::get_if<protocol::DownloadChunkRequest>(&req)) {
    received_.insert(received_.end(), chunk->data.begin(), chunk->data.end());
    a.body = protocol::DownloadChunkAnswer{chunk->chunk, storage::crc32(chunk->data)};
  } else if (!open_ || storage::crc32(received_) != open_->crc32) {
    a.status = protocol::TransferStatus::kCrcMismatch;
  } else {  // commit
    set = received_;
    factory = false;
    open_.reset();
    a.body = protocol::DownloadCommitAnswer{storage::crc32(set)};
  }
  return a;
}

}  // namespace rs4sim::proxy::testing
