#include "rs4/protocol/parameter_transfer.h"

#include "codec/reader.h"
#include "codec/writer.h"

#include <type_traits>

namespace rs4sim::rs4::protocol {
namespace {

constexpr std::uint8_t byte(TransferCode c) noexcept { return static_cast<std::uint8_t>(c); }
constexpr auto kMaxStatus = static_cast<std::uint8_t>(TransferStatus::kAdapterAttached);

template <typename... Ts>
struct Overloaded : Ts... {
  using Ts::operator()...;
};
// clang 14 has no class template argument deduction for aggregates (P1816): spelled out.
template <typename... Ts>
Overloaded(Ts...) -> Overloaded<Ts...>;

// A reader over the fields after CMD and the option bytes; checks the end.
template <typename T>
Result<T> finish(const codec::Reader& r, T value) {
  if (!r.ok()) return ProtocolError::kTruncated;
  if (!r.at_end()) return ProtocolError::kTrailingBytes;
  return value;
}

void write_identification(codec::Appender<std::vector<std::uint8_t>>& w, const Identification& i) {
  w.u16_be(i.device_type);
  w.u32_be(i.serial_number);
  w.u8(i.firmware_major);
  w.u8(i.firmware_minor);
  w.u8(i.format_version);
  w.u16_be(i.set_size);
  w.u16_be(i.chunk_size);
  w.u32_be(i.set_crc32);
  w.u8(i.flags);
  w.u16_be(i.change_counter);
}

Result<TransferAnswerBody> read_identification(codec::Reader& r) {
  Identification i;
  i.device_type = r.u16_be();
  i.serial_number = r.u32_be();
  i.firmware_major = r.u8();
  i.firmware_minor = r.u8();
  i.format_version = r.u8();
  i.set_size = r.u16_be();
  i.chunk_size = r.u16_be();
  i.set_crc32 = r.u32_be();
  i.flags = r.u8();
  i.change_counter = r.u16_be();
  if (!r.ok()) return ProtocolError::kTruncated;
  if (i.chunk_size == 0 || i.chunk_size > kMaxChunkSize || (i.flags & ~kFlagsDefined) != 0 ||
      i.chunk_count() > kMaxChunkCount) {
    return ProtocolError::kBadAnswerValue;
  }
  return TransferAnswerBody{IdentifyAnswer{i}};
}

Result<TransferAnswerBody> read_upload_chunk(codec::Reader& r) {
  UploadChunkAnswer a;
  a.chunk = r.u8();
  a.chunk_count = r.u8();
  const std::uint16_t length = r.u16_be();
  a.crc32 = r.u32_be();
  if (!r.ok()) return ProtocolError::kTruncated;
  if (a.chunk_count == 0 || a.chunk_count > kMaxChunkCount || a.chunk >= a.chunk_count ||
      length == 0 || length > kMaxChunkSize) {
    return ProtocolError::kBadAnswerValue;
  }
  const auto data = r.bytes(length);
  if (!r.ok()) return ProtocolError::kTruncated;
  a.data.assign(data.begin(), data.end());
  return TransferAnswerBody{std::move(a)};
}

Result<TransferAnswerBody> read_body(TransferCode code, codec::Reader& r) {
  switch (code) {
    case TransferCode::kIdentify: return read_identification(r);
    case TransferCode::kUploadChunk: return read_upload_chunk(r);
    case TransferCode::kDownloadBegin: {
      DownloadBeginAnswer a;
      a.chunk_count = r.u8();
      a.chunk_size = r.u16_be();
      if (!r.ok()) return ProtocolError::kTruncated;
      if (a.chunk_count == 0 || a.chunk_count > kMaxChunkCount || a.chunk_size == 0 ||
          a.chunk_size > kMaxChunkSize) {
        return ProtocolError::kBadAnswerValue;
      }
      return TransferAnswerBody{a};
    }
    case TransferCode::kDownloadChunk: {
      DownloadChunkAnswer a;
      a.chunk = r.u8();
      a.echo_crc32 = r.u32_be();
      if (a.chunk >= kMaxChunkCount) return ProtocolError::kBadAnswerValue;
      return TransferAnswerBody{a};
    }
    case TransferCode::kDownloadCommit: return TransferAnswerBody{DownloadCommitAnswer{r.u32_be()}};
    case TransferCode::kDownloadBreak: {
      DownloadBreakAnswer a{r.u8()};
      if ((a.flags & ~kFlagsDefined) != 0) return ProtocolError::kBadAnswerValue;
      return TransferAnswerBody{a};
    }
  }
  return ProtocolError::kBadAnswerCode;
}

// Each request and answer type names the code it belongs to (kCode).
template <class Variant>
TransferCode code_of(const Variant& message) noexcept {
  return std::visit([](const auto& m) { return std::remove_cvref_t<decltype(m)>::kCode; },
                    message);
}

std::error_code write_body(codec::Appender<std::vector<std::uint8_t>>& w,
                           const TransferAnswerBody& body) {
  return std::visit(Overloaded{[&](const IdentifyAnswer& a) -> std::error_code {
                                 write_identification(w, a.identification);
                                 return {};
                               },
                               [&](const UploadChunkAnswer& a) -> std::error_code {
                                 if (a.data.empty() || a.data.size() > kMaxChunkSize) {
                                   return ProtocolError::kBadAnswerValue;
                                 }
                                 w.u8(a.chunk);
                                 w.u8(a.chunk_count);
                                 w.u16_be(static_cast<std::uint16_t>(a.data.size()));
                                 w.u32_be(a.crc32);
                                 w.bytes(a.data);
                                 return {};
                               },
                               [&](const DownloadBeginAnswer& a) -> std::error_code {
                                 w.u8(a.chunk_count);
                                 w.u16_be(a.chunk_size);
                                 return {};
                               },
                               [&](const DownloadChunkAnswer& a) -> std::error_code {
                                 w.u8(a.chunk);
                                 w.u32_be(a.echo_crc32);
                                 return {};
                               },
                               [&](const DownloadCommitAnswer& a) -> std::error_code {
                                 w.u32_be(a.active_crc32);
                                 return {};
                               },
                               [&](const DownloadBreakAnswer& a) -> std::error_code {
                                 w.u8(a.flags);
                                 return {};
                               }},
                    body);
}

}  // namespace

bool is_transfer_code(std::uint8_t code) noexcept {
  return code >= byte(TransferCode::kIdentify) && code <= byte(TransferCode::kDownloadBreak);
}

const char* to_string(TransferStatus s) noexcept {
  switch (s) {
    case TransferStatus::kOk: return "ok";
    case TransferStatus::kWrongLength: return "wrong length";
    case TransferStatus::kBadChunk: return "bad chunk number";
    case TransferStatus::kNoDownload: return "no download open";
    case TransferStatus::kSizeMismatch: return "size mismatch";
    case TransferStatus::kCrcMismatch: return "CRC-32 mismatch";
    case TransferStatus::kInvalidSet: return "invalid parameter set";
    case TransferStatus::kNotOperational: return "RS4 not operational";
    case TransferStatus::kNoSyncRunning: return "no proxy sync running";
    case TransferStatus::kAdapterAttached: return "PC adapter attached";
  }
  return "unknown";
}

std::size_t Identification::chunk_count() const noexcept {
  if (chunk_size == 0) return 0;
  return (std::size_t{set_size} + chunk_size - 1U) / chunk_size;
}

TransferCode request_code(const TransferRequest& request) noexcept { return code_of(request); }

Result<std::vector<std::uint8_t>> encode_request(const TransferRequest& request) {
  return encode_request(request, TelegramPrefix{});
}

Result<std::vector<std::uint8_t>> encode_request(const TransferRequest& request,
                                                 const TelegramPrefix& prefix) {
  std::vector<std::uint8_t> out;
  if (const auto ec = encode_prefix(byte(request_code(request)), prefix, out)) return ec;
  codec::Appender w(out);
  if (const auto* up = std::get_if<UploadChunkRequest>(&request)) {
    w.u8(up->chunk);
  } else if (const auto* begin = std::get_if<DownloadBeginRequest>(&request)) {
    w.u16_be(begin->size);
    w.u32_be(begin->crc32);
  } else if (const auto* chunk = std::get_if<DownloadChunkRequest>(&request)) {
    if (chunk->data.empty() || chunk->data.size() > kMaxChunkSize) {
      return ProtocolError::kBadAnswerValue;
    }
    w.u8(chunk->chunk);
    w.bytes(chunk->data);
  }
  return out;
}

Result<TransferRequest> decode_request(std::span<const std::uint8_t> body) {
  if (body.empty() || !is_transfer_code(body[0])) return ProtocolError::kBadCommandByte;
  const auto prefix = decode_prefix(body);
  if (!prefix) return prefix.error();
  codec::Reader r(body.subspan(prefix.value().size));
  switch (static_cast<TransferCode>(body[0])) {
    case TransferCode::kIdentify: return finish(r, TransferRequest{IdentifyRequest{}});
    case TransferCode::kUploadChunk: {
      const UploadChunkRequest up{r.u8()};
      return finish(r, TransferRequest{up});
    }
    case TransferCode::kDownloadBegin: {
      DownloadBeginRequest begin;
      begin.size = r.u16_be();
      begin.crc32 = r.u32_be();
      return finish(r, TransferRequest{begin});
    }
    case TransferCode::kDownloadChunk: {
      const std::uint8_t chunk = r.u8();
      if (!r.ok()) return ProtocolError::kTruncated;
      const auto data = r.rest();
      if (data.empty() || data.size() > kMaxChunkSize) return ProtocolError::kBadAnswerValue;
      return TransferRequest{DownloadChunkRequest{chunk, data}};
    }
    case TransferCode::kDownloadCommit: return finish(r, TransferRequest{DownloadCommitRequest{}});
    case TransferCode::kDownloadBreak: return finish(r, TransferRequest{DownloadBreakRequest{}});
  }
  return ProtocolError::kBadCommandByte;
}

Result<std::vector<std::uint8_t>> encode_answer(const TransferAnswer& answer) {
  std::vector<std::uint8_t> out;
  if (const auto ec = encode_prefix(byte(answer.code), TelegramPrefix{answer.options, {}}, out)) {
    return ec;
  }
  codec::Appender w(out);
  w.u8(static_cast<std::uint8_t>(answer.status));
  if (answer.status != TransferStatus::kOk) return out;
  if (!answer.body || code_of(*answer.body) != answer.code) {
    return ProtocolError::kBadAnswerValue;
  }
  if (const auto ec = write_body(w, *answer.body)) return ec;
  return out;
}

Result<TransferAnswer> decode_answer(std::span<const std::uint8_t> body) {
  if (body.empty() || !is_transfer_code(body[0])) return ProtocolError::kBadAnswerCode;
  const auto prefix = decode_prefix(body);
  if (!prefix) return prefix.error();
  TransferAnswer a;
  a.code = static_cast<TransferCode>(body[0]);
  a.options = prefix.value().prefix.options;
  codec::Reader r(body.subspan(prefix.value().size));
  const std::uint8_t status = r.u8();
  if (!r.ok()) return ProtocolError::kTruncated;
  if (status > kMaxStatus) return ProtocolError::kBadAnswerValue;
  a.status = static_cast<TransferStatus>(status);
  if (a.status != TransferStatus::kOk) return finish(r, std::move(a));
  auto parsed = read_body(a.code, r);
  if (!parsed) return parsed.error();
  a.body = std::move(parsed.value());
  return finish(r, std::move(a));
}

}  // namespace rs4sim::rs4::protocol
