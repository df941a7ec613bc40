#include "modbus/error.h"

namespace rs4sim::modbus {

std::string_view to_string(ModbusError e) noexcept {
  switch (e) {
    case ModbusError::kTooShort: return "RTU frame shorter than 4 bytes";
    case ModbusError::kTooLong: return "RTU frame longer than 256 bytes";
    case ModbusError::kBadCrc: return "RTU frame CRC mismatch";
    case ModbusError::kBadLength: return "PDU length does not fit its function";
    case ModbusError::kBadByteCount: return "byte count disagrees with the data";
    case ModbusError::kBadQuantity: return "register count out of range";
    case ModbusError::kWrongFunction: return "PDU of another function";
  }
  return "unknown modbus error";
}

}  // namespace rs4sim::modbus
