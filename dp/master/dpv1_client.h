#pragma once
// MSAC_C1 client of one slave: Read/Write requests and their polling
// ([IEC 61158-6-3 MSAC_C1, MSAC_C1 polling]).
//
// Wire pattern ([IEC 61158-6-3 MSAC_C1 polling]): SRD to DSAP 51 from SSAP 51 with the request PDU;
// while the slave answers without a response PDU (SC or "no data"), the master polls with SRDs to
// DSAP
// 51 that carry no DU (DSAP/SSAP only, e.g. `68 05 05 68 85 82 7C 33 33 E9 16`) until the
// reply carries the response or the negative response, or the C1 response timeout
// (counted from the first transmission of the request) expires. One request at a time per
// slave; further requests wait in a FIFO. A reply RR (no resources: the slave still
// works on an earlier request, [IEC 61158-6-3 MSAC_C1 polling] [VPC3+C manual p. 56]) makes the
// master send the request again on its next turn, until the timeout.

#include "dp/master/event_queue.h"
#include "dp/master/events.h"
#include "dp/master/reply.h"
#include "dp/pdu/dpv1.h"
#include "dp/time/clock.h"

#include <boost/container/static_vector.hpp>

#include <cstdint>
#include <deque>
#include <optional>
#include <system_error>

namespace rs4sim::dp::master {

struct Dpv1Job {
  Dpv1RequestId id = 0;
  Dpv1Operation operation = Dpv1Operation::kRead;
  std::uint8_t slot = 0;
  std::uint8_t index = 0;
  std::uint8_t length = 0;  // Read: max bytes wanted (1..240)
  pdu::Dpv1Data data;       // Write: the bytes (1..240)
};

class Dpv1Client {
 public:
  static constexpr std::size_t kQueueLimit = 16;

  Dpv1Client(std::uint8_t slave_address, Duration response_timeout)
      : address_(slave_address), timeout_(response_timeout) {}

  // Queues a job. Errors: kBadArgument (length 0 or > 240, slot/index 255), kQueueFull.
  std::error_code submit(Dpv1Job job);

  // The DU of the next SRD to DSAP 51: the request PDU of the next job, or an empty poll
  // for the job in progress. nullopt when idle. Starts the job's timeout on first send.
  std::optional<fdl::DataUnit> next_pdu(TimePoint now);

  // A job was sent and its response is still outstanding (the SAP is busy,
  // [IEC 61158-6-3 DPV1 alarms]).
  [[nodiscard]] bool busy() const { return active_.has_value(); }
  [[nodiscard]] bool idle() const { return !active_ && queue_.empty(); }
  [[nodiscard]] std::size_t queued() const { return queue_.size() + (active_ ? 1 : 0); }

  // Evaluates the slave's reply to the last SRD from next_pdu().
  void on_reply(const Reply& r, EventQueue& events);
  // Completes the job in progress with kDpv1Timeout once its time has passed.
  void check_timeout(TimePoint now, EventQueue& events);
  // Completes the job in progress with `active_error` and every queued one with `rest`.
  void abort_all(std::error_code active_error, std::error_code rest, EventQueue& events);

 private:
  struct Active {
    Dpv1Job job;
    TimePoint deadline;
    bool resend = false;  // the slave answered RR (no free buffer): send the request again
  };
  [[nodiscard]] fdl::DataUnit request_pdu(const Dpv1Job& j) const;
  void complete(Dpv1Result r, EventQueue& events);
  void finish_with(std::error_code ec, EventQueue& events);
  void on_response(const pdu::C1Response& resp, EventQueue& events);
  Dpv1Result result_for(const Dpv1Job& job) const;

  std::uint8_t address_;
  Duration timeout_;
  std::deque<Dpv1Job> queue_;
  std::optional<Active> active_;
};

}  // namespace rs4sim::dp::master
