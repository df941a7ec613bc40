#include "dp/devices/description.h"

#include "dp/pdu/sap.h"

#include <array>
#include <string_view>

namespace rs4sim::dp::devices {
namespace {

// The flags of `rs4sim run --device generic` (app/devices/device_generic.cpp).
constexpr std::array kOptions{
    stream::OptionInfo{"--address", 0, pdu::sap::kMaxSlaveAddress, "its station address"},
    stream::OptionInfo{"--ident", 1, 0, "Ident_Number, e.g. 0x1234"},
    stream::OptionInfo{"--cfg", 1, 0, "configuration identifiers in hex, e.g. \"10 20\""},
    stream::OptionInfo{"--gsd", 1, 0,
                       "the DP slave its GSD file describes (ident, Cfg, User_Prm_Data, rates, "
                       "MaxTsdr, DPV1, Max_Diag_Data_Len)"},
    stream::OptionInfo{"--module", 1, 0,
                       "with --gsd: a module by its GSD name, repeated in slot order (a compact "
                       "station's one module is implicit)"},
};

}  // namespace

// How the API finds its address.
constexpr std::string_view kAddressRule =
    "its station address 0..125 (--address) [IEC 61158-4-3 addresses, SAPs]";

const Description& description() {
  // kind, --device word, title, link, address rule, counters message, and the tables
  static const Description d(stream::DeviceKind::kGeneric, "generic", "generic DP slave",
                             stream::LinkKind::kProfibusDp, kAddressRule, "", kOptions, {}, {});
  return d;
}

}  // namespace rs4sim::dp::devices
