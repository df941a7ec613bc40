// libFuzzer target: Slave_Diag decoder and the extended-diagnosis block reader
// ([IEC 61158-6-3 Slave_Diag, DPV1 alarms, status PDUs]). The diag re-encodes exactly; every block
// the encoders can express re-encodes to its own bytes; the reader always terminates.
#include "dp/pdu/ext_diag.h"
#include "dp/pdu/slave_diag.h"
#include "fuzz_check.h"

using namespace rs4sim::dp::pdu;

namespace {

struct Reencode {
  rs4sim::dp::fdl::DataUnit& out;
  Result<void> operator()(const DeviceDiag& d) { return encode_device_diag(d.data, out); }
  Result<void> operator()(const IdentifierDiag& d) { return encode_identifier_diag(d.bits, out); }
  Result<void> operator()(const ChannelDiag& c) {
    if (c.direction == ChannelDirection::kReserved) return PduError::kValueOutOfRange;
    return encode_channel_diag(c, out);
  }
  Result<void> operator()(const AlarmPdu& a) { return encode_alarm(a, out); }
  Result<void> operator()(const StatusPdu& s) { return encode_status(s, out); }
  Result<void> operator()(const RevisionBlock& r) {
    out.push_back(r.header);
    return boost::outcome_v2::success();
  }
};

void read_blocks(std::span<const std::uint8_t> ext, bool dpv1) {
  ExtDiagReader reader(ext, dpv1);
  std::size_t consumed = 0;
  for (std::size_t i = 0; i <= ext.size(); ++i) {
    const auto r = reader.next();
    if (!r || !r.value()) return;
    rs4sim::dp::fdl::DataUnit out;
    const auto e = std::visit(Reencode{out}, *r.value());
    if (e) {
      fuzz::check(consumed + out.size() <= ext.size());
      fuzz::check(fuzz::same(out, ext.subspan(consumed, out.size())));
    }
    consumed += out.size();
    if (!e) return;  // block not expressible by an encoder (reserved direction): stop checking
  }
  fuzz::check(false);  // the reader must end within ext.size() blocks
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::span<const std::uint8_t> du(data, size);
  const auto d = decode_slave_diag(du);
  if (d) {
    rs4sim::dp::fdl::DataUnit out;
    fuzz::check(encode_slave_diag(d.value(), out).has_value());
    fuzz::check(fuzz::same(out, du));
  }
  read_blocks(du, false);
  read_blocks(du, true);
  return 0;
}
