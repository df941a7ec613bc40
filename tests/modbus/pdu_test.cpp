#include "modbus/pdu.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace rs4sim::modbus {
namespace {

using Bytes = std::vector<std::uint8_t>;
using Words = std::vector<std::uint16_t>;

RtuFrame decoded(const Bytes& wire) {
  RtuFrame f;
  EXPECT_FALSE(decode(wire, f));
  return f;
}

TEST(Pdu, ReadRequestP3) {
  // P3 [Polaris manual §8.2.3]: slave 1, FC 3, start 0x2000, 10 words, CRC CE 0D.
  const Bytes wire{0x01, 0x03, 0x20, 0x00, 0x00, 0x0A, 0xCE, 0x0D};
  ReadRequest r;
  ASSERT_FALSE(parse_read_request(decoded(wire), r));
  EXPECT_EQ(r.function, 0x03);
  EXPECT_EQ(r.start, 0x2000);
  EXPECT_EQ(r.quantity, 10);
  EXPECT_EQ(encode(make_read_request(0x01, r)), wire);
}

TEST(Pdu, ReadInputRequestP6) {
  // P6: slave 1, FC 4, start 0x2000, 2 words, CRC 7A 0B.
  const Bytes wire{0x01, 0x04, 0x20, 0x00, 0x00, 0x02, 0x7A, 0x0B};
  EXPECT_EQ(encode(make_read_request(0x01, {kReadInputRegisters, 0x2000, 2})), wire);
}

TEST(Pdu, ReadRequestRejects) {
  ReadRequest r;
  EXPECT_EQ(parse_read_request(RtuFrame{1, 3, {0x20, 0x00, 0x00}}, r), ModbusError::kBadLength);
  EXPECT_EQ(parse_read_request(RtuFrame{1, 3, {0x20, 0x00, 0x00, 0x00}}, r),
            ModbusError::kBadQuantity);
  EXPECT_EQ(parse_read_request(RtuFrame{1, 3, {0x20, 0x00, 0x00, 0x7E}}, r),
            ModbusError::kBadQuantity);
}

TEST(Pdu, ReadResponseP7) {
  // P7: slave 1, FC 3, 4 bytes, words 0x0009 0x0022, CRC AA 28.
  const Bytes wire{0x01, 0x03, 0x04, 0x00, 0x09, 0x00, 0x22, 0xAA, 0x28};
  Words words;
  ASSERT_FALSE(parse_read_response(decoded(wire), words));
  EXPECT_EQ(words, (Words{0x0009, 0x0022}));
  EXPECT_EQ(encode(make_read_response(0x01, 0x03, words)), wire);
}

TEST(Pdu, ReadResponseBadByteCount) {
  Words words;
  EXPECT_EQ(parse_read_response(RtuFrame{1, 3, {0x04, 0x00, 0x09}}, words),
            ModbusError::kBadByteCount);
  EXPECT_EQ(parse_read_response(RtuFrame{1, 3, {}}, words), ModbusError::kBadLength);
}

TEST(Pdu, WriteMultipleFl4MasterFrame) {
  // The barrier as master, FL4, objects 9-13 and 25-34 [Polaris manual §8.2.1, §8.2.3]:
  const Bytes wire{0x01,                    // slave
                   0x10,                    // FC 16
                   0x00, 0x00,              // start register 0
                   0x00, 0x0A,              // 10 words
                   0x14,                    // 20 bytes
                   0x00, 0x09, 0x00, 0x0D,  // object 1: 9..13
                   0x00, 0x19, 0x00, 0x22,  // object 2: 25..34
                   0x00, 0x00, 0x00, 0x00,  // object 3: none
                   0x00, 0x00, 0x00, 0x00,  // object 4: none
                   0x00, 0x09, 0x00, 0x22,  // overall 9..34
                   0xCA, 0xC3};             // CRC
  WriteMultipleRequest w;
  ASSERT_FALSE(parse_write_multiple(decoded(wire), w));
  EXPECT_EQ(w.start, 0);
  EXPECT_EQ(w.words, (Words{9, 13, 25, 34, 0, 0, 0, 0, 9, 34}));
  EXPECT_EQ(encode(make_write_multiple(0x01, 0, w.words)), wire);
}

TEST(Pdu, WriteMultipleRejects) {
  WriteMultipleRequest w;
  EXPECT_EQ(parse_write_multiple(RtuFrame{1, 3, {}}, w), ModbusError::kWrongFunction);
  EXPECT_EQ(parse_write_multiple(RtuFrame{1, 0x10, {0, 0, 0, 1}}, w), ModbusError::kBadLength);
  EXPECT_EQ(parse_write_multiple(RtuFrame{1, 0x10, {0, 0, 0, 1, 4, 0, 0}}, w),
            ModbusError::kBadByteCount);
  EXPECT_EQ(parse_write_multiple(RtuFrame{1, 0x10, {0, 0, 0, 0, 0}}, w), ModbusError::kBadQuantity);
}

TEST(Pdu, WriteMultipleResponse) {
  // [Modbus application protocol V1.1b3 §6.12] response: start, quantity.
  EXPECT_EQ(make_write_multiple_response(0x11, 0x0001, 2),
            (RtuFrame{0x11, 0x10, {0x00, 0x01, 0x00, 0x02}}));
}

TEST(Pdu, WriteSingleSpecExample) {
  // [Modbus application protocol V1.1b3 §6.6] example: write register 2 (address 0x0001)
  // to 0x0003, on slave 0x11. CRC computed independently (CRC-16/MODBUS, low byte first).
  const Bytes wire{0x11,        // slave
                   0x06,        // FC 6 write single register
                   0x00, 0x01,  // register address 0x0001
                   0x00, 0x03,  // value 0x0003
                   0x9A, 0x9B};  // CRC 0x9B9A
  WriteSingleRequest w;
  ASSERT_FALSE(parse_write_single(decoded(wire), w));
  EXPECT_EQ(w, (WriteSingleRequest{0x0001, 0x0003}));
  EXPECT_EQ(encode(make_write_single(0x11, w)), wire);
  // The normal response is an echo of the request.
  EXPECT_EQ(encode(make_write_single_response(0x11, w)), wire);
}

TEST(Pdu, WriteSingleRejects) {
  WriteSingleRequest w{7, 7};
  EXPECT_EQ(parse_write_single(RtuFrame{1, 0x10, {0, 1, 0, 3}}, w), ModbusError::kWrongFunction);
  EXPECT_EQ(parse_write_single(RtuFrame{1, 0x06, {0, 1, 0}}, w), ModbusError::kBadLength);
  EXPECT_EQ(parse_write_single(RtuFrame{1, 0x06, {0, 1, 0, 3, 0}}, w), ModbusError::kBadLength);
  EXPECT_EQ(w, (WriteSingleRequest{7, 7}));  // untouched on error
}

TEST(Pdu, WriteMultipleSpecExample) {
  // [Modbus application protocol V1.1b3 §6.12] example: two registers from 0x0001, values
  // 0x000A and 0x0102, on slave 0x11; the response echoes start and quantity.
  const Bytes request{0x11,        // slave
                      0x10,        // FC 16
                      0x00, 0x01,  // start 0x0001
                      0x00, 0x02,  // 2 registers
                      0x04,        // 4 bytes
                      0x00, 0x0A,  // 0x000A
                      0x01, 0x02,  // 0x0102
                      0xC6, 0xF0};  // CRC 0xF0C6
  WriteMultipleRequest w;
  ASSERT_FALSE(parse_write_multiple(decoded(request), w));
  EXPECT_EQ(w.start, 0x0001);
  EXPECT_EQ(w.words, (Words{0x000A, 0x0102}));
  const Bytes response{0x11, 0x10,   // slave, FC 16
                       0x00, 0x01,   // start
                       0x00, 0x02,   // quantity
                       0x12, 0x98};  // CRC 0x9812
  EXPECT_EQ(encode(make_write_multiple_response(0x11, 0x0001, 2)), response);
  WriteMultipleResponse r;
  ASSERT_FALSE(parse_write_multiple_response(decoded(response), r));
  EXPECT_EQ(r, (WriteMultipleResponse{0x0001, 2}));
}

TEST(Pdu, WriteMultipleResponseRejects) {
  WriteMultipleResponse r;
  EXPECT_EQ(parse_write_multiple_response(RtuFrame{1, 0x06, {0, 1, 0, 2}}, r),
            ModbusError::kWrongFunction);
  EXPECT_EQ(parse_write_multiple_response(RtuFrame{1, 0x10, {0, 1, 0}}, r),
            ModbusError::kBadLength);
  EXPECT_EQ(parse_write_multiple_response(RtuFrame{1, 0x10, {0, 1, 0, 0}}, r),
            ModbusError::kBadQuantity);
  EXPECT_EQ(parse_write_multiple_response(RtuFrame{1, 0x10, {0, 1, 0, 0x7C}}, r),
            ModbusError::kBadQuantity);
}

TEST(Pdu, ExceptionBusy) {
  // Exception 06 Server Device Busy [Modbus application protocol V1.1b3 §7] to FC 3, slave 1:
  // 01 83 06, CRC 0x32C1 computed independently.
  EXPECT_EQ(encode(make_exception(0x01, 0x03, ExceptionCode::kServerDeviceBusy)),
            (Bytes{0x01, 0x83, 0x06, 0xC1, 0x32}));
}

TEST(Pdu, ExceptionP8) {
  const RtuFrame f = make_exception(0x03, 0x03, ExceptionCode::kNegativeAcknowledge);
  EXPECT_TRUE(is_exception(f));
  EXPECT_EQ(encode(f), (Bytes{0x03, 0x83, 0x07, 0xA1, 0x32}));
}

}  // namespace
}  // namespace rs4sim::modbus
