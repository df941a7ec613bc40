#pragma once
// The rs4sim.v1 tests' unary calls, and the rich error details of a status as they read them
// (google.rpc.Status in the status's error_details: one BadRequest or one PreconditionFailure,
// docs/rpc.md).
#include "google/rpc/error_details.pb.h"
#include "google/rpc/status.pb.h"
#include "rs4sim/v1/rs4.pb.h"

#include <grpcpp/client_context.h>
#include <grpcpp/support/status.h>

#include <optional>
#include <string>

namespace rs4sim::rpc {

// One unary call: `rpc` of `stub` with `req`, the answer in `out`; its status.
template <class Stub, class Request, class Reply>
grpc::Status unary(Stub& stub,
                   grpc::Status (Stub::*rpc)(grpc::ClientContext*, const Request&, Reply*),
                   const Request& req, Reply& out) {
  grpc::ClientContext ctx;
  return (stub.*rpc)(&ctx, req, &out);
}

// The same for a call that answers Empty.
template <class Stub, class Request>
grpc::Status unary(Stub& stub,
                   grpc::Status (Stub::*rpc)(grpc::ClientContext*, const Request&, v1::Empty*),
                   const Request& req) {
  v1::Empty e;
  return unary(stub, rpc, req, e);
}

// The one detail of `status` as a T, if it carries exactly one of that type.
template <class T>
std::optional<T> only_detail(const grpc::Status& status) {
  google::rpc::Status rich;
  T detail;
  if (!rich.ParseFromString(status.error_details()) || rich.details_size() != 1 ||
      !rich.details(0).UnpackTo(&detail)) {
    return std::nullopt;
  }
  return detail;
}

// The request that names one station.
inline v1::StationRequest station_request(std::uint32_t address) {
  v1::StationRequest req;
  req.set_address(address);
  return req;
}

// A bus fault of `kind` on the telegrams of station `address` in `direction`, `count` times.
inline v1::BusFaultRequest bus_fault_request(std::uint32_t address, v1::BusFaultKind kind,
                                             v1::Direction direction, std::uint32_t count) {
  v1::BusFaultRequest req;
  req.set_address(address);
  req.set_kind(kind);
  req.set_direction(direction);
  req.set_count(count);
  return req;
}

// The field of an INVALID_ARGUMENT's one BadRequest violation ("?" without exactly one).
inline std::string bad_field(const grpc::Status& status) {
  const auto bad = only_detail<google::rpc::BadRequest>(status);
  if (!bad || bad->field_violations_size() != 1) return "?";
  return bad->field_violations(0).field();
}

// "field: description" of that violation.
inline std::string bad_field_described(const grpc::Status& status) {
  const auto bad = only_detail<google::rpc::BadRequest>(status);
  if (!bad || bad->field_violations_size() != 1) return "?";
  return bad->field_violations(0).field() + ": " + bad->field_violations(0).description();
}

// "TYPE subject: description" of a FAILED_PRECONDITION's one PreconditionFailure violation.
inline std::string precondition(const grpc::Status& status) {
  const auto failure = only_detail<google::rpc::PreconditionFailure>(status);
  if (!failure || failure->violations_size() != 1) return "?";
  const auto& v = failure->violations(0);
  return v.type() + " " + v.subject() + ": " + v.description();
}

}  // namespace rs4sim::rpc
