#pragma once
// gRPC statuses with the rich error model (google.rpc.Status in the binary error details):
// INVALID_ARGUMENT carries a BadRequest naming the field, FAILED_PRECONDITION a
// PreconditionFailure, so generic clients show what was wrong and where.

#include <grpcpp/support/status.h>

#include <string>

namespace rs4sim::rpc {

grpc::Status invalid_argument(const std::string& field, const std::string& description);
grpc::Status not_found(const std::string& message);
// type: e.g. "CLOCK", "POWER"; subject: what it concerns (e.g. "station 4").
grpc::Status failed_precondition(const std::string& type, const std::string& subject,
                                 const std::string& description);

}  // namespace rs4sim::rpc
