#include "rs4/param_doc/rs232_set_client.h"

#include "rs4/scanner/crc32.h"
#include "rs4/scanner/parameter_codec.h"

#include <algorithm>
#include <cstdio>

namespace rs4sim::rs4::param_doc {
namespace {

using protocol::TransferAnswer;
using protocol::TransferRequest;
using protocol::TransferStatus;

struct Step {
  std::optional<protocol::TransferAnswerBody> body;
  std::string error;
};

std::string hex(unsigned value) {
  char b[16];
  std::snprintf(b, sizeof b, "0x%04X", value);
  return b;
}

// One transfer command and its kOk answer body, or why not.
Step transfer(const Exchange& exchange, const TransferRequest& request,
              const rs232::CommandOptions& options = {}) {
  const auto frame = rs232::encode_transfer(request, options);
  if (!frame) return {std::nullopt, "cannot encode the command: " + frame.error().message()};
  const auto code = static_cast<unsigned>(protocol::request_code(request));
  const auto answer = exchange(frame.value());
  if (!answer) return {std::nullopt, "no answer to command " + hex(code)};
  if (const auto* e = std::get_if<protocol::ErrorTelegram>(&*answer)) {
    return {std::nullopt, "the RS4 refused command " + hex(code) + " with error " +
                              hex(e->report.number) +
                              (e->report.number == 0x0503 ? " (wrong password)" : "")};
  }
  const auto* t = std::get_if<TransferAnswer>(&*answer);
  if (t == nullptr || static_cast<unsigned>(t->code) != code) {
    return {std::nullopt, "unexpected answer to command " + hex(code)};
  }
  if (t->status != TransferStatus::kOk) {
    return {std::nullopt, "command " + hex(code) + ": " + protocol::to_string(t->status)};
  }
  return {t->body, {}};
}

template <class T>
const T* body_of(const Step& step) {
  return step.body ? std::get_if<T>(&*step.body) : nullptr;
}

}  // namespace

LiveSet read_live_set(const Exchange& exchange) {
  const Step id = transfer(exchange, protocol::IdentifyRequest{});
  const auto* identify = body_of<protocol::IdentifyAnswer>(id);
  if (identify == nullptr) return {std::nullopt, id.error.empty() ? "bad IDENTIFY" : id.error};
  const auto& info = identify->identification;
  std::vector<std::uint8_t> blob;
  for (std::size_t x = 0; x < info.chunk_count(); ++x) {
    const Step chunk =
        transfer(exchange, protocol::UploadChunkRequest{static_cast<std::uint8_t>(x)});
    const auto* c = body_of<protocol::UploadChunkAnswer>(chunk);
    if (c == nullptr) return {std::nullopt, chunk.error.empty() ? "bad chunk" : chunk.error};
    if (scanner::crc32_iso_hdlc(c->data) != c->crc32) {
      return {std::nullopt, "chunk " + std::to_string(x) + ": CRC-32 mismatch"};
    }
    blob.insert(blob.end(), c->data.begin(), c->data.end());
  }
  if (scanner::crc32_iso_hdlc(blob) != info.set_crc32) {
    return {std::nullopt, "the uploaded set does not have the CRC-32 IDENTIFY announced"};
  }
  auto decoded = scanner::decode_transfer_form(blob);
  if (!decoded) return {std::nullopt, "uploaded set invalid: " + decoded.error().message()};
  scanner::ParameterSet set = decoded.value();
  for (auto& pw : set.passwords) pw.fill(0xFF);  // never transferred: shown as empty
  set.identity = {info.serial_number, info.device_type, info.firmware_major, info.firmware_minor};
  return {set, {}};
}

std::string write_live_set(const Exchange& exchange, const scanner::ParameterSet& set,
                           const scanner::Password& password) {
  const auto blob = scanner::encode_for_transfer(set);
  const std::uint32_t crc = scanner::crc32_iso_hdlc(blob);
  const rs232::CommandOptions with_password{false, password};
  const Step begin = transfer(
      exchange, protocol::DownloadBeginRequest{static_cast<std::uint16_t>(blob.size()), crc},
      with_password);
  const auto* b = body_of<protocol::DownloadBeginAnswer>(begin);
  if (b == nullptr) return begin.error.empty() ? "bad DOWNLOAD_BEGIN answer" : begin.error;
  for (std::size_t x = 0; x < b->chunk_count; ++x) {
    const std::size_t from = x * b->chunk_size;
    const std::size_t size = std::min<std::size_t>(b->chunk_size, blob.size() - from);
    const std::span<const std::uint8_t> data(blob.data() + from, size);
    const Step chunk =
        transfer(exchange, protocol::DownloadChunkRequest{static_cast<std::uint8_t>(x), data},
                 with_password);
    const auto* c = body_of<protocol::DownloadChunkAnswer>(chunk);
    if (c == nullptr) return chunk.error.empty() ? "bad DOWNLOAD_CHUNK answer" : chunk.error;
    if (c->echo_crc32 != scanner::crc32_iso_hdlc(data)) {
      return "chunk " + std::to_string(x) + ": the RS4 received other bytes (CRC-32 echo)";
    }
  }
  const Step commit = transfer(exchange, protocol::DownloadCommitRequest{}, with_password);
  const auto* done = body_of<protocol::DownloadCommitAnswer>(commit);
  if (done == nullptr) return commit.error.empty() ? "bad DOWNLOAD_COMMIT answer" : commit.error;
  if (done->active_crc32 != crc) return "the RS4's active set has another CRC-32 than the one sent";
  return {};
}

}  // namespace rs4sim::rs4::param_doc
