// libFuzzer target: Global_Control, Set_Slave_Add, empty requests and I/O images
// ([IEC 61158-6-3 SAP assignment, Global_Control, Set_Slave_Add, Rd_Inp/Rd_Outp]). Input byte 0
// selects the service.
#include "dp/pdu/global_control.h"
#include "dp/pdu/set_slave_add.h"
#include "dp/pdu/simple_services.h"
#include "fuzz_check.h"

using namespace rs4sim::dp::pdu;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::span<const std::uint8_t> du(data + 1, size - 1);
  rs4sim::dp::fdl::DataUnit out;
  switch (data[0] % 3) {
    case 0:
      if (const auto gc = decode_global_control(du)) {
        fuzz::check(encode_global_control(gc.value(), out).has_value() && fuzz::same(out, du));
        (void)gc.value().addresses(data[0]);
      }
      break;
    case 1:
      if (const auto ssa = decode_set_slave_add(du)) {
        fuzz::check(encode_set_slave_add(ssa.value(), out).has_value());
        const auto again =
            decode_set_slave_add(std::span<const std::uint8_t>(out.data(), out.size()));
        fuzz::check(again.has_value() && again.value() == ssa.value());
      }
      break;
    default:
      fuzz::check(decode_empty_request(du).has_value() == du.empty());
      if (const auto img = decode_io_image(du)) {
        fuzz::check(encode_io_image(img.value(), out).has_value() && fuzz::same(out, du));
      }
      break;
  }
  return 0;
}
