#pragma once
// What the services of the RS-485 devices share (gridscan_service.h, metron_service.h,
// polaris_service.h): the call's context, the address check and the run on the loop, the
// checks of the common request fields, and Exchange/Receive on the simulated line.

#include "dp/time/clock.h"
#include "rpc/event_hub.h"
#include "rpc/executor.h"
#include "rpc/line_target.h"
#include "rpc/tapped_byte_device.h"
#include "rs4sim/v1/devices.pb.h"
#include "stream/clock.h"

#include <grpcpp/support/status.h>

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace rs4sim::rpc {

// What every call needs: the run's loop and clock, the device's address on its line, its
// tap, the run's event hub (nullptr: none) and, on the simulated clock, its line (nullptr on
// a real-time link: Exchange, Receive and a timed PowerCycle answer FAILED_PRECONDITION).
struct LineContext {
  Executor& executor;
  const dp::Clock& clock;
  std::uint8_t address;
  TappedByteDevice& tap;
  EventHub* hub = nullptr;
  SimulatedLine* line = nullptr;
};

namespace line {

using LineFn = std::function<grpc::Status(dp::TimePoint)>;

// Checks the address (INVALID_ARGUMENT beyond a byte, NOT_FOUND for another device; `kind`
// names the device in the message), then runs `fn` on the loop; when `changes`, the event hub
// looks at the device again afterwards. The link needs no poke: a core whose deadline or
// transmit queue a setter moves wakes it itself ([stream/byte_device.h] point 4;
// tests/*/wake_test.cpp).
grpc::Status on_line(const LineContext& c, const std::string& kind, std::uint32_t address,
                     const LineFn& fn, bool changes);

// SetBlockedRequest.blocked as numbers 1..count, or the INVALID_ARGUMENT naming the entry.
std::variant<std::vector<std::uint16_t>, grpc::Status> numbers(const v1::SetBlockedRequest& in,
                                                               unsigned count, const char* what);

// A fault's delay: 1..10000 ms, else INVALID_ARGUMENT naming `field`.
grpc::Status check_delay(std::uint32_t ms, const char* field);

// "9-13,25-34" (the --blocked syntax), "none" when empty.
std::string ranges(const std::vector<std::uint16_t>& sorted);

const char* on_off(bool b);

// An enum's API word, from the device library's to_token() (one table, beside its enum).
template <typename Enum>
std::string token_of(Enum e) {
  return std::string(to_token(e));
}

void set_last_frame(const TappedByteDevice& tap, v1::LastFrame& out);
std::uint32_t whole_ms(stream::Duration d);

// FAILED_PRECONDITION: the call needs the simulated line (`kind`'s run on --link memory).
grpc::Status needs_simulated_line(const std::string& kind);

// Exchange and Receive on the simulated line (FAILED_PRECONDITION on a real-time link).
grpc::Status exchange_on(const LineContext& c, const std::string& kind,
                         const v1::ExchangeRequest& in, v1::ExchangeResponse& out);
grpc::Status receive_on(const LineContext& c, const std::string& kind, const v1::ReceiveRequest& in,
                        v1::ReceiveResponse& out);

}  // namespace line
}  // namespace rs4sim::rpc
