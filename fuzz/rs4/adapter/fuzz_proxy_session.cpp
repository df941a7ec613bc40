// fuzz_proxy_session: arbitrary sequences of the proxy's transfer commands 0x60..0x65
// ([docs/proxy-protocol.md]) against the device-side ProxySession and a running scanner:
// raw command bytes, well-formed downloads of mutated sets (some chunks corrupted, out of
// order or missing), sync start/stop, time and power. Invariants: no crash; every answer
// decodes with the master's decoder, answers the command it got and stays < 1100 bytes; a
// download command succeeds only inside a sync; the RS4's set always validates and keeps
// its identity and passwords; the set changes only by a successful COMMIT or BREAK, and a
// COMMIT reports the CRC of the set then active.
#include "rs4/adapter/proxy_session.h"
#include "rs4/scanner/crc32.h"
#include "rs4/scanner/parameter_codec.h"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <span>
#include <vector>

namespace {

using namespace rs4sim::rs4;
using namespace std::chrono_literals;
using Bytes = std::vector<std::uint8_t>;

void check(bool ok) {
  if (!ok) __builtin_trap();
}

struct Input {
  std::span<const std::uint8_t> d;
  std::size_t i = 0;
  bool empty() const { return i >= d.size(); }
  std::uint8_t byte() { return empty() ? 0 : d[i++]; }
};

scanner::ParameterSet device_set() {
  auto s = scanner::factory_default();
  s.passwords[1] = {'P', 'W', 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF};
  return s;
}

// A set the proxy might hold: the factory set with a few fields from the input (some of
// them invalid on purpose).
Bytes stored_blob(Input& in) {
  auto s = scanner::factory_default();
  s.response_steps = static_cast<std::uint8_t>(in.byte() % 16);
  s.start_pair = static_cast<std::uint8_t>(in.byte() % 6);
  const auto seg = static_cast<std::size_t>(in.byte()) * 2 % scanner::kSegmentCount;
  s.pairs[in.byte() % 4].protective_mm[seg] = static_cast<std::uint16_t>(in.byte() * 20);
  return scanner::encode_for_transfer(s);
}

Bytes with_header(protocol::TransferCode code, Bytes fields) {
  Bytes out{static_cast<std::uint8_t>(code), protocol::kRequestOption1};
  out.insert(out.end(), fields.begin(), fields.end());
  return out;
}

scanner::ScannerConfig fast_boot() {
  scanner::ScannerConfig c;
  c.boot_duration = 100ms;
  return c;
}

struct Harness {
  scanner::Scanner rs4{fast_boot()};
  adapter::ProxySession session;
  scanner::TimePoint now{};
  Bytes blob;  // the set being downloaded by the well-formed path

  Harness() {
    (void)rs4.set_parameters(device_set(), now);
    rs4.power_on(now);
    now += 100ms;
    rs4.advance(now);
  }

  void send(const Bytes& command) {
    const bool running = session.running();
    const auto counter = rs4.change_counter();
    const auto answer = session.answer(command, rs4, now);
    check(answer.size() < 1100);
    const auto decoded = protocol::decode_answer(answer);
    check(static_cast<bool>(decoded));
    const auto& a = decoded.value();
    check(static_cast<std::uint8_t>(a.code) == command[0]);
    const bool ok = a.status == protocol::TransferStatus::kOk;
    const bool download = command[0] >= 0x62;
    if (ok && download) check(running);
    const bool writes = ok && (a.code == protocol::TransferCode::kDownloadCommit ||
                               a.code == protocol::TransferCode::kDownloadBreak);
    if (!writes) check(rs4.change_counter() == counter);
    if (ok && a.code == protocol::TransferCode::kDownloadCommit) {
      check(std::get<protocol::DownloadCommitAnswer>(*a.body).active_crc32 ==
            rs4.transfer_checksum());
    }
    check(!scanner::validate(rs4.parameters()).has_value());
    // [RS4 manual §7.1.2]: in configuration (OSSDs off) exactly while a download is open.
    if (rs4.status().state == scanner::ScannerState::kConfiguration) {
      check(session.download_open() && !rs4.ossd());
    }
    check(rs4.parameters().passwords == device_set().passwords);
    check(rs4.parameters().identity == scanner::ScannerConfig{}.identity);
  }

