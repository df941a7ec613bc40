#include "dp/master/bus_parameters.h"

#include "dp/master/master_error.h"

#include <chrono>

namespace rs4sim::dp::master {
namespace {

struct TableRow {
  std::uint32_t tqui, tset, max_tsdr, tsl;
};

// §1.7 default bus parameters ([FELSER time ratios table]).
TableRow row_for(Baud baud) {
  switch (baud) {
    case Baud::k500k: return {0, 1, 100, 200};
    case Baud::k1M5: return {0, 1, 150, 300};
    case Baud::k3M: return {3, 4, 250, 400};
    case Baud::k6M: return {6, 8, 450, 600};
    case Baud::k12M: return {9, 16, 800, 1000};
    default: return {0, 1, 60, 100};  // ≤ 187.5 kbit/s
  }
}

bool known_baud(Baud b) {
  switch (b) {
    case Baud::k9k6: case Baud::k19k2: case Baud::k45k45: case Baud::k93k75:
    case Baud::k187k5: case Baud::k500k: case Baud::k1M5: case Baud::k3M:
    case Baud::k6M: case Baud::k12M:
      return true;
  }
  return false;
}

}  // namespace

BusParameters BusParameters::defaults_for(Baud baud) {
  const TableRow r = row_for(baud);
  BusParameters p;
  p.baud = baud;
  p.tsl = r.tsl;
  p.min_tsdr = 11;
  p.max_tsdr = r.max_tsdr;
  p.tset = r.tset;
  p.tqui = r.tqui;
  p.tid1 = 37;
  p.tid2 = r.max_tsdr;
  return p;
}

Duration BusParameters::bits(std::uint64_t n) const {
  const auto baud_rate = static_cast<std::uint64_t>(baud);
  const std::uint64_t ns = (n * 1'000'000'000ULL + baud_rate - 1) / baud_rate;
  return std::chrono::duration_cast<Duration>(std::chrono::nanoseconds(ns));
}

Duration BusParameters::token_lost_timeout(std::uint8_t ts) const {
  return bits(static_cast<std::uint64_t>(tsl) * (6U + 2U * ts));
}

std::error_code validate(const BusParameters& p) {
  const bool ok = known_baud(p.baud) && p.max_tsdr + 15 <= p.tsl && p.tsl <= 16383 &&
                  35 + 2 * p.tset + p.tqui <= p.max_tsdr && p.max_tsdr <= 1023 &&
                  p.min_tsdr >= 11 && p.min_tsdr + 1 <= p.max_tsdr && p.tid1 >= kTsynBits &&
                  p.tid2 >= kTsynBits && p.hsa >= 1 && p.hsa <= 126;
  return ok ? std::error_code{} : make_error_code(MasterError::kBadBusParameters);
}

}  // namespace rs4sim::dp::master
