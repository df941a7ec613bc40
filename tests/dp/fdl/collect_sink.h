#pragma once
// Test helper: a DecoderSink that records everything in order.

#include "dp/fdl/decoder.h"

#include <span>
#include <system_error>
#include <utility>
#include <variant>
#include <vector>

namespace rs4sim::dp::fdl::testing {

using Event = std::variant<Telegram, std::error_code>;

class CollectSink final : public DecoderSink {
 public:
  void on_telegram(const Telegram& t) override { events.emplace_back(t); }
  void on_decode_error(std::error_code e) override { events.emplace_back(e); }
  void on_refused_frame(std::span<const std::uint8_t> frame, std::error_code e) override {
    refused.emplace_back(std::vector<std::uint8_t>(frame.begin(), frame.end()), e);
  }

  [[nodiscard]] std::vector<Telegram> telegrams() const {
    std::vector<Telegram> out;
    for (const auto& e : events) {
      if (const auto* t = std::get_if<Telegram>(&e)) out.push_back(*t);
    }
    return out;
  }
  [[nodiscard]] std::vector<std::error_code> errors() const {
    std::vector<std::error_code> out;
    for (const auto& e : events) {
      if (const auto* c = std::get_if<std::error_code>(&e)) out.push_back(*c);
    }
    return out;
  }
  std::vector<Event> events;
  // on_refused_frame: the frame's bytes and the error that follows it.
  std::vector<std::pair<std::vector<std::uint8_t>, std::error_code>> refused;
};

using Bytes = std::vector<std::uint8_t>;

inline Bytes concat(std::initializer_list<Bytes> parts) {
  Bytes out;
  for (const auto& p : parts) out.insert(out.end(), p.begin(), p.end());
  return out;
}

}  // namespace rs4sim::dp::fdl::testing