  void raw(Input& in) {
    Bytes cmd{static_cast<std::uint8_t>(0x60 + in.byte() % 6)};
    const std::size_t n = in.byte() % 8 == 0 ? 1030 : in.byte() % 12;
    for (std::size_t k = 0; k < n && !in.empty(); ++k) cmd.push_back(in.byte());
    send(cmd);
  }

  void begin(Input& in) {
    blob = stored_blob(in);
    auto crc = scanner::crc32_iso_hdlc(blob);
    if (in.byte() % 8 == 0) crc ^= 1U;
    auto size = static_cast<std::uint16_t>(blob.size());
    if (in.byte() % 16 == 0) --size;
    send(with_header(protocol::TransferCode::kDownloadBegin,
                     {static_cast<std::uint8_t>(size >> 8), static_cast<std::uint8_t>(size),
                      static_cast<std::uint8_t>(crc >> 24), static_cast<std::uint8_t>(crc >> 16),
                      static_cast<std::uint8_t>(crc >> 8), static_cast<std::uint8_t>(crc)}));
  }

  // Chunk x of the stored blob (sometimes with one byte flipped).
  void chunk(Input& in) {
    if (blob.empty()) blob = stored_blob(in);
    const std::uint8_t x = in.byte() % 10;
    const std::size_t off = std::size_t{x} * protocol::kMaxChunkSize;
    if (off >= blob.size())
      return send(with_header(protocol::TransferCode::kDownloadChunk, {x, 0}));
    const auto n = std::min(protocol::kMaxChunkSize, blob.size() - off);
    Bytes fields{x};
    fields.insert(fields.end(), blob.begin() + static_cast<std::ptrdiff_t>(off),
                  blob.begin() + static_cast<std::ptrdiff_t>(off + n));
    if (in.byte() % 16 == 0) fields[1 + in.byte() % n] ^= 0x40;
    send(with_header(protocol::TransferCode::kDownloadChunk, std::move(fields)));
  }

  // All chunks in order and the commit: reaches the apply path.
  void whole_download(Input& in) {
    begin(in);
    for (std::uint8_t x = 0; std::size_t{x} * protocol::kMaxChunkSize < blob.size(); ++x) {
      const std::size_t off = std::size_t{x} * protocol::kMaxChunkSize;
      const auto n = std::min(protocol::kMaxChunkSize, blob.size() - off);
      Bytes fields{x};
      fields.insert(fields.end(), blob.begin() + static_cast<std::ptrdiff_t>(off),
                    blob.begin() + static_cast<std::ptrdiff_t>(off + n));
      send(with_header(protocol::TransferCode::kDownloadChunk, std::move(fields)));
    }
    send(with_header(protocol::TransferCode::kDownloadCommit, {}));
  }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Input in{std::span<const std::uint8_t>(data, size)};
  Harness h;
  for (unsigned steps = 0; steps < 64 && !in.empty(); ++steps) {
    switch (in.byte() % 10) {
      case 0: h.session.request(static_cast<protocol::SyncReason>(in.byte() % 5)); break;
      case 1: h.session.start(h.rs4, h.now); break;
      case 2: h.session.stop(h.rs4, h.now); break;
      case 3: h.raw(in); break;
      case 4: h.begin(in); break;
      case 5: h.chunk(in); break;
      case 6: h.send(with_header(protocol::TransferCode::kDownloadCommit, {})); break;
      case 7: h.whole_download(in); break;
      case 8:
        h.send(with_header(in.byte() % 2 == 0 ? protocol::TransferCode::kIdentify
                                              : protocol::TransferCode::kDownloadBreak,
                           {}));
        break;
      default:
        h.now += std::chrono::milliseconds(in.byte() * 4);
        if (in.byte() % 8 == 0) h.rs4.power_cycle(h.now);
        h.rs4.advance(h.now);
        break;
    }
  }
  return 0;
}
