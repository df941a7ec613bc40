#pragma once
// The PDUs the Polaris barrier speaks [Modbus application protocol V1.1b3 §6.3]
// [Modbus application protocol V1.1b3 §6.4] [Modbus application protocol V1.1b3 §6.12]
// [Modbus application protocol V1.1b3 §6.6] [Modbus application protocol V1.1b3 §7]: read
// holding/input registers (FC 0x03/0x04), write single register (FC 0x06), write multiple
// registers (FC 0x10) and exception responses (function | 0x80, code).

#include "modbus/rtu_frame.h"

#include <cstdint>
#include <span>
#include <system_error>
#include <vector>

namespace rs4sim::modbus {

inline constexpr std::uint8_t kReadHoldingRegisters = 0x03;
inline constexpr std::uint8_t kReadInputRegisters = 0x04;
inline constexpr std::uint8_t kWriteSingleRegister = 0x06;
inline constexpr std::uint8_t kWriteMultipleRegisters = 0x10;
inline constexpr std::uint16_t kMaxReadQuantity = 125;   // 0x7D
inline constexpr std::uint16_t kMaxWriteQuantity = 123;  // 0x7B

enum class ExceptionCode : std::uint8_t {
  kIllegalFunction = 0x01,
  kIllegalDataAddress = 0x02,
  kIllegalDataValue = 0x03,
  kServerDeviceFailure = 0x04,
  kServerDeviceBusy = 0x06,     // a long command is running; ask again later
  kNegativeAcknowledge = 0x07,  // Modbus's old code; the Polaris answers bad frames with it
};

struct ReadRequest {
  std::uint8_t function = kReadHoldingRegisters;  // 0x03 or 0x04
  std::uint16_t start = 0;
  std::uint16_t quantity = 0;
};

// FC 0x06: one register and its new value; the normal response echoes the request
// [Modbus application protocol V1.1b3 §6.6].
struct WriteSingleRequest {
  std::uint16_t address = 0;
  std::uint16_t value = 0;
  friend bool operator==(const WriteSingleRequest&, const WriteSingleRequest&) = default;
};

struct WriteMultipleRequest {
  std::uint16_t start = 0;
  std::vector<std::uint16_t> words;
};

[[nodiscard]] RtuFrame make_read_request(std::uint8_t address, const ReadRequest& r);
// Any function byte of `f` is accepted (the caller decides which it serves); the
// quantity is checked against 1..125.
[[nodiscard]] std::error_code parse_read_request(const RtuFrame& f, ReadRequest& out);

[[nodiscard]] RtuFrame make_read_response(std::uint8_t address, std::uint8_t function,
                                          std::span<const std::uint16_t> words);
[[nodiscard]] std::error_code parse_read_response(const RtuFrame& f,
                                                  std::vector<std::uint16_t>& words);

// FC 0x06 request, and its response: the same PDU [Modbus application protocol V1.1b3 §6.6].
[[nodiscard]] RtuFrame make_write_single(std::uint8_t address, const WriteSingleRequest& w);
[[nodiscard]] inline RtuFrame make_write_single_response(std::uint8_t address,
                                                         const WriteSingleRequest& w) {
  return make_write_single(address, w);
}
// Request or response (they have the same layout): function 0x06, exactly 4 data bytes.
[[nodiscard]] std::error_code parse_write_single(const RtuFrame& f, WriteSingleRequest& out);

[[nodiscard]] RtuFrame make_write_multiple(std::uint8_t address, std::uint16_t start,
                                           std::span<const std::uint16_t> words);
[[nodiscard]] std::error_code parse_write_multiple(const RtuFrame& f, WriteMultipleRequest& out);
[[nodiscard]] RtuFrame make_write_multiple_response(std::uint8_t address, std::uint16_t start,
                                                    std::uint16_t quantity);
// FC 0x10 response: start and quantity (1..123) [Modbus application protocol V1.1b3 §6.12].
struct WriteMultipleResponse {
  std::uint16_t start = 0;
  std::uint16_t quantity = 0;
  friend bool operator==(const WriteMultipleResponse&, const WriteMultipleResponse&) = default;
};
[[nodiscard]] std::error_code parse_write_multiple_response(const RtuFrame& f,
                                                            WriteMultipleResponse& out);

[[nodiscard]] RtuFrame make_exception(std::uint8_t address, std::uint8_t function,
                                      ExceptionCode code);
[[nodiscard]] inline bool is_exception(const RtuFrame& f) {
  return (f.function & kExceptionFlag) != 0;
}

}  // namespace rs4sim::modbus
