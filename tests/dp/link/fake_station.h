#pragma once
// A scriptable dp::Station for link tests: records what it receives (with the time),
// answers requests addressed to it according to a reply policy, and can run a periodic
// timer. Deliberately tiny: it knows nothing of DP, only of FDL shapes.

#include "dp/link/memory_bus.h"
#include "dp/station.h"

#include <deque>
#include <optional>
#include <vector>

namespace rs4sim::dp::link::testing {

struct Received {
  fdl::Telegram telegram;
  TimePoint at;
};

class FakeStation : public Station {
 public:
  enum class Reply { kNone, kShortAck, kEchoData };

  explicit FakeStation(std::uint8_t address, Reply reply = Reply::kNone)
      : address_(address), reply_(reply) {}

  [[nodiscard]] std::uint8_t address() const override { return address_; }

  void on_telegram(const fdl::Telegram& t, TimePoint now) override {
    received.push_back({t, now});
    const bool for_me = t.da == address_ && t.type != fdl::FrameType::kShortAck &&
                        t.type != fdl::FrameType::kToken && t.fc.is_request();
    if (!for_me) return;
    if (reply_ == Reply::kShortAck) outbox.push_back(fdl::make_short_ack());
    if (reply_ == Reply::kEchoData) {
      outbox.push_back(fdl::make_data_telegram(
          t.sa, address_, fdl::FrameControl::response(fdl::ResponseStatus::kDataLow), t.ssap,
          t.dsap,
          reply_data ? std::span<const std::uint8_t>(*reply_data)
                     : std::span<const std::uint8_t>(t.data.data(), t.data.size())));
    }
  }

  void on_time(TimePoint now) override {
    ++on_time_calls;
    last_on_time = now;
    if (period && next_ && now >= *next_) {
      ++timer_fires;
      next_ = *next_ + *period;
      if (on_timer) outbox.push_back(*on_timer);
    }
  }

  [[nodiscard]] std::optional<TimePoint> next_deadline() const override {
    return stuck_deadline ? stuck_deadline : next_;
  }

  std::optional<fdl::Telegram> take_transmit() override {
    if (outbox.empty()) return std::nullopt;
    fdl::Telegram t = outbox.front();
    outbox.pop_front();
    return t;
  }

  // Station::send_time(): every telegram handed out starts no earlier than `hold`.
  [[nodiscard]] std::optional<TimePoint> send_time() const override { return hold; }

  // Fires every `p`, first at `first`; sends `telegram` on each fire if given.
  void run_timer(TimePoint first, Duration p, std::optional<fdl::Telegram> telegram = {}) {
    next_ = first;
    period = p;
    on_timer = std::move(telegram);
    wake();
  }

  // Queues a telegram from outside a link call and tells the link (Station::wake()).
  void send(fdl::Telegram t) {
    outbox.push_back(std::move(t));
    wake();
  }

  std::vector<Received> received;
  std::deque<fdl::Telegram> outbox;
  std::optional<Duration> period;
  std::optional<fdl::Telegram> on_timer;
  std::optional<TimePoint> stuck_deadline;
  std::optional<TimePoint> hold;  // send_time() of everything sent
  std::optional<std::vector<std::uint8_t>>
      reply_data;  // kEchoData: reply with this instead  // a broken core that never advances
  int on_time_calls = 0;
  int timer_fires = 0;
  TimePoint last_on_time{};

 private:
  std::uint8_t address_;
  Reply reply_;
  std::optional<TimePoint> next_;
};

// A Data_Exchange-shaped request (default SAP, SRD_HI FCB=1 FCV=1) from `sa` to `da`.
inline fdl::Telegram srd_request(std::uint8_t da, std::uint8_t sa, std::vector<std::uint8_t> data) {
  return fdl::make_data_telegram(
      da, sa, fdl::FrameControl::request(fdl::RequestFunction::kSrdHigh, true, true), std::nullopt,
      std::nullopt, data);
}

// A master (2) and a slave (5) attached to one memory bus with its manual clock.
struct MasterAndSlave {
  explicit MasterAndSlave(MemoryBusConfig config = {},
                          FakeStation::Reply reply = FakeStation::Reply::kNone)
      : bus(clock, config), slave(5, reply) {
    bus.attach(master);
    bus.attach(slave);
  }
  ManualClock clock;
  MemoryBus bus;
  FakeStation master{2};
  FakeStation slave;
};

}  // namespace rs4sim::dp::link::testing
