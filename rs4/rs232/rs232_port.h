#pragma once
// The RS4's own RS232 interface behind the optical PC adapter, live ([docs/rs232.md]):
// a stream::ByteDevice beside the PROFIBUS station of the same RS4, sharing its
// rs4::adapter::Adapter (and so its Scanner).
//
//   bytes in → protocol::Rs232Deframer → command interpreter (rs232_interpreter.cpp)
//            → answers framed with protocol::frame_rs232 → take_transmit()
//   scans    → continuous 0x23 at the scan rate (40 ms), 0x53/0x54 as the RS4 emits them
//
// Reachability ([RS4 manual §7.1, §7.2], [RS4 manual §5.1.1] bit 3): attach()/detach() are the
// PC adapter's reed contact and go through Adapter::attach_pc_adapter/detach_pc_adapter, so the
// PROFIBUS side shows exactly the switched-through bit and the Proxy-Request on removal. The port
// answers only while the adapter reports the interface switched through; otherwise it is silent
// and drops what it hears (nothing is behind the optical window).
//
// Sans-I/O: time comes in through on_bytes/on_time; the port calls Adapter::on_time(now) before
// it reads the scanner, which is idempotent for the adapter's own deadlines.

#include "rs4/adapter/adapter.h"
#include "rs4/adapter/proxy_session.h"
#include "rs4/protocol/rs232.h"
#include "rs4/rs232/port_options.h"
#include "stream/byte_device.h"

#include <cstdint>
#include <deque>
#include <optional>
#include <span>
#include <vector>

namespace rs4sim::rs4::rs232 {

struct PortCounters {
  std::uint64_t commands = 0;                // well-framed commands interpreted
  std::uint64_t acks = 0, naks = 0;          // 0x16 / 0x17 sent
  std::uint64_t error_telegrams = 0;         // 0x53 sent for a refused command
  std::uint64_t wrong_passwords = 0;         // protected commands refused for the password
  std::uint64_t framing_errors = 0;          // bad check, stuffing, short, oversized: silence
  std::uint64_t ignored_while_detached = 0;  // bytes heard while not switched through
  std::uint64_t measurements = 0;            // 0x23 sent (stream and on request)
  std::uint64_t scans_skipped_busy = 0;      // stream scans skipped: the line still busy
  std::uint64_t events = 0;                  // 0x53/0x54 of the RS4 sent
  std::uint64_t baud_changes = 0;
};

class Rs232Port final : public stream::ByteDevice {
 public:
  // `adapter` must outlive the port; the port installs the adapter's event listener.
  Rs232Port(adapter::Adapter& adapter, const PortOptions& options = {});
  ~Rs232Port() override;
  Rs232Port(const Rs232Port&) = delete;
  Rs232Port& operator=(const Rs232Port&) = delete;

  // ---- the PC adapter ([RS4 manual §7.1, §7.2]) ---------------------------------------------
  void attach(stream::TimePoint now);
  void detach(stream::TimePoint now);
  [[nodiscard]] bool attached() const noexcept { return attached_; }
  // Attached and switched through (no sync running, RS4 powered): the port answers.
  [[nodiscard]] bool reachable() const noexcept;
  [[nodiscard]] bool streaming() const noexcept { return streaming_; }

  // ---- stream::ByteDevice --------------------------------------------------------------------
  [[nodiscard]] stream::LineSettings line_settings() const override { return line_; }
  void on_bytes(std::span<const std::uint8_t> bytes, stream::TimePoint now) override;
  void on_time(stream::TimePoint now) override;
  [[nodiscard]] std::optional<stream::TimePoint> next_deadline() const override;
  std::optional<std::vector<std::uint8_t>> take_transmit() override;

  [[nodiscard]] const PortCounters& counters() const noexcept { return counters_; }
  [[nodiscard]] const protocol::DeframerCounters& deframer_counters() const noexcept {
    return deframer_.counters();
  }

 private:
  // rs232_port.cpp: line, stream, transmit
  void sync_adapter(stream::TimePoint now);
  void stream_scan(stream::TimePoint now);
  void send(std::vector<std::uint8_t> body, stream::TimePoint now);
  void on_rs4_event(const scanner::Rs4Event& e);
  void close_session(stream::TimePoint now);
  // rs232_interpreter.cpp: one command
  void interpret(std::span<const std::uint8_t> body, stream::TimePoint now);
  struct Verdict {  // what a command did: nothing to add, or refused with an error number
    std::uint16_t error = 0;
    std::uint16_t parameter = 0;
  };
  Verdict execute(std::uint8_t code, std::span<const std::uint8_t> data,
                  std::span<const std::uint8_t> body, stream::TimePoint now);
  Verdict set_baud(std::span<const std::uint8_t> data, stream::TimePoint now);
  [[nodiscard]] bool password_ok(const protocol::TelegramPrefix& prefix) const;
  void refuse(std::uint8_t code, bool acknowledge, const Verdict& v, stream::TimePoint now);
  void acknowledge(std::uint8_t code, stream::TimePoint now);

  adapter::Adapter& adapter_;
  PortOptions options_;
  stream::LineSettings line_;
  protocol::Rs232Deframer deframer_;
  adapter::ProxySession session_;  // the parameter-set commands 0x60..0x65 (shared handlers)
  bool attached_ = false;
  bool streaming_ = false;
  bool open_ = false;                                 // reachable as seen at the last call
  std::optional<std::uint32_t> streamed_scan_;        // scan number sent last by the stream
  std::optional<stream::LineSettings> pending_line_;  // after the acknowledgement went out
  stream::TimePoint pending_line_at_{};
  stream::TimePoint line_busy_until_{};  // when the frames queued so far leave the wire
  std::deque<std::vector<std::uint8_t>> transmit_;
  std::optional<std::vector<std::uint8_t>> answer_;     // of the command being executed
  std::vector<protocol::Rs232Deframer::Event> events_;  // scratch
  stream::TimePoint now_{};  // time of the call in progress (for the event listener)
  bool in_call_ = false;     // inside on_bytes/on_time: the link drains afterwards anyway
  PortCounters counters_;
};

}  // namespace rs4sim::rs4::rs232
