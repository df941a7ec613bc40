#include "modbus/rtu_frame.h"

#include "codec/endian.h"
#include "modbus/crc16.h"

namespace rs4sim::modbus {

std::vector<std::uint8_t> encode(const RtuFrame& frame) {
  std::vector<std::uint8_t> wire;
  wire.reserve(frame.data.size() + kMinFrameSize);
  wire.push_back(frame.address);
  wire.push_back(frame.function);
  wire.insert(wire.end(), frame.data.begin(), frame.data.end());
  const std::uint16_t crc = crc16(wire);
  wire.push_back(codec::low_byte(crc));
  wire.push_back(codec::high_byte(crc));
  return wire;
}

std::error_code decode(std::span<const std::uint8_t> wire, RtuFrame& out) {
  if (wire.size() < kMinFrameSize) return ModbusError::kTooShort;
  if (wire.size() > kMaxFrameSize) return ModbusError::kTooLong;
  const std::size_t body = wire.size() - 2;
  const std::uint16_t sent = codec::be16(wire[body + 1], wire[body]);
  if (crc16(wire.first(body)) != sent) return ModbusError::kBadCrc;
  out.address = wire[0];
  out.function = wire[1];
  out.data.assign(wire.begin() + 2, wire.begin() + static_cast<std::ptrdiff_t>(body));
  return {};
}

}  // namespace rs4sim::modbus
