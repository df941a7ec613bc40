#pragma once
// ProxySync: the Proxy-FB's job for one slave ([RS4 manual §6.4, §6.5, §7.1, §7.2]) as a
// sans-I/O machine (docs/proxy.md). Inputs: the PROFIsafe-unwrapped input byte (bit 2
// Proxy-Request, [RS4 manual §5.1.1]), Proxy-Enable, the results of the DPV1 records it asked
// for, and the time. Outputs: RecordRequests (one outstanding at a time) and the FB outputs.
// The exchange it runs is the contract of docs/proxy-protocol.md: 98 PROXY_BEGIN, IDENTIFY,
// upload or download, 99 PROXY_END. The parameter archive keeps the sets.

#include "dp/time/clock.h"
#include "proxy/exchange.h"
#include "proxy/positions.h"
#include "proxy/record.h"
#include "proxy/retentive.h"
#include "rs4/protocol/adapter_answer.h"
#include "rs4/protocol/parameter_transfer.h"
#include "storage/parameter_archive.h"

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace rs4sim::proxy {

inline constexpr std::uint8_t kProxyRequestBit = 0x04;  // input byte bit 2 ([RS4 manual §5.1.1])
inline constexpr std::uint8_t kRs232ActiveBit = 0x08;   // input byte bit 3 ([RS4 manual §5.1.1])

// What the proxy records with every version it stores (docs/storage.md "What maintenance
// records"): who runs it and where, the station's site and line, and whether an upload of the
// set already current is stored again. The comment of each version names the scenario.
struct Recording {
  storage::Author author;
  std::string site;
  std::string line;
  bool skip_identical = false;
};

using WallClock = std::function<storage::Timestamp()>;

struct ProxySyncConfig {
  storage::StationKey station;
  Recording recording{};
  ExchangeTiming timing;
  // DECISION (docs/proxy.md "Failures"): after a failed sync the next one starts no earlier
  // than this, so a persistent fault does not loop hot.
  dp::Duration retry_delay = std::chrono::seconds(5);
  bool background_verify = true;  // upload after an immediate release and compare
  // The archive's timestamps (docs/storage.md "Times"): the wall clock the owner injects (the
  // machine reads none), read at each write, so a stored time is never later than the moment
  // it was written. Without one: the run's own time from the Unix epoch (tests).
  WallClock wall_clock{};
  // The run's time is a simulation's (`rs4sim demo`, `master --link memory`): recorded beside
  // each version (StoreRequest::simulated). A real link's steady clock is not.
  bool simulated = false;
};

// The archive timestamp of a write at machine time `now`.
storage::Timestamp wall_time(const ProxySyncConfig& config, dp::TimePoint now);

// The FB outputs ([RS4 manual §6.4]).
struct FbOutputs {
  bool fb_busy = false;
  bool config_set_to_default = false;
  std::uint16_t error_number_fb = 0;   // 0xPPKK (positions.h)
  std::uint16_t error_code_sfc = 0;    // record.h RecordResult::sfc
  std::uint16_t error_number_rs4 = 0;  // TransferStatus, or the number of an RS4 0x53 telegram
  friend bool operator==(const FbOutputs&, const FbOutputs&) = default;
};

struct SyncProgress {
  Step step = Step::kIdle;
  std::uint8_t position = 0;  // the step's main position (write, else copy)
  std::size_t bytes_done = 0;
  std::size_t bytes_total = 0;
  rs4::protocol::SyncDirection direction = rs4::protocol::SyncDirection::kNone;
  friend bool operator==(const SyncProgress&, const SyncProgress&) = default;
};

class ProxySync {
 public:
  ProxySync(ProxySyncConfig config, storage::ParameterArchive& archive);

  // ---- inputs
  // Bit 2 Proxy-Request; bit 3 "RS232 aktiv": while the PC adapter is attached no sync starts
  // ([RS4 manual §6.5] "Es findet keine Kommunikation statt, solange der optische PC-Adapter am
  // RS4/PROFIsafe angebracht ist").
  void set_input_byte(std::uint8_t byte) noexcept {
    request_ = (byte & kProxyRequestBit) != 0;
    pc_adapter_ = (byte & kRs232ActiveBit) != 0;
  }
  // The FB runs only when enabled; a running sync is finished (docs/proxy.md).
  void set_proxy_enable(bool enabled) noexcept { enabled_ = enabled; }
  void on_record_result(const RecordResult& result, dp::TimePoint now);
  void tick(dp::TimePoint now);

  // True when the machine wants the bus: a Proxy-Request while enabled and idle (and the
  // retry delay over), or the safe abort after restore(). The scheduler then calls start().
  [[nodiscard]] bool ready(dp::TimePoint now) const noexcept;
  void start(dp::TimePoint now);
  // Running: a sync, its failure report or the background verify.
  [[nodiscard]] bool active() const noexcept;

  // ---- outputs
  std::optional<RecordRequest> take_request(dp::TimePoint now);
  [[nodiscard]] std::optional<dp::TimePoint> next_wakeup() const noexcept;
  [[nodiscard]] const FbOutputs& outputs() const noexcept { return out_; }
  [[nodiscard]] SyncProgress progress() const noexcept;
  [[nodiscard]] const storage::StationKey& station() const noexcept { return config_.station; }
  [[nodiscard]] const ProxySyncConfig& config() const noexcept { return config_; }

  // ---- retentive state (retentive.h)
  [[nodiscard]] RetentiveRecord snapshot() const noexcept;
  // After a restart: a sync that was open on the device is failed safely (99 failed, so the
  // device falls back to factory settings and asks again) as soon as start() is called.
  void restore(const RetentiveRecord& record) noexcept;

 private:
  using Identification = rs4::protocol::Identification;

  // proxy_sync.cpp
  void begin_exchange(Step step, std::vector<std::uint8_t> command, dp::TimePoint now);
  void exchange_finished(dp::TimePoint now);
  void fail(FailureKind kind, dp::TimePoint now, std::uint16_t adapter_error = 0,
            std::uint16_t rs4 = 0);
  void report_failure(dp::TimePoint now);
  void finish(storage::SyncOutcome outcome, dp::TimePoint now);
  void log_sync(storage::SyncOutcome outcome, dp::TimePoint now);

  // proxy_sync_steps.cpp
  void on_answer(std::span<const std::uint8_t> answer, dp::TimePoint now);
  void load_current(dp::TimePoint now);
  bool load_known_serial();
  void on_begin(std::span<const std::uint8_t> answer, dp::TimePoint now);
  void on_identify(std::span<const std::uint8_t> answer, dp::TimePoint now);
  void decide(dp::TimePoint now);
  void start_upload(bool background, dp::TimePoint now);
  void request_chunk(dp::TimePoint now);
  void on_upload(std::span<const std::uint8_t> answer, dp::TimePoint now);
  void upload_complete(dp::TimePoint now);
  bool store_set(storage::VersionSource source, std::string summary, std::string note,
                 dp::TimePoint now);
  // The comment of the version an upload stores: the scenario that made it.
  [[nodiscard]] std::string upload_note() const;
  void start_download(dp::TimePoint now);
  void send_download_chunk(dp::TimePoint now);
  void on_download(std::span<const std::uint8_t> answer, dp::TimePoint now);
  void store_serial(dp::TimePoint now);
  void send_end(dp::TimePoint now);
  void on_end(std::span<const std::uint8_t> answer, dp::TimePoint now);
  std::optional<rs4::protocol::TransferAnswer> transfer_answer(std::span<const std::uint8_t> answer,
                                                               rs4::protocol::TransferCode code,
                                                               dp::TimePoint now);

  ProxySyncConfig config_;
  storage::ParameterArchive& archive_;
  bool request_ = false;
  bool enabled_ = false;

  Step step_ = Step::kIdle;
  Exchange exchange_;
  FbOutputs out_;
  dp::TimePoint retry_until_{};
  dp::TimePoint started_at_{};
  bool abort_pending_ = false;     // restore() found an open sync
  Step abort_step_ = Step::kIdle;  // the step it was in

  // The sync's facts.
  rs4::protocol::ProxyBeginAnswer begin_;
  std::optional<Identification> ident_;  // agreed by both reads
  std::optional<Identification> first_;  // the first read of a repeated IDENTIFY
  std::optional<storage::VersionWithSet> current_;
  std::string known_serial_;       // the serial number the archive last saw on this station
  std::vector<std::uint8_t> set_;  // uploaded so far / to download
  std::uint32_t set_crc_ = 0;
  std::optional<storage::VersionId> restore_version_;  // pending restore being downloaded
  std::vector<std::uint8_t> first_chunk_;              // first read of a repeated UPLOAD_CHUNK
  std::size_t chunk_ = 0;
  std::size_t chunk_count_ = 0;
  std::size_t chunk_size_ = 0;
  bool sync_open_ = false;
  bool pc_adapter_ = false;  // input bit 3: the PC adapter is switched through
  bool download_open_ = false;
  bool downloaded_ = false;
  bool verify_after_end_ = false;
  bool background_ = false;          // the upload is the background verify
  // What the sync does, once decide() chose (the sync log's direction says what happened, not
  // what the RS4 asked: a first commissioning with nothing stored transfers nothing).
  std::optional<storage::SyncDirection> transfer_;
  std::uint16_t adapter_error_ = 0;  // sent in 99 failed
};

}  // namespace rs4sim::proxy
