#pragma once
// Helpers for the proxy sync tests on the adapter rig: multi-block commands through the real
// block protocol ([RS4 manual §5.2.1]) and the transfer requests of [docs/proxy-protocol.md].
#include "adapter_rig.h"
#include "rs4/protocol/parameter_transfer.h"

#include <algorithm>

namespace rs4sim::rs4::adapter::testing {

// WRITE `payload` in blocks of ≤ 236 bytes (numbered 0, 1, …, the last one 0xFFFF), then READ
// the whole answer.
inline Bytes command(Rig& rig, const Bytes& payload,
                     dp::slave::AcyclicChannel ch = dp::slave::AcyclicChannel::kC1) {
  std::size_t offset = 0;
  std::uint16_t number = 0;
  while (true) {
    const std::size_t n =
        std::min<std::size_t>(protocol::kMaxBlockPayload, payload.size() - offset);
    const bool last = offset + n == payload.size();
    const Bytes part(payload.begin() + static_cast<std::ptrdiff_t>(offset),
                     payload.begin() + static_cast<std::ptrdiff_t>(offset + n));
    rig.write(Rig::block(part, last ? protocol::kLastBlockNumber : number++), 2, ch);
    offset += n;
    if (last) break;
  }
  return rig.read_answer(240, ch);
}

inline Bytes request(const protocol::TransferRequest& r) {
  auto bytes = protocol::encode_request(r);
  EXPECT_TRUE(bytes);
  return bytes ? bytes.value() : Bytes{};
}

// Sends a transfer request and decodes the answer (the master's decoder).
inline protocol::TransferAnswer transfer(Rig& rig, const protocol::TransferRequest& r) {
  const auto answer = protocol::decode_answer(command(rig, request(r)));
  EXPECT_TRUE(answer) << answer.error().message();
  return answer ? answer.value() : protocol::TransferAnswer{};
}

// DOWNLOAD_BEGIN, every chunk in order, DOWNLOAD_COMMIT: the commit answer.
inline protocol::TransferAnswer download(Rig& rig, const Bytes& blob, std::uint32_t crc) {
  const auto begin =
      transfer(rig, protocol::DownloadBeginRequest{static_cast<std::uint16_t>(blob.size()), crc});
  EXPECT_EQ(begin.status, protocol::TransferStatus::kOk);
  for (std::size_t x = 0; x * protocol::kMaxChunkSize < blob.size(); ++x) {
    const std::size_t off = x * protocol::kMaxChunkSize;
    const std::size_t n = std::min(protocol::kMaxChunkSize, blob.size() - off);
    const auto a = transfer(
        rig, protocol::DownloadChunkRequest{static_cast<std::uint8_t>(x),
                                            std::span<const std::uint8_t>(blob).subspan(off, n)});
    EXPECT_EQ(a.status, protocol::TransferStatus::kOk) << "chunk " << x;
  }
  return transfer(rig, protocol::DownloadCommitRequest{});
}

// The adapter rig in data exchange with the RS4 booted (Proxy-Request set), Proxy-Enable 1.
inline void boot_with_proxy(Rig& rig) {
  rig.out_byte = kOutputProxyEnable | 0x01;
  rig.start();
  rig.run(31s);
}

}  // namespace rs4sim::rs4::adapter::testing
