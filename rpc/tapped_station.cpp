#include "rpc/tapped_station.h"

#include <array>

namespace rs4sim::rpc {

TappedStation::TappedStation(dp::Station& inner) : inner_(inner) {
  // The inner station's wakes must reach the link this one is attached to.
  inner_.set_wake_handler([this] { wake(); });
}

void TappedStation::on_telegram(const dp::fdl::Telegram& t, dp::TimePoint now) {
  now_ = now;
  if (t.da == inner_.address()) tap(t, v1::DIRECTION_TO_STATION);
  inner_.on_telegram(t, now);
}

void TappedStation::on_time(dp::TimePoint now) {
  now_ = now;
  inner_.on_time(now);
}

std::optional<dp::fdl::Telegram> TappedStation::take_transmit() {
  auto t = inner_.take_transmit();
  if (t) tap(*t, v1::DIRECTION_FROM_STATION);
  return t;
}

void TappedStation::tap(const dp::fdl::Telegram& t, v1::Direction direction) {
  if (hub_ == nullptr || !hub_->wants_telegrams()) return;
  std::array<std::uint8_t, dp::fdl::kMaxTelegramSize> wire{};
  const auto size = dp::fdl::encode(t, std::span(wire));
  hub_->telegram(inner_.address(), direction, std::span(wire.data(), size), "delivered", now_);
}

}  // namespace rs4sim::rpc
