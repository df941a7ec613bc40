// The proxy's EXTENSION commands ([docs/proxy-protocol.md]): RS4 transfer commands 0x60..0x65
// and the adapter commands 0x98 / 0x99. The expected bytes are written out by hand from the
// layout tables of docs/proxy-protocol.md, field by field.
#include "rs4/protocol/adapter_answer.h"
#include "rs4/protocol/adapter_command.h"
#include "rs4/protocol/parameter_transfer.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace rs4sim::rs4::protocol {
namespace {

using Bytes = std::vector<std::uint8_t>;

// The RS4 measuring with field pair 1 selected, no flag set ([RS4 manual §5.2.3] table 5.2-9).
OptionBytes measuring_pair1() {
  OptionBytes o;
  o.state = Option1State::kMeasuring;
  o.first_field_pair = 1;
  return o;
}

TEST(ParameterTransferRequest, BytesOfEveryRequest) {
  EXPECT_EQ(encode_request(IdentifyRequest{}).value(), (Bytes{0x60, 0x01}));
  EXPECT_EQ(encode_request(UploadChunkRequest{3}).value(), (Bytes{0x61, 0x01, 0x03}));
  EXPECT_EQ(encode_request(DownloadBeginRequest{8507, 0x12345678}).value(),
            (Bytes{
                0x62,                    // DOWNLOAD_BEGIN
                0x01,                    // option 1: one option byte, state "none"
                0x21, 0x3B,              // size 8507, high byte first
                0x12, 0x34, 0x56, 0x78,  // CRC-32 of the transfer form
            }));
  const Bytes data{0xAA, 0xBB, 0xCC};
  EXPECT_EQ(encode_request(DownloadChunkRequest{8, data}).value(),
            (Bytes{0x63, 0x01, 0x08, 0xAA, 0xBB, 0xCC}));
  EXPECT_EQ(encode_request(DownloadCommitRequest{}).value(), (Bytes{0x64, 0x01}));
  EXPECT_EQ(encode_request(DownloadBreakRequest{}).value(), (Bytes{0x65, 0x01}));
}

TEST(ParameterTransferRequest, DecodeChecksLengthAndCode) {
  const Bytes begin{0x62, 0x01, 0x21, 0x3B, 0x12, 0x34, 0x56, 0x78};
  const auto r = decode_request(begin);
  ASSERT_TRUE(r);
  EXPECT_EQ(std::get<DownloadBeginRequest>(r.value()), (DownloadBeginRequest{8507, 0x12345678}));

  EXPECT_EQ(decode_request(Bytes{0x62, 0x01, 0x21}).error(), ProtocolError::kTruncated);
  EXPECT_EQ(decode_request(Bytes{0x60, 0x01, 0x00}).error(), ProtocolError::kTrailingBytes);
  EXPECT_EQ(decode_request(Bytes{0x61, 0x01}).error(), ProtocolError::kTruncated);
  EXPECT_EQ(decode_request(Bytes{0x63, 0x01, 0x00}).error(), ProtocolError::kBadAnswerValue);
  EXPECT_EQ(decode_request(Bytes{0x66, 0x01}).error(), ProtocolError::kBadCommandByte);
  EXPECT_EQ(decode_request(Bytes{}).error(), ProtocolError::kBadCommandByte);
  EXPECT_EQ(decode_request(Bytes{0x60, 0x00}).error(), ProtocolError::kBadOptionCount);

  Bytes big{0x63, 0x01, 0x00};
  big.resize(3 + kMaxChunkSize, 0x55);
  ASSERT_TRUE(decode_request(big));
  big.push_back(0x55);  // 1025 data bytes
  EXPECT_EQ(decode_request(big).error(), ProtocolError::kBadAnswerValue);
  EXPECT_EQ(encode_request(DownloadChunkRequest{0, std::span(big).subspan(3)}).error(),
            ProtocolError::kBadAnswerValue);
}

TEST(ParameterTransferAnswer, IdentifyAnswerFieldByField) {
  Identification id;
  id.device_type = 0x0004;
  id.serial_number = 0x00012345;
  id.firmware_major = 1;
  id.firmware_minor = 0;
  id.format_version = 1;
  id.set_size = 8507;
  id.chunk_size = 1024;
  id.set_crc32 = 0xDEADBEEF;
  id.flags = kFlagFactoryDefault;
  id.change_counter = 2;
  const TransferAnswer answer{TransferCode::kIdentify, measuring_pair1(), TransferStatus::kOk,
                              IdentifyAnswer{id}};
  const Bytes expected{
      0x60,                    // IDENTIFY
      0x0B,                    // option 1: three option bytes (11), state measuring (010)
      0x80,                    // option 2: no flag, option 3 follows (bit 7)
      0x81,                    // option 3: first pair 1, marker bit 7
      0x00,                    // status ok
      0x00, 0x04,              // device type
      0x00, 0x01, 0x23, 0x45,  // serial number
      0x01, 0x00,              // firmware 1.0
      0x01,                    // format version of the set encoding
      0x21, 0x3B,              // set size 8507
      0x04, 0x00,              // chunk size 1024
      0xDE, 0xAD, 0xBE, 0xEF,  // set CRC-32 (transfer form)
      0x01,                    // flags: factory default
      0x00, 0x02,              // change counter
  };
  EXPECT_EQ(encode_answer(answer).value(), expected);
  const auto back = decode_answer(expected);
  ASSERT_TRUE(back);
  EXPECT_EQ(back.value(), answer);
  EXPECT_EQ(id.chunk_count(), 9U);  // 8 × 1024 + 315
  EXPECT_TRUE(id.factory_default());

  Bytes cut(expected.begin(), expected.end() - 1);
  EXPECT_EQ(decode_answer(cut).error(), ProtocolError::kTruncated);
  Bytes reserved = expected;
  reserved[22] = 0x04;  // undefined flag bit
  EXPECT_EQ(decode_answer(reserved).error(), ProtocolError::kBadAnswerValue);
  Bytes zero_chunk = expected;
  zero_chunk[16] = 0;
  zero_chunk[17] = 0;
  EXPECT_EQ(decode_answer(zero_chunk).error(), ProtocolError::kBadAnswerValue);
}

TEST(ParameterTransferAnswer, UploadChunkAnswer) {
  const UploadChunkAnswer chunk{8, 9, 0x01020304, Bytes{0x10, 0x20}};
  const TransferAnswer answer{TransferCode::kUploadChunk, measuring_pair1(), TransferStatus::kOk,
                              chunk};
  const Bytes expected{
      0x61, 0x0B, 0x80, 0x81,  // UPLOAD_CHUNK, options
      0x00,                    // status ok
      0x08,                    // chunk 8
      0x09,                    // of 9
      0x00, 0x02,              // 2 data bytes
      0x01, 0x02, 0x03, 0x04,  // CRC-32 of the data
      0x10, 0x20,              // data
  };
  EXPECT_EQ(encode_answer(answer).value(), expected);
  EXPECT_EQ(decode_answer(expected).value(), answer);

  Bytes beyond = expected;
  beyond[5] = 9;  // chunk 9 of 9
  EXPECT_EQ(decode_answer(beyond).error(), ProtocolError::kBadAnswerValue);
  Bytes longer = expected;
  longer.push_back(0x30);
  EXPECT_EQ(decode_answer(longer).error(), ProtocolError::kTrailingBytes);
}

TEST(ParameterTransferAnswer, DownloadAnswers) {
  const auto opts = measuring_pair1();
  EXPECT_EQ(encode_answer({TransferCode::kDownloadBegin, opts, TransferStatus::kOk,
                           DownloadBeginAnswer{9, 1024}})
                .value(),
            (Bytes{0x62, 0x0B, 0x80, 0x81, 0x00, 0x09, 0x04, 0x00}));
  EXPECT_EQ(encode_answer({TransferCode::kDownloadChunk, opts, TransferStatus::kOk,
                           DownloadChunkAnswer{2, 0xCAFEBABE}})
                .value(),
            (Bytes{0x63, 0x0B, 0x80, 0x81, 0x00, 0x02, 0xCA, 0xFE, 0xBA, 0xBE}));
  EXPECT_EQ(encode_answer({TransferCode::kDownloadCommit, opts, TransferStatus::kOk,
                           DownloadCommitAnswer{0x0A0B0C0D}})
                .value(),
            (Bytes{0x64, 0x0B, 0x80, 0x81, 0x00, 0x0A, 0x0B, 0x0C, 0x0D}));
  EXPECT_EQ(encode_answer({TransferCode::kDownloadBreak, opts, TransferStatus::kOk,
                           DownloadBreakAnswer{kFlagFactoryDefault}})
                .value(),
            (Bytes{0x65, 0x0B, 0x80, 0x81, 0x00, 0x01}));
}

TEST(ParameterTransferAnswer, RefusalCarriesTheStatusAlone) {
  OptionBytes init;
  init.state = Option1State::kInitialisation;
  const TransferAnswer refused{TransferCode::kDownloadCommit, init, TransferStatus::kCrcMismatch,
                               std::nullopt};
  const Bytes expected{
      0x64,  // DOWNLOAD_COMMIT
      0x05,  // option 1: one option byte, state initialisation (001)
      0x05,  // status 5: CRC-32 mismatch (ERROR_NUMBER_RS4)
  };
  EXPECT_EQ(encode_answer(refused).value(), expected);
  EXPECT_EQ(decode_answer(expected).value(), refused);
  EXPECT_EQ(decode_answer(Bytes{0x64, 0x05, 0x0A}).error(), ProtocolError::kBadAnswerValue);
  EXPECT_EQ(decode_answer(Bytes{0x64, 0x05, 0x05, 0x00}).error(), ProtocolError::kTrailingBytes);
  // A kOk answer without a body, or with the body of another command, is refused.
  EXPECT_EQ(
      encode_answer({TransferCode::kIdentify, init, TransferStatus::kOk, std::nullopt}).error(),
      ProtocolError::kBadAnswerValue);
  EXPECT_EQ(
      encode_answer({TransferCode::kIdentify, init, TransferStatus::kOk, DownloadBreakAnswer{}})
          .error(),
      ProtocolError::kBadAnswerValue);
  EXPECT_EQ(decode_answer(Bytes{0x53, 0x05, 0x00}).error(), ProtocolError::kBadAnswerCode);
}

TEST(ProxyAdapterCommands, BeginAndEndBytes) {
  EXPECT_EQ(encode_command(ProxyBeginCommand{}), Bytes{0x98});
  EXPECT_EQ(encode_command(ProxyEndCommand{ProxyOutcome::kFailed, 0x2B13}),
            (Bytes{
                0x99,        // PROFI_CMD_PROXY_END
                0x01,        // outcome: failed
                0x2B, 0x13,  // adapter error 0x2B13: echo CRC of chunk 3 wrong
            }));
  const auto begin = parse_write_command(Bytes{0x98});
  ASSERT_TRUE(begin);
  EXPECT_TRUE(std::holds_alternative<ProxyBeginCommand>(begin.value()));
  const auto end = parse_write_command(Bytes{0x99, 0x00, 0x00, 0x00});
  ASSERT_TRUE(end);
  EXPECT_EQ(std::get<ProxyEndCommand>(end.value()), (ProxyEndCommand{}));
}

TEST(ProxyAdapterCommands, BadEndCommandsAreRejectedAsTable5_2_3) {
  auto rejected = [](const Bytes& payload) {
    const auto r = parse_write_command(payload);
    EXPECT_TRUE(r && std::holds_alternative<RejectedCommand>(r.value()));
    return r ? std::get<RejectedCommand>(r.value()) : RejectedCommand{};
  };
  EXPECT_EQ(rejected({0x98, 0x00}), (RejectedCommand{CommandErrorKind::kWrongLength, 0x98}));
  EXPECT_EQ(rejected({0x99, 0x00, 0x00}), (RejectedCommand{CommandErrorKind::kWrongLength, 0x99}));
  // success with an error number, failure with an error that is not a proxy error, outcome 2
  EXPECT_EQ(rejected({0x99, 0x00, 0x2B, 0x09}),
            (RejectedCommand{CommandErrorKind::kWrongParameter, 0x99}));
  EXPECT_EQ(rejected({0x99, 0x01, 0x2A, 0x06}),
            (RejectedCommand{CommandErrorKind::kWrongParameter, 0x99}));
  EXPECT_EQ(rejected({0x99, 0x02, 0x00, 0x00}),
            (RejectedCommand{CommandErrorKind::kWrongParameter, 0x99}));
  for (const unsigned ok : {0x0000U, 0x2B01U, 0x2B09U, 0x2B10U, 0x2B1FU, 0x2B20U, 0x2B2FU}) {
    EXPECT_TRUE(is_proxy_end_error(static_cast<std::uint16_t>(ok))) << ok;
  }
  for (const unsigned bad : {0x2B00U, 0x2B02U, 0x2B30U, 0x2A05U, 0x2419U}) {
    EXPECT_FALSE(is_proxy_end_error(static_cast<std::uint16_t>(bad))) << bad;
  }
}

TEST(ProxyAdapterAnswers, BeginAndEndAnswers) {
  const ProxyBeginAnswer begin{SyncReason::kPcAdapterRemoved, SyncDirection::kUpload, false};
  const Bytes begin_bytes{
      0x98,  // answer to PROFI_CMD_PROXY_BEGIN
      0x02,  // reason: PC adapter removed
      0x02,  // direction: upload (device → proxy)
      0x00,  // flags: not at factory settings
  };
  EXPECT_EQ(encode_proxy_begin_answer(begin), begin_bytes);
  EXPECT_EQ(decode_proxy_begin_answer(begin_bytes).value(), begin);
  EXPECT_EQ(decode_proxy_begin_answer(Bytes{0x98, 0x00, 0x00, 0x01}).value(),
            (ProxyBeginAnswer{SyncReason::kNone, SyncDirection::kNone, true}));
  EXPECT_EQ(decode_proxy_begin_answer(Bytes{0x98, 0x01, 0x00, 0x00}).error(),
            ProtocolError::kBadAnswerValue);  // a reason without a direction
  EXPECT_EQ(decode_proxy_begin_answer(Bytes{0x98, 0x04, 0x02, 0x00}).value(),
            (ProxyBeginAnswer{SyncReason::kUserParametrisation, SyncDirection::kUpload, false}));
  EXPECT_EQ(decode_proxy_begin_answer(Bytes{0x98, 0x05, 0x01, 0x00}).error(),
            ProtocolError::kBadAnswerValue);  // reason 5 is not defined
  EXPECT_EQ(decode_proxy_begin_answer(Bytes{0x98, 0x01, 0x01}).error(),
            ProtocolError::kBadAnswerLength);
  EXPECT_EQ(decode_proxy_begin_answer(Bytes{0x99, 0x01, 0x01, 0x00}).error(),
            ProtocolError::kBadAnswerCode);

  EXPECT_EQ(encode_proxy_end_answer({true, true}), (Bytes{0x99, 0x01, 0x01}));
  EXPECT_EQ(decode_proxy_end_answer(Bytes{0x99, 0x00, 0x00}).value(), (ProxyEndAnswer{}));
  EXPECT_EQ(decode_proxy_end_answer(Bytes{0x99, 0x02, 0x00}).error(),
            ProtocolError::kBadAnswerValue);
}

}  // namespace
}  // namespace rs4sim::rs4::protocol
