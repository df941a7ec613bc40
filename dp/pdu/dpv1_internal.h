#pragma once
// Shared pieces of the C1 and C2 codecs (internal).

#include "dp/pdu/dpv1.h"

namespace rs4sim::dp::pdu::internal {

constexpr std::uint8_t fn(Dpv1Function f) { return static_cast<std::uint8_t>(f); }

inline std::span<const std::uint8_t> as_span(const Dpv1Data& d) { return {d.data(), d.size()}; }

// A decoder's value as an alternative of the variant Out, or its error.
template <class Out, class T>
Result<Out> as(Result<T>&& r) {
  if (!r) return r.error();
  return Out{std::move(r).value()};
}

bool known_function(std::uint8_t fn);
// Every DPV1 DU: at least the function byte, at most 244 bytes.
Result<void> check_du(std::span<const std::uint8_t> du);
Result<void> exact_size(std::span<const std::uint8_t> du, std::size_t n);
Result<Dpv1Data> data_with_length(std::span<const std::uint8_t> du);
Result<ReadRequest> decode_read_request(std::span<const std::uint8_t> du);
Result<WriteRequest> decode_write_request(std::span<const std::uint8_t> du);
Result<ReadResponse> decode_read_response(std::span<const std::uint8_t> du);
Result<WriteResponse> decode_write_response(std::span<const std::uint8_t> du);
Result<Dpv1Error> decode_negative(std::span<const std::uint8_t> du);
Result<AlarmAck> decode_alarm_ack(std::span<const std::uint8_t> du);
Result<void> encode_data_pdu(Dpv1Function f, std::uint8_t slot, std::uint8_t index,
                             std::span<const std::uint8_t> data, fdl::DataUnit& out);

}  // namespace rs4sim::dp::pdu::internal
