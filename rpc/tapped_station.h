#pragma once
// A dp::Station in front of another that shows the event hub every telegram to and from it
// (real-time links: the runner hands the station decoded telegrams; they are encoded again
// for the event, as they were on the wire). Everything else passes through unchanged.

#include "dp/station.h"
#include "rpc/event_hub.h"

namespace rs4sim::rpc {

class TappedStation final : public dp::Station {
 public:
  explicit TappedStation(dp::Station& inner);
  // nullptr = no tap (until the run's gRPC services exist).
  void set_hub(EventHub* hub) noexcept { hub_ = hub; }

  [[nodiscard]] std::uint8_t address() const override { return inner_.address(); }
  void on_telegram(const dp::fdl::Telegram& t, dp::TimePoint now) override;
  void on_time(dp::TimePoint now) override;
  [[nodiscard]] std::optional<dp::TimePoint> next_deadline() const override {
    return inner_.next_deadline();
  }
  std::optional<dp::fdl::Telegram> take_transmit() override;
  void on_malformed_frame(std::error_code why) override { inner_.on_malformed_frame(why); }
  [[nodiscard]] std::uint16_t min_tsdr_bits() const override { return inner_.min_tsdr_bits(); }

 private:
  void tap(const dp::fdl::Telegram& t, v1::Direction direction);

  dp::Station& inner_;
  EventHub* hub_ = nullptr;
  dp::TimePoint now_{};  // of the last call: take_transmit() has no time of its own
};

}  // namespace rs4sim::rpc
