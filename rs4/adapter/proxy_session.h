#pragma once
// The device side of the proxy's parameter transfer — EXTENSION ([docs/proxy-protocol.md],
// [RS4 manual §7.1, §7.2]): why the adapter asks for a sync, the direction the device
// wants, and the RS4's answers to the transfer commands 0x60..0x65 (identify, upload in
// chunks, download begin/chunk/commit/break).
//
// A plain state holder beside the Adapter (which owns the flags of [RS4 manual §5.1.1]
// bit 2 and the OSSD release): the Adapter tells it when a sync starts and ends, and
// routes every transfer command here. Sans-I/O: the scanner and `now` come in.
//
// Download rules: only while a sync runs or with an accepted password (kNoSyncRunning
// otherwise, [docs/decisions.md#rs4-parametrisation-over-profibus]); DOWNLOAD_BEGIN with
// the device's set size; chunks strictly in order 0..n-1, each of the chunk size (the last
// one shorter); COMMIT checks size and whole CRC-32, decodes, merges with the device's
// set (passwords and identity kept, scanner::merge_download), validates and applies it.
// The RS4 is in its configuration mode for the whole download, not only at the commit:
// DOWNLOAD_BEGIN enters it (OSSDs off, option 1 state 011, input bit 4 "RS4-
// Parametrierzustand", [RS4 manual §7.1.2] "schaltet das OSSD-Signal während eines Downloads
// … aus", [RS4 manual §5.1.1]), COMMIT, a refused COMMIT and stop() leave it (start
// interlock as at every start), BREAK leaves it at factory settings. Any refusal leaves the
// RS4's set unchanged.

#include "rs4/protocol/adapter_answer.h"
#include "rs4/protocol/parameter_transfer.h"
#include "rs4/scanner/scanner.h"

#include <cstdint>
#include <span>
#include <vector>

namespace rs4sim::rs4::adapter {

class ProxySession {
 public:
  // Nothing running, no reason remembered (power-off / power-on).
  void reset() noexcept;
  // Why the adapter sets Proxy-Request; reported by the next PROFI_CMD_PROXY_BEGIN.
  void request(protocol::SyncReason why) noexcept { reason_ = why; }
  // The sync starts: the device decides the direction ([docs/proxy-protocol.md] step 2); a
  // user's download still open is discarded (the RS4 leaves configuration).
  void start(scanner::Scanner& rs4, scanner::TimePoint now);
  // The sync is over (END, abort, link loss): an open download is discarded and the RS4
  // leaves its configuration mode with its set unchanged.
  void stop(scanner::Scanner& rs4, scanner::TimePoint now);

  [[nodiscard]] bool running() const noexcept { return running_; }
  [[nodiscard]] protocol::SyncReason reason() const noexcept { return reason_; }
  [[nodiscard]] protocol::SyncDirection direction() const noexcept { return direction_; }
  [[nodiscard]] bool download_open() const noexcept { return download_.open; }

  // The RS4's answer body to one transfer command (CMD 0x60..0x65 first), with the RS4's
  // option bytes ([RS4 manual §5.2.3]). A malformed request is answered with a status.
  // Downloads only while running(), or `authorised` (the command carried a password the RS4
  // accepted: a user's parametrisation, [RS4 manual §5.1.1] bit 4 "Der RS4 kann sowohl über
  // den PROFIBUS … als auch über die PC-Schnittstelle … parametriert werden").
  std::vector<std::uint8_t> answer(std::span<const std::uint8_t> command, scanner::Scanner& rs4,
                                   scanner::TimePoint now, bool authorised = false);

 private:
  struct Download {
    bool open = false;
    std::uint16_t size = 0;
    std::uint32_t crc32 = 0;
    std::uint8_t next_chunk = 0;
    std::vector<std::uint8_t> bytes;
  };
  using Answer = protocol::TransferAnswer;

  // proxy_transfer.cpp: one handler per command.
  Answer identify(const scanner::Scanner& rs4) const;
  static Answer upload_chunk(const protocol::UploadChunkRequest& r, const scanner::Scanner& rs4);
  Answer download_begin(const protocol::DownloadBeginRequest& r, scanner::Scanner& rs4,
                        scanner::TimePoint now);
  // Ends an open download: the RS4 leaves configuration (set unchanged).
  void close_download(scanner::Scanner& rs4, scanner::TimePoint now);
  Answer download_chunk(const protocol::DownloadChunkRequest& r);
  Answer download_commit(scanner::Scanner& rs4, scanner::TimePoint now);
  Answer download_break(scanner::Scanner& rs4, scanner::TimePoint now);
  Answer dispatch(const protocol::TransferRequest& request, scanner::Scanner& rs4,
                  scanner::TimePoint now, bool authorised);

  bool running_ = false;
  protocol::SyncReason reason_ = protocol::SyncReason::kNone;
  protocol::SyncDirection direction_ = protocol::SyncDirection::kNone;
  Download download_;
};

// The direction a device in this state wants ([docs/proxy-protocol.md] step 2): after the
// PC adapter was removed → upload; at factory settings → download; otherwise → verify.
[[nodiscard]] protocol::SyncDirection sync_direction(protocol::SyncReason why,
                                                     bool factory_settings) noexcept;

}  // namespace rs4sim::rs4::adapter
