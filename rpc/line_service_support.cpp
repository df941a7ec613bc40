#include "rpc/line_service_support.h"

#include "rpc/service_support.h"
#include "rpc/status.h"

#include <google/protobuf/descriptor.h>
#include <google/protobuf/message.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <string>
#include <variant>
#include <vector>

namespace rs4sim::rpc::line {
namespace {

constexpr std::uint32_t kMaxFaultDelayMs = 10'000;
constexpr std::size_t kMaxExchangeBytes = 256;  // the longest frame of the three: a Modbus RTU ADU
                                                // [Modbus serial line V1.02 §2.5.1]
constexpr std::uint32_t kDefaultExchangeMs = 1000;
constexpr std::uint64_t kMaxSimulatedMs = 24ULL * 3600 * 1000;

void fill_frame(const stream::LineFrame& f, v1::ReceivedFrame& out) {
  out.set_frame(std::string(f.bytes.begin(), f.bytes.end()));
  out.set_start_ns(to_ns(f.start));
  out.set_end_ns(to_ns(f.end));
}

}  // namespace

bool set_counter(google::protobuf::Message& out, std::string_view name,
                 const std::vector<std::uint64_t>& values) {
  const auto* field = out.GetDescriptor()->FindFieldByName(std::string(name));
  if (field == nullptr || field->cpp_type() != google::protobuf::FieldDescriptor::CPPTYPE_UINT64) {
    return false;
  }
  const auto* r = out.GetReflection();
  if (field->is_repeated()) {
    r->ClearField(&out, field);
    for (const auto v : values) r->AddUInt64(&out, field, v);
  } else if (!values.empty()) {
    r->SetUInt64(&out, field, values.front());
  }
  return true;
}

grpc::Status needs_simulated_line(const std::string& kind) {
  std::string word = kind;  // the --device word: "gridscan" for "GridScan"
  std::transform(word.begin(), word.end(), word.begin(),
                 [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
  return failed_precondition(
      "CLOCK", "simulated line",
      "this " + kind +
          " runs on a real-time link; Exchange and Receive need the simulated "
          "line (rs4sim run --device " +
          word + " --link memory --grpc ...)");
}

// Checks the address (INVALID_ARGUMENT beyond a byte, NOT_FOUND for another device), then
// runs `fn` on the loop; after a change the event hub looks at the device again. The link
// needs no poke: a core whose deadline or transmit queue a setter moves wakes it itself
// ([stream/byte_device.h] point 4; tests/*/wake_test.cpp).
grpc::Status on_line(const LineContext& c, const std::string& kind, std::uint32_t address,
                     const LineFn& fn, bool changes) {
  if (address > 255) {
    return invalid_argument("address", std::to_string(address) + " is not a one-byte address");
  }
  if (address != c.address) {
    return not_found("no " + kind + " at address " + std::to_string(address) + " (this run's " +
                     kind + " answers to " + std::to_string(c.address) + ")");
  }
  grpc::Status result;
  c.executor.run([&] {
    const auto now = c.clock.now();
    result = fn(now);
    if (!changes) return;
    if (c.hub != nullptr) c.hub->poll(now);
  });
  return result;
}

// SetBlockedRequest.blocked as numbers 1..count, or the INVALID_ARGUMENT naming the entry.
std::variant<std::vector<std::uint16_t>, grpc::Status> numbers(const v1::SetBlockedRequest& in,
                                                               unsigned count, const char* what) {
  std::vector<std::uint16_t> out;
  for (int i = 0; i < in.blocked_size(); ++i) {
    const auto n = in.blocked(i);
    if (n == 0 || n > count) {
      return invalid_argument(
          "blocked[" + std::to_string(i) + "]",
          std::string(what) + " " + std::to_string(n) + " outside 1.." + std::to_string(count));
    }
    out.push_back(static_cast<std::uint16_t>(n));
  }
  return out;
}

grpc::Status check_delay(std::uint32_t ms, const char* field) {
  if (ms == 0 || ms > kMaxFaultDelayMs) {
    return invalid_argument(field, std::to_string(ms) + " ms outside 1..10000");
  }
  return grpc::Status::OK;
}

// "9-13,25-34" (the --blocked syntax), "none" when empty.
std::string ranges(const std::vector<std::uint16_t>& sorted) {
  std::string out;
  for (std::size_t i = 0; i < sorted.size();) {
    std::size_t j = i;
    while (j + 1 < sorted.size() && sorted[j + 1] == sorted[j] + 1) ++j;
    out += (out.empty() ? "" : ",") + std::to_string(sorted[i]);
    if (j > i) out += "-" + std::to_string(sorted[j]);
    i = j + 1;
  }
  return out.empty() ? "none" : out;
}

const char* on_off(bool b) { return b ? "on" : "off"; }

void set_last_frame(const TappedByteDevice& tap, v1::LastFrame& out) {
  const auto& f = tap.last_frame();
  out.set_frame(std::string(f.begin(), f.end()));
  if (const auto at = tap.last_sent()) out.set_sent_ns(to_ns(*at));
}

std::uint32_t whole_ms(stream::Duration d) {
  return static_cast<std::uint32_t>(
      std::chrono::duration_cast<std::chrono::milliseconds>(d).count());
}

grpc::Status exchange_on(const LineContext& c, const std::string& kind,
                         const v1::ExchangeRequest& in, v1::ExchangeResponse& out) {
  if (in.request().empty() || in.request().size() > kMaxExchangeBytes) {
    return invalid_argument("request", std::to_string(in.request().size()) +
                                           " bytes outside 1..256 (the longest frame on the line)");
  }
  if (in.timeout_ms() > kMaxSimulatedMs) {
    return invalid_argument(
        "timeout_ms", std::to_string(in.timeout_ms()) + " ms outside 0..86400000 (24 h; 0 = 1000)");
  }
  const std::uint32_t ms = in.timeout_ms() == 0 ? kDefaultExchangeMs : in.timeout_ms();
  const std::vector<std::uint8_t> request(in.request().begin(), in.request().end());
  return on_line(
      c, kind, in.address(),
      [&](dp::TimePoint) {
        if (c.line == nullptr) return needs_simulated_line(kind);
        const auto x = c.line->exchange(request, std::chrono::milliseconds(ms));
        if (c.hub != nullptr) c.hub->poll(c.line->now());
        out.set_sent_ns(to_ns(x.sent));
        out.set_arrived_ns(to_ns(x.arrived));
        out.set_answered(x.reply.has_value());
        if (x.reply) {
          out.set_reply(std::string(x.reply->bytes.begin(), x.reply->bytes.end()));
          out.set_reply_start_ns(to_ns(x.reply->start));
          out.set_reply_end_ns(to_ns(x.reply->end));
          out.set_reply_after_ns(to_ns(x.reply->end) - to_ns(x.sent));
        }
        out.set_now_ns(to_ns(c.line->now()));
        return grpc::Status::OK;
      },
      false);
}

grpc::Status receive_on(const LineContext& c, const std::string& kind, const v1::ReceiveRequest& in,
                        v1::ReceiveResponse& out) {
  if (in.wait_ms() > kMaxSimulatedMs) {
    return invalid_argument("wait_ms",
                            std::to_string(in.wait_ms()) + " ms outside 0..86400000 (24 h)");
  }
  return on_line(
      c, kind, in.address(),
      [&](dp::TimePoint) {
        if (c.line == nullptr) return needs_simulated_line(kind);
        if (in.wait_ms() > 0) {
          (void)c.line->run_until([] { return false; }, std::chrono::milliseconds(in.wait_ms()));
          if (c.hub != nullptr) c.hub->poll(c.line->now());
        }
        for (const auto& f : c.line->receive()) fill_frame(f, *out.add_frames());
        out.set_dropped(c.line->unsolicited_dropped());
        out.set_now_ns(to_ns(c.line->now()));
        return grpc::Status::OK;
      },
      false);
}

}  // namespace rs4sim::rpc::line
