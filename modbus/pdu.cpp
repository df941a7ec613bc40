#include "modbus/pdu.h"

#include "codec/endian.h"

namespace rs4sim::modbus {

namespace {

void put16(std::vector<std::uint8_t>& out, std::uint16_t v) {
  out.push_back(codec::high_byte(v));
  out.push_back(codec::low_byte(v));
}

std::uint16_t get16(std::span<const std::uint8_t> data, std::size_t at) {
  return codec::be16(data[at], data[at + 1]);
}

void put_words(std::vector<std::uint8_t>& out, std::span<const std::uint16_t> words) {
  for (const std::uint16_t w : words) put16(out, w);
}

std::vector<std::uint16_t> get_words(std::span<const std::uint8_t> bytes) {
  std::vector<std::uint16_t> words(bytes.size() / 2);
  for (std::size_t i = 0; i < words.size(); ++i) words[i] = get16(bytes, 2 * i);
  return words;
}

}  // namespace

RtuFrame make_read_request(std::uint8_t address, const ReadRequest& r) {
  RtuFrame f{address, r.function, {}};
  put16(f.data, r.start);
  put16(f.data, r.quantity);
  return f;
}

std::error_code parse_read_request(const RtuFrame& f, ReadRequest& out) {
  if (f.data.size() != 4) return ModbusError::kBadLength;
  const std::uint16_t quantity = get16(f.data, 2);
  if (quantity < 1 || quantity > kMaxReadQuantity) return ModbusError::kBadQuantity;
  out = ReadRequest{f.function, get16(f.data, 0), quantity};
  return {};
}

RtuFrame make_read_response(std::uint8_t address, std::uint8_t function,
                            std::span<const std::uint16_t> words) {
  RtuFrame f{address, function, {}};
  f.data.reserve(1 + 2 * words.size());
  f.data.push_back(static_cast<std::uint8_t>(2 * words.size()));
  put_words(f.data, words);
  return f;
}

std::error_code parse_read_response(const RtuFrame& f, std::vector<std::uint16_t>& words) {
  if (f.data.empty()) return ModbusError::kBadLength;
  const std::size_t count = f.data[0];
  if (count % 2 != 0 || count + 1 != f.data.size()) return ModbusError::kBadByteCount;
  words = get_words(std::span(f.data).subspan(1));
  return {};
}

RtuFrame make_write_single(std::uint8_t address, const WriteSingleRequest& w) {
  RtuFrame f{address, kWriteSingleRegister, {}};
  put16(f.data, w.address);
  put16(f.data, w.value);
  return f;
}

std::error_code parse_write_single(const RtuFrame& f, WriteSingleRequest& out) {
  if (f.function != kWriteSingleRegister) return ModbusError::kWrongFunction;
  if (f.data.size() != 4) return ModbusError::kBadLength;
  out = WriteSingleRequest{get16(f.data, 0), get16(f.data, 2)};
  return {};
}

RtuFrame make_write_multiple(std::uint8_t address, std::uint16_t start,
                             std::span<const std::uint16_t> words) {
  RtuFrame f{address, kWriteMultipleRegisters, {}};
  f.data.reserve(5 + 2 * words.size());
  put16(f.data, start);
  put16(f.data, static_cast<std::uint16_t>(words.size()));
  f.data.push_back(static_cast<std::uint8_t>(2 * words.size()));
  put_words(f.data, words);
  return f;
}

std::error_code parse_write_multiple(const RtuFrame& f, WriteMultipleRequest& out) {
  if (f.function != kWriteMultipleRegisters) return ModbusError::kWrongFunction;
  if (f.data.size() < 5) return ModbusError::kBadLength;
  const std::uint16_t quantity = get16(f.data, 2);
  if (quantity < 1 || quantity > kMaxWriteQuantity) return ModbusError::kBadQuantity;
  const std::size_t count = f.data[4];
  if (count != 2U * quantity || count + 5 != f.data.size()) return ModbusError::kBadByteCount;
  out.start = get16(f.data, 0);
  out.words = get_words(std::span(f.data).subspan(5));
  return {};
}

RtuFrame make_write_multiple_response(std::uint8_t address, std::uint16_t start,
                                      std::uint16_t quantity) {
  RtuFrame f{address, kWriteMultipleRegisters, {}};
  put16(f.data, start);
  put16(f.data, quantity);
  return f;
}

std::error_code parse_write_multiple_response(const RtuFrame& f, WriteMultipleResponse& out) {
  if (f.function != kWriteMultipleRegisters) return ModbusError::kWrongFunction;
  if (f.data.size() != 4) return ModbusError::kBadLength;
  const std::uint16_t quantity = get16(f.data, 2);
  if (quantity < 1 || quantity > kMaxWriteQuantity) return ModbusError::kBadQuantity;
  out = WriteMultipleResponse{get16(f.data, 0), quantity};
  return {};
}

RtuFrame make_exception(std::uint8_t address, std::uint8_t function, ExceptionCode code) {
  return RtuFrame{address,
                  static_cast<std::uint8_t>(function | kExceptionFlag),
                  {static_cast<std::uint8_t>(code)}};
}

}  // namespace rs4sim::modbus
