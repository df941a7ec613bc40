#include "dp/master/dpv1_client.h"

#include "dp/master/master_error.h"
#include "dp/pdu/sap.h"

namespace rs4sim::dp::master {

std::error_code Dpv1Client::submit(Dpv1Job job) {
  const bool read_ok =
      job.operation == Dpv1Operation::kRead && job.length >= 1 && job.length <= pdu::kDpv1MaxData;
  const bool write_ok = job.operation == Dpv1Operation::kWrite && !job.data.empty();
  // Index 255 is reserved for the I&M call mechanism but legal on the wire
  // ([IEC 61158-6-3 MSAC_C1]).
  if (!(read_ok || write_ok) || job.slot == 255) {
    return make_error_code(MasterError::kBadArgument);
  }
  if (queued() >= kQueueLimit) return make_error_code(MasterError::kQueueFull);
  if (job.operation == Dpv1Operation::kWrite) {
    job.length = static_cast<std::uint8_t>(job.data.size());
  }
  queue_.push_back(std::move(job));
  return {};
}

fdl::DataUnit Dpv1Client::request_pdu(const Dpv1Job& j) const {
  fdl::DataUnit du;
  if (j.operation == Dpv1Operation::kRead) {
    (void)pdu::encode(pdu::ReadRequest{j.slot, j.index, j.length}, du);
  } else {
    (void)pdu::encode(pdu::WriteRequest{j.slot, j.index, j.data}, du);
  }
  return du;
}

std::optional<fdl::DataUnit> Dpv1Client::next_pdu(TimePoint now) {
  if (active_) {
    if (!active_->resend)
      return fdl::DataUnit{};  // empty poll ([IEC 61158-6-3 MSAC_C1 polling]
                               // step 3)
    active_->resend = false;
    return request_pdu(active_->job);
  }
  if (queue_.empty()) return std::nullopt;
  active_ = Active{std::move(queue_.front()), now + timeout_};
  queue_.pop_front();
  return request_pdu(active_->job);
}

Dpv1Result Dpv1Client::result_for(const Dpv1Job& job) const {
  Dpv1Result r;
  r.id = job.id;
  r.address = address_;
  r.operation = job.operation;
  r.slot = job.slot;
  r.index = job.index;
  return r;
}

void Dpv1Client::complete(Dpv1Result r, EventQueue& events) {
  active_.reset();
  events.push(std::move(r));
}

void Dpv1Client::finish_with(std::error_code ec, EventQueue& events) {
  if (!active_) return;
  Dpv1Result r = result_for(active_->job);
  r.error = ec;
  complete(std::move(r), events);
}

void Dpv1Client::on_reply(const Reply& r, EventQueue& events) {
  if (!active_) return;
  using S = fdl::ResponseStatus;
  if (r.empty_ack())
    return;  // no response yet: poll again ([IEC 61158-6-3 MSAC_C1 polling]
             // step 2)
  if (!r.short_ack && r.status == S::kSapNotEnabled) {
    finish_with(make_error_code(MasterError::kSapNotEnabled), events);
    return;
  }
  if (!r.short_ack && r.status == S::kNoResource && !r.has_saps) {
    active_->resend = true;  // busy with an earlier request: try again next turn
    return;
  }
  if (!r.carries_data() || !r.from_saps(pdu::sap::kMasterMsac1, pdu::sap::kMsacC1)) {
    const bool rejected = !r.short_ack && r.status == S::kUserError;
    finish_with(
        make_error_code(rejected ? MasterError::kServiceRejected : MasterError::kInvalidResponse),
        events);
    return;
  }
  auto resp = pdu::decode_c1_response(r.data);
  if (!resp) {
    finish_with(make_error_code(MasterError::kInvalidResponse), events);
    return;
  }
  on_response(resp.value(), events);
}

void Dpv1Client::on_response(const pdu::C1Response& resp, EventQueue& events) {
  const Dpv1Job& job = active_->job;
  Dpv1Result out = result_for(job);
  const bool is_read = job.operation == Dpv1Operation::kRead;
  if (const auto* rd = std::get_if<pdu::ReadResponse>(&resp);
      rd && is_read && rd->slot == job.slot && rd->index == job.index &&
      rd->data.size() <= job.length) {
    out.data = rd->data;
    out.length = static_cast<std::uint8_t>(rd->data.size());
  } else if (const auto* wr = std::get_if<pdu::WriteResponse>(&resp);
             wr && !is_read && wr->slot == job.slot && wr->index == job.index) {
    out.length = wr->length;
  } else if (const auto* neg = std::get_if<pdu::Dpv1Error>(&resp);
             neg &&
             neg->function == (is_read ? pdu::Dpv1Function::kRead : pdu::Dpv1Function::kWrite)) {
    out.negative = *neg;
    out.error = to_error_code(*neg);
  } else {
    out.error = make_error_code(MasterError::kInvalidResponse);
  }
  complete(std::move(out), events);
}

void Dpv1Client::check_timeout(TimePoint now, EventQueue& events) {
  if (active_ && now >= active_->deadline) {
    finish_with(make_error_code(MasterError::kDpv1Timeout), events);
  }
}

void Dpv1Client::abort_all(std::error_code active_error, std::error_code rest, EventQueue& events) {
  finish_with(active_error, events);
  while (!queue_.empty()) {
    Dpv1Result r = result_for(queue_.front());
    queue_.pop_front();
    r.error = rest;
    complete(std::move(r), events);
  }
}

}  // namespace rs4sim::dp::master
