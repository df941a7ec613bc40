#pragma once
// What the services of the RS-485 devices share (gridscan_service.h, metron_service.h,
// polaris_service.h): the call's context, the address check and the run on the loop, the
// checks of the common request fields, Exchange/Receive on the simulated line, and the calls
// every one of them answers alike (line::LineService).

#include "dp/time/clock.h"
#include "rpc/event_hub.h"
#include "rpc/executor.h"
#include "rpc/line_target.h"
#include "rpc/tapped_byte_device.h"
#include "rs4sim/v1/devices.pb.h"
#include "stream/clock.h"
#include "stream/device_description.h"

#include <grpcpp/support/status.h>

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

namespace grpc {
class ServerContext;
}
namespace google::protobuf {
class Message;
}

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

// Sets the uint64 field `name` of `out` (a Counters message) to `values` (a repeated field:
// all of them; a scalar: the first). False: the message has no such field.
bool set_counter(google::protobuf::Message& out, std::string_view name,
                 const std::vector<std::uint64_t>& values);

// Every counter of the device's description into its Counters message, by the field names
// the description gives (tests/*/description_test.cpp: every one is a field, and back).
template <typename Device, typename Counters>
void set_counters(const stream::DeviceDescription<Device, Counters>& d, const Counters& k,
                  google::protobuf::Message& out) {
  for (const auto& c : d.counters) {
    std::vector<std::uint64_t> values;
    for (std::size_t i = 0; i < c.size; ++i) values.push_back(c.value(k, i));
    (void)set_counter(out, c.name, values);
  }
}

std::uint32_t whole_ms(stream::Duration d);

// What every line device's state message carries the same way: the faults present and the
// late-reply delay, the counters, the last frame on the line and the time of the answer.
template <typename Device, typename Counters, typename State>
void set_line_state(const stream::DeviceDescription<Device, Counters>& d, const Device& device,
                    const LineContext& c, std::int64_t now_ns, State& out) {
  for (const auto& f : stream::faults_present(d, device)) out.add_faults_present(f);
  out.set_late_ms(whole_ms(device.faults().transmit.late));
  set_counters(d, device.counters(), *out.mutable_counters());
  set_last_frame(c.tap, *out.mutable_last_frame());
  out.set_now_ns(now_ns);
}

// FAILED_PRECONDITION: the call needs the simulated line (`kind`'s run on --link memory).
grpc::Status needs_simulated_line(const std::string& kind);

// Exchange and Receive on the simulated line (FAILED_PRECONDITION on a real-time link).
grpc::Status exchange_on(const LineContext& c, const std::string& kind,
                         const v1::ExchangeRequest& in, v1::ExchangeResponse& out);
grpc::Status receive_on(const LineContext& c, const std::string& kind, const v1::ReceiveRequest& in,
                        v1::ReceiveResponse& out);

// The part of a line service that is the same for the three devices, over `Base` (the
// generated v1::GridScan::Service, v1::Metron::Service, v1::Polaris::Service) whose
// InjectFault and ClearFault take a `FaultRequest`: InjectFault and ClearFault run the
// device's fault(request, inject); Exchange and Receive check the address by the device's
// rule, then run exchange_on / receive_on. The device's service adds its own calls.
template <typename Base, typename FaultRequest>
class LineService : public Base {
 public:
  // Refuses an address the device can never have, before on_line's own check (the METRON's
  // broadcast, an address beyond Modbus's range), else OK. nullptr: on_line's check alone.
  using AddressCheck = grpc::Status (*)(std::uint32_t address);

  grpc::Status InjectFault(grpc::ServerContext*, const FaultRequest* in, v1::Empty*) final {
    return fault(*in, true);
  }
  grpc::Status ClearFault(grpc::ServerContext*, const FaultRequest* in, v1::Empty*) final {
    return fault(*in, false);
  }
  grpc::Status Exchange(grpc::ServerContext*, const v1::ExchangeRequest* in,
                        v1::ExchangeResponse* out) final {
    if (auto bad = check_address(in->address()); !bad.ok()) return bad;
    return exchange_on(c_, kind_, *in, *out);
  }
  grpc::Status Receive(grpc::ServerContext*, const v1::ReceiveRequest* in,
                       v1::ReceiveResponse* out) final {
    if (auto bad = check_address(in->address()); !bad.ok()) return bad;
    return receive_on(c_, kind_, *in, *out);
  }

 protected:
  // `kind` names the device in the messages ("GridScan", "METRON", "Polaris").
  LineService(LineContext context, std::string kind, AddressCheck check)
      : c_(context), kind_(std::move(kind)), check_address_(check) {}

  // InjectFault (`inject`) or ClearFault: the device's checks and its faults.
  virtual grpc::Status fault(const FaultRequest& in, bool inject) = 0;

  // A change the device cannot refuse: `apply` on the loop, then the event hub looks.
  grpc::Status change(std::uint32_t address, const std::function<void()>& apply) const {
    return on_device(
        address,
        [&](dp::TimePoint) {
          apply();
          return grpc::Status::OK;
        },
        true);
  }

  // A call on the device: the address by the device's rule, then on_line with its kind.
  grpc::Status on_device(std::uint32_t address, const LineFn& fn, bool changes) const {
    if (auto bad = check_address(address); !bad.ok()) return bad;
    return on_line(c_, kind_, address, fn, changes);
  }

  LineContext c_;

 private:
  [[nodiscard]] grpc::Status check_address(std::uint32_t address) const {
    return check_address_ == nullptr ? grpc::Status::OK : check_address_(address);
  }

  std::string kind_;
  AddressCheck check_address_;
};

}  // namespace line
}  // namespace rs4sim::rpc
