// Decodes the input as one RTU frame and every PDU parser on it. A decoded frame must
// encode back to the same bytes, and every parsed PDU must re-encode to its frame.
#include "modbus/pdu.h"
#include "modbus/rtu_frame.h"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>
#include <vector>

namespace {

using rs4sim::modbus::RtuFrame;

void check(bool ok) {
  if (!ok) std::abort();
}

void check_pdus(const RtuFrame& f) {
  namespace mb = rs4sim::modbus;
  mb::ReadRequest read;
  if (!mb::parse_read_request(f, read)) check(mb::make_read_request(f.address, read) == f);
  std::vector<std::uint16_t> words;
  if (!mb::parse_read_response(f, words)) {
    check(mb::make_read_response(f.address, f.function, words) == f);
  }
  mb::WriteMultipleRequest write;
  if (!mb::parse_write_multiple(f, write)) {
    check(mb::make_write_multiple(f.address, write.start, write.words) == f);
  }
  mb::WriteSingleRequest single;
  if (!mb::parse_write_single(f, single)) check(mb::make_write_single(f.address, single) == f);
  mb::WriteMultipleResponse written;
  if (!mb::parse_write_multiple_response(f, written)) {
    check(mb::make_write_multiple_response(f.address, written.start, written.quantity) == f);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto wire = std::span(data, size);
  RtuFrame frame;
  if (rs4sim::modbus::decode(wire, frame)) return 0;
  const std::vector<std::uint8_t> again = rs4sim::modbus::encode(frame);
  check(again.size() == size && std::equal(again.begin(), again.end(), wire.begin()));
  check_pdus(frame);
  return 0;
}
