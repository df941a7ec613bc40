#pragma once
// A scripted master for device tests: sends one request at a time over a MemoryBus and
// returns the wire bytes of the reply, so tests compare against bytes from the cited sources.

#include "dp/fdl/decoder.h"
#include "dp/fdl/fcb.h"
#include "dp/link/memory_bus.h"

#include <gtest/gtest.h>

#include <deque>
#include <vector>

namespace rs4sim::dp::devices::testing {

using Bytes = std::vector<std::uint8_t>;

class ScriptMaster final : public Station {
 public:
  ScriptMaster(link::MemoryBus& bus, std::uint8_t address) : bus_(bus), address_(address) {
    bus_.add_observer([this](const link::BusEvent& e) {
      if (e.from != address_) last_reply_.assign(e.wire.begin(), e.wire.end());
    });
  }
  [[nodiscard]] std::uint8_t address() const override { return address_; }
  void on_telegram(const fdl::Telegram& t, TimePoint) override { replies.push_back(t); }
  void on_time(TimePoint) override {}
  [[nodiscard]] std::optional<TimePoint> next_deadline() const override { return std::nullopt; }
  std::optional<fdl::Telegram> take_transmit() override {
    if (out_.empty()) return std::nullopt;
    auto t = out_.front();
    out_.pop_front();
    return t;
  }

  // Sends exactly these wire bytes (a frame written from the cited sources) and returns the reply
  // bytes (empty: no reply). The frame's FC must match the FCB sequence of [IEC 61158-4-3 FCB/FCV].
  Bytes send_frame(const Bytes& frame) {
    fdl::Telegram t;
    EXPECT_FALSE(fdl::decode_frame(frame, t)) << "spec frame does not decode";
    if (t.fc.fcv() || t.fc.fcb()) {
      EXPECT_EQ(t.fc, fcb_.next(t.da, t.fc.function())) << "FCB sequence of the script";
    }
    return send(t);
  }

  // Sends an SRD high request with the next FCB to `da`.
  Bytes request(std::uint8_t da, std::optional<std::uint8_t> dsap, std::optional<std::uint8_t> ssap,
                const Bytes& du) {
    const auto fc = fcb_.next(da, fdl::RequestFunction::kSrdHigh);
    return send(fdl::make_data_telegram(da, address_, fc, dsap, ssap, du));
  }

  Bytes send(const fdl::Telegram& t) {
    last_reply_.clear();
    out_.push_back(t);
    wake();  // Station::wake(): the bus drains the new request
    bus_.run_for(std::chrono::milliseconds(1));
    return last_reply_;
  }

  std::vector<fdl::Telegram> replies;

 private:
  link::MemoryBus& bus_;
  std::uint8_t address_;
  fdl::FcbInitiator fcb_;
  std::deque<fdl::Telegram> out_;
  Bytes last_reply_;
};

}  // namespace rs4sim::dp::devices::testing
