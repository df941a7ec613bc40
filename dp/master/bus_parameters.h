#pragma once
// Bus parameters of the class 1 master ([IEC 61158-4-3 UART character, bus parameters, timing]
// [IEC 61158-2 baud rates]).
//
// All FDL times are counted in bit times (Tbit = 1/baud). The defaults per baud rate are
// the table of [IEC 61158-4-3 bus parameters, timing] (dp/time/baud_rate.h); `validate` checks the
// constraints of [IEC 61158-4-3 bus parameters, timing] ([ELPRO 105U-G manual p. 91]).

#include "dp/time/baud_rate.h"
#include "dp/time/clock.h"

#include <cstdint>
#include <system_error>

namespace rs4sim::dp::master {

struct BusParameters {
  BaudRate baud = BaudRate::k1M5;
  std::uint32_t tsl = 300;       // slot time: wait for the first reply character
  std::uint32_t min_tsdr = 11;   // responder's minimum delay
  std::uint32_t max_tsdr = 150;  // responder's maximum delay
  std::uint32_t tset = 1;
  std::uint32_t tqui = 0;
  std::uint32_t tid1 = 37;           // idle after a reply before the next request
                                     // ([COM PROFIBUS bus-parameter printout])
  std::uint32_t tid2 = 150;          // idle after a request without reply (SDN), ≥ max TSDR
  std::uint8_t max_retry_limit = 1;  // retries after a missing reply
                                     // ([IEC 61158-6-3 slave supervision], profirust 1)
  std::uint8_t hsa = 126;            // highest station address

  // The [IEC 61158-4-3 bus parameters, timing] default table for `baud` (TSL, TSDR, TSET, TQUI)
  // with TID1 = 37 and TID2 = max TSDR.
  static BusParameters defaults_for(BaudRate baud);

  // Duration of `bits` bit times at this baud rate, rounded up to the next nanosecond.
  [[nodiscard]] Duration bits(std::uint64_t n) const { return bit_time(baud, n); }
  // Wire time of `characters` UART characters (11 bits each, [IEC 61158-4-3 UART character]
  // [IEC 61158-2 baud rates]).
  [[nodiscard]] Duration characters(std::uint64_t n) const { return bits(n * kBitsPerCharacter); }
  // Token-lost timeout TTO = TSL · (6 + 2·TS) ([IEC 61158-4-3 bus parameters, timing]) for own
  // address `ts`.
  [[nodiscard]] Duration token_lost_timeout(std::uint8_t ts) const;
};

// [IEC 61158-4-3 bus parameters, timing] constraints: maxTSDR + 15 ≤ TSL ≤ 16383; 35 + 2·TSET +
// TQUI ≤ maxTSDR ≤ 1023;
// 11 ≤ minTSDR ≤ maxTSDR − 1; TID1, TID2 ≥ TSYN; baud one of [IEC 61158-4-3 UART character]
// [IEC 61158-2 baud rates]. Returns a MasterError::kBadBusParameters error naming nothing more; the
// message of the category says which rule.
std::error_code validate(const BusParameters& p);

}  // namespace rs4sim::dp::master
