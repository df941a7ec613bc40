// Observation.StreamEvents (docs/rpc.md "Event stream"): the request is checked here, the
// stream subscribes on the loop (so its snapshot and the changes after it line up), then this
// gRPC thread writes what the queue holds until the client goes away or the run ends.
#include "modbus/rtu_frame.h"
#include "rpc/event_hub.h"
#include "rpc/rs4_services.h"
#include "rpc/service_support.h"
#include "rpc/status.h"

#include <string>

namespace rs4sim::rpc {
namespace {

constexpr std::chrono::milliseconds kCancelCheck{100};  // how soon a cancelled stream ends

grpc::Status check(const v1::StreamEventsRequest& in) {
  const auto capacity = in.queue_capacity();
  if (capacity != 0 &&
      (capacity < EventQueue::kMinCapacity || capacity > EventQueue::kMaxCapacity)) {
    return invalid_argument("queue_capacity",
                            std::to_string(capacity) + " outside " +
                                std::to_string(EventQueue::kMinCapacity) + ".." +
                                std::to_string(EventQueue::kMaxCapacity) +
                                " (0 = " + std::to_string(EventQueue::kDefaultCapacity) + ")");
  }
  for (int i = 0; i < in.addresses_size(); ++i) {
    if (in.addresses(i) > 255) {
      return invalid_argument(
          "addresses[" + std::to_string(i) + "]",
          "address " + std::to_string(in.addresses(i)) +
              " outside 0..255 (RS4: 0..126, Polaris: " + std::to_string(modbus::kMinSlaveAddress) +
              ".." + std::to_string(modbus::kMaxSlaveAddress) + ")");
    }
  }
  return grpc::Status::OK;
}

}  // namespace

grpc::Status ObservationService::StreamEvents(grpc::ServerContext* context,
                                              const v1::StreamEventsRequest* in,
                                              grpc::ServerWriter<v1::Event>* out) {
  if (auto status = check(*in); !status.ok()) return status;
  EventHub* hub = c_.target.events();
  if (hub == nullptr) {
    return failed_precondition("EVENTS", "event stream", "this run has no event source");
  }
  const std::vector<std::uint8_t> addresses(in->addresses().begin(), in->addresses().end());
  const auto queue = std::make_shared<EventQueue>(
      in->queue_capacity() == 0 ? EventQueue::kDefaultCapacity : in->queue_capacity(),
      in->telegrams(), addresses);
  grpc::Status status;
  c_.executor.run([&] {
    for (const auto a : addresses) {
      if (!hub->watches(a)) {
        status = unknown_station(c_.target, a);
        return;
      }
    }
    hub->subscribe(queue, c_.target.now());
  });
  if (!status.ok()) return status;
  bool open = true;
  while (open && !context->IsCancelled()) {
    auto batch = queue->pop(kCancelCheck);
    if (batch.empty() && queue->closed()) break;
    // (No buffer hint: a sync Write with one waits for a flush that never comes.)
    for (std::size_t i = 0; i < batch.size() && open; ++i) open = out->Write(batch[i]);
  }
  hub->unsubscribe(queue);
  return grpc::Status::OK;
}

}  // namespace rs4sim::rpc
