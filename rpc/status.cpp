#include "rpc/status.h"

#include "google/rpc/error_details.pb.h"
#include "google/rpc/status.pb.h"

namespace rs4sim::rpc {
namespace {

grpc::Status with_detail(grpc::StatusCode code, const std::string& message,
                         const google::protobuf::Message& detail) {
  google::rpc::Status status;
  status.set_code(static_cast<int>(code));
  status.set_message(message);
  status.add_details()->PackFrom(detail);
  return {code, message, status.SerializeAsString()};
}

}  // namespace

grpc::Status invalid_argument(const std::string& field, const std::string& description) {
  google::rpc::BadRequest bad;
  auto* v = bad.add_field_violations();
  v->set_field(field);
  v->set_description(description);
  return with_detail(grpc::StatusCode::INVALID_ARGUMENT, field + ": " + description, bad);
}

grpc::Status not_found(const std::string& message) {
  return {grpc::StatusCode::NOT_FOUND, message};
}

grpc::Status failed_precondition(const std::string& type, const std::string& subject,
                                 const std::string& description) {
  google::rpc::PreconditionFailure failure;
  auto* v = failure.add_violations();
  v->set_type(type);
  v->set_subject(subject);
  v->set_description(description);
  return with_detail(grpc::StatusCode::FAILED_PRECONDITION, subject + ": " + description, failure);
}

}  // namespace rs4sim::rpc
