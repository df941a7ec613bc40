#include "dp/master/bus_parameters.h"

#include "dp/master/master_error.h"

namespace rs4sim::dp::master {

BusParameters BusParameters::defaults_for(BaudRate baud) {
  const DefaultBusTimes r = default_bus_times(baud);
  BusParameters p;
  p.baud = baud;
  p.tsl = r.tsl;
  p.min_tsdr = kMinTsdrBits;
  p.max_tsdr = r.max_tsdr;
  p.tset = r.tset;
  p.tqui = r.tqui;
  p.tid1 = kTid1Bits;
  p.tid2 = r.max_tsdr;
  return p;
}

Duration BusParameters::token_lost_timeout(std::uint8_t ts) const {
  return bits(static_cast<std::uint64_t>(tsl) * (6U + 2U * ts));
}

std::error_code validate(const BusParameters& p) {
  const bool standard_rate = baud_rate_from_bps(bits_per_second(p.baud)).has_value();
  const bool ok = standard_rate && p.max_tsdr + 15 <= p.tsl && p.tsl <= 16383 &&
                  35 + 2 * p.tset + p.tqui <= p.max_tsdr && p.max_tsdr <= 1023 &&
                  p.min_tsdr >= 11 && p.min_tsdr + 1 <= p.max_tsdr && p.tid1 >= kTsynBits &&
                  p.tid2 >= kTsynBits && p.hsa >= 1 && p.hsa <= 126;
  return ok ? std::error_code{} : make_error_code(MasterError::kBadBusParameters);
}

}  // namespace rs4sim::dp::master
