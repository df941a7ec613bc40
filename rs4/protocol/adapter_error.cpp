#include "rs4/protocol/adapter_error.h"

#include <string>

namespace rs4sim::rs4::protocol {
namespace {

constexpr std::uint16_t kFamilyMask = 0xFFF0;
constexpr std::string_view kProxyRemedy =
    "process acyclic READ and WRITE only after the Proxy-FB completed the parameter "
    "sync; watch FB_BUSY ([RS4 manual §6.4])";

struct Text {
  std::string_view cause;
  std::string_view remedy;
};

Text text(AdapterError e) noexcept {
  const auto value = to_wire(e);
  if ((value & kFamilyMask) == to_wire(AdapterError::kEchoCrcWrong)) {
    return {"echo data CRC no. x wrong", kProxyRemedy};
  }
  if ((value & kFamilyMask) == to_wire(AdapterError::kCrcDiffersOnReread)) {
    return {"CRC no. x differs on read repetition", kProxyRemedy};
  }
  switch (e) {
    case AdapterError::kSafetyDriverCannotCheckOutputs:
      return {"the PROFIsafe driver cannot check the cyclic output data",
              "invalid operating state; can occur on PROFIBUS disturbances"};
    case AdapterError::kOutputsInconsistent:
      return {"processing the output data gives no consistent result",
              "invalid operating state; can occur on PROFIBUS disturbances"};
    case AdapterError::kWrongFieldPair:
      return {"wrong protective field pair number", "select only field pairs 1 to 4"};
    case AdapterError::kTelegramNotProcessed:
      return {"PROFIBUS telegram could not be processed",
              "evaluate the flow-control byte ([RS4 manual §5.2.1]) before acyclic WRITEs"};
    case AdapterError::kReadBuffersFull:
      return {"all read buffers for PROFIBUS telegrams are occupied",
              "fetch the result the adapter provides after every WRITE"};
    case AdapterError::kTelegramTooLong:
      return {"PROFIBUS telegram too long (>= 1100 bytes)", "send only valid acyclic WRITEs"};
    case AdapterError::kUnexpectedBlockNumber:
      return {"unexpected block number in PROFIBUS telegram",
              "number the blocks of a telegram sequentially"};
    case AdapterError::kProxyStateUnknown: return {"unknown state of the Proxy-FB", kProxyRemedy};
    case AdapterError::kCrcComparison: return {"error in CRC comparison", kProxyRemedy};
    default: return {"unknown adapter error", "see [RS4 manual table 5.3-3]"};
  }
}

}  // namespace

AdapterError echo_crc_wrong(std::uint8_t crc_number) noexcept {
  return static_cast<AdapterError>(to_wire(AdapterError::kEchoCrcWrong) | (crc_number & 0x0FU));
}

AdapterError crc_differs_on_reread(std::uint8_t crc_number) noexcept {
  return static_cast<AdapterError>(to_wire(AdapterError::kCrcDiffersOnReread) |
                                   (crc_number & 0x0FU));
}

std::optional<std::uint8_t> crc_number(AdapterError e) noexcept {
  const auto family = to_wire(e) & kFamilyMask;
  if (family == to_wire(AdapterError::kEchoCrcWrong) ||
      family == to_wire(AdapterError::kCrcDiffersOnReread)) {
    return static_cast<std::uint8_t>(to_wire(e) & 0x0FU);
  }
  return std::nullopt;
}

std::optional<AdapterError> adapter_error_from_wire(std::uint16_t value) noexcept {
  switch (value) {
    case 0x2418:
    case 0x2419:
    case 0x2600:
    case 0x2A04:
    case 0x2A05:
    case 0x2A06:
    case 0x2A0B:
    case 0x2B01:
    case 0x2B09: return static_cast<AdapterError>(value);
    default: break;
  }
  const auto family = static_cast<std::uint16_t>(value & kFamilyMask);
  if (family == 0x2B10 || family == 0x2B20) return static_cast<AdapterError>(value);
  return std::nullopt;
}

std::string_view adapter_error_cause(AdapterError e) noexcept { return text(e).cause; }
std::string_view to_string(AdapterError e) noexcept { return text(e).cause; }
std::string_view adapter_error_remedy(AdapterError e) noexcept { return text(e).remedy; }

std::string error_message(AdapterError e) {
  const auto value = to_wire(e);
  const Text t = text(e);
  std::string out = "0x";
  constexpr char kHex[] = "0123456789ABCDEF";
  for (int shift = 12; shift >= 0; shift -= 4)
    out += kHex[(static_cast<unsigned>(value) >> shift) & 0xFU];
  out += ": ";
  out += t.cause;
  out += " (remedy: ";
  out += t.remedy;
  out += ")";
  return out;
}

}  // namespace rs4sim::rs4::protocol
