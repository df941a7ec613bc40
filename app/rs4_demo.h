#pragma once
// `rs4sim demo` (RS4 scenario): one RS4/PROFIsafe, our GSD-configured class 1 master and
// a PROFIsafe F-host on the in-memory bus, on the manual clock (runs in well under a
// second). Narrates boot, DP and PROFIsafe start-up, OSSD, protective-field violation,
// restart interlock, field-pair switching, a measurement telegram (0x92 + READ), an RS4
// error as diagnosis alarm coming/going and a passivation with ACK_REI.
//
// cmd_demo.cpp (link author) calls run_rs4_demo() for `rs4sim demo` / `--device rs4`;
// see docs/requests/rs4-device-to-lead.md.

#include <iosfwd>

namespace rs4sim::app {

// Returns 0 when every step happened as the manual says, 1 otherwise (the failing step
// is named on `out`).
int run_rs4_demo(std::ostream& out);

}  // namespace rs4sim::app
