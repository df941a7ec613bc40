// EXTENSION: the configuration registers at 0x0100 (docs/polaris.md "Configuration
// registers") driven over the shared line rig (tests/polaris/polaris_line.h) on the manual
// clock: FC 3 reads, FC 6 / FC 16 writes echoed [Modbus application protocol V1.1b3 §6.6]
// [Modbus application protocol V1.1b3 §6.12], the refusals (02, 03, all or nothing),
// broadcast writes ignored, and a setting taking effect at the next read. Every CRC below was
// computed independently (CRC-16/MODBUS, low byte first; check: 03 83 07 gives A1 32 as in
// docs/polaris.md).
#include "tests/polaris/polaris_line.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <vector>

namespace rs4sim::polaris {
namespace {

using std::chrono::milliseconds;
using namespace testing;  // Answers, answers, Bytes, Rig

// PL 10, 40 beams, FL1, slave 1, 19200 8N1; beams 9..13 and 25..34 interrupted
// (interrupt_objects).
Options config_options() {
  Options o;
  o.beams = 40;
  o.mode = DataMode::kFl1;
  return o;
}

void interrupt_objects(Rig& r) {
  std::vector<std::uint16_t> beams;
  for (std::uint16_t b = 9; b <= 13; ++b) beams.push_back(b);
  for (std::uint16_t b = 25; b <= 34; ++b) beams.push_back(b);
  EXPECT_FALSE(r.device().set_interrupted(beams, r.now()));
}

const Bytes kReadFl1{0x01, 0x03, 0x20, 0x00, 0x00, 0x02, 0xCF, 0xCB};
const Bytes kFl1Data{0x01, 0x03, 0x04, 0x00, 0x09, 0x00, 0x22, 0xAA, 0x28};
const Bytes kReadMode{0x01, 0x03, 0x01, 0x00, 0x00, 0x01, 0x85, 0xF6};  // 0x0100, 1 word
const Bytes kModeFl1{0x01, 0x03, 0x02, 0x00, 0x01, 0x79, 0x84};         // mode 1 (FL1)
const Bytes kModeFl4{0x01, 0x03, 0x02, 0x00, 0x02, 0x39, 0x85};         // mode 2 (FL4)

// A PolarisConfig test starts from the configuration above with the objects interrupted.
struct PolarisConfig : ::testing::Test {
  PolarisConfig() { interrupt_objects(r); }
  Rig r{config_options()};
};

TEST_F(PolarisConfig, ReadsTheWholeBlock) {
  const Bytes request{0x01, 0x03,   // slave 1, FC 3
                      0x01, 0x00,   // start 0x0100
                      0x00, 0x0C,   // 12 registers
                      0x44, 0x33};  // CRC
  EXPECT_EQ(answers(r, request), (Answers{{0x01, 0x03, 0x18,  // slave 1, FC 3, 24 bytes
                                           0x00, 0x01,        // 0x0100 data mode: FL1
                                           0x20, 0x00,        // 0x0101 start address 8192
                                           0x00, 0x00,        // 0x0102 direction: direct
                                           0x00, 0x00,        // 0x0103 detection: object
                                           0x00, 0x01,        // 0x0104 PN2 filter: 1 scan
                                           0x00, 0x64,        // 0x0105 scan time: 100 ms
                                           0x00, 0x00,        // 0x0106 bit order: LSB first
                                           0x00, 0x01,        // 0x0107 NAK mode: exception 07
                                           0x00, 0x00,        // 0x0108 command: reads 0
                                           0x00, 0x00,        // 0x0109 status: idle
                                           0x00, 0x00,        // 0x010A calibrations: 0
                                           0x00, 0x28,        // 0x010B beams: 40
                                           0xC0, 0xD8}}));    // CRC
  EXPECT_EQ(r.device().counters().requests, 1U);
}

TEST_F(PolarisConfig, WriteSingleEchoesAndTheNextReadUsesTheNewMode) {
  ASSERT_EQ(answers(r, kReadFl1), (Answers{kFl1Data}));
  const Bytes write{0x01, 0x06,   // slave 1, FC 6
                    0x01, 0x00,   // register 0x0100 data mode
                    0x00, 0x02,   // FL4
                    0x09, 0xF7};  // CRC
  EXPECT_EQ(answers(r, write), (Answers{write}));  // the response echoes the request
  EXPECT_EQ(r.device().options().mode, DataMode::kFl4);
  // P3 -> P4 [Polaris manual §8.2.3]: the FL4 block of objects 9..13 and 25..34.
  EXPECT_EQ(answers(r, {0x01, 0x03, 0x20, 0x00, 0x00, 0x0A, 0xCE, 0x0D}),
            (Answers{{0x01, 0x03, 0x14, 0x00, 0x09, 0x00, 0x0D, 0x00, 0x19, 0x00, 0x22, 0x00, 0x00,
                      0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x09, 0x00, 0x22, 0x19, 0x5A}}));
  EXPECT_EQ(answers(r, kReadMode), (Answers{kModeFl4}));
  EXPECT_EQ(r.device().counters().writes, 1U);
}

TEST_F(PolarisConfig, WriteMultipleMovesTheBlockAndReversesTheNumbering) {
  const Bytes write{0x01, 0x10,   // slave 1, FC 16
                    0x01, 0x00,   // start 0x0100
                    0x00, 0x03,   // 3 registers
                    0x06,         // 6 bytes
                    0x00, 0x02,   // data mode FL4
                    0x10, 0x00,   // start address 0x1000
                    0x00, 0x01,   // direction reverse
                    0x5E, 0xBC};  // CRC
  // Response: start and quantity [Modbus application protocol V1.1b3 §6.12].
  EXPECT_EQ(answers(r, write), (Answers{{0x01, 0x10, 0x01, 0x00, 0x00, 0x03, 0x81, 0xF4}}));
  // The old start address is now outside the block: exception 02.
  EXPECT_EQ(answers(r, {0x01, 0x03, 0x20, 0x00, 0x00, 0x0A, 0xCE, 0x0D}),
            (Answers{{0x01, 0x83, 0x02, 0xC0, 0xF1}}));
  // FL4 at 0x1000, reverse: physical 25..34 -> 7..16, 9..13 -> 28..32 (N + 1 - p).
  EXPECT_EQ(answers(r, {0x01, 0x03, 0x10, 0x00, 0x00, 0x0A, 0xC1, 0x0D}),
            (Answers{{0x01, 0x03, 0x14,
                      0x00, 0x07, 0x00, 0x10,  // object 1: 7..16
                      0x00, 0x1C, 0x00, 0x20,  // object 2: 28..32
                      0x00, 0x00, 0x00, 0x00,  // object 3: none
                      0x00, 0x00, 0x00, 0x00,  // object 4: none
                      0x00, 0x07, 0x00, 0x20,  // overall 7..32
                      0xC8, 0xA6}}));
}

TEST_F(PolarisConfig, AddressesOutsideTheMapOrReadOnlyGetException02) {
  const Bytes k02{0x01, 0x86, 0x02, 0xC3, 0xA1};  // FC 6 | 0x80, Illegal Data Address
  // Just past and just before the block: no configuration register, so the write is the
  // manual's "incorrect function code" -> 07 [Polaris manual §8.1.2] (PolarisWriteOutside).
  const Bytes k07{0x01, 0x86, 0x07, 0x03, 0xA2};  // FC 6 | 0x80, Negative Acknowledgment
  EXPECT_EQ(answers(r, {0x01, 0x06, 0x01, 0x0C, 0x00, 0x01, 0x89, 0xF5}), (Answers{k07}));  // past
  EXPECT_EQ(answers(r, {0x01, 0x06, 0x00, 0xFF, 0x00, 0x01, 0x78, 0x3A}), (Answers{k07}));  // before
  EXPECT_EQ(answers(r, {0x01, 0x06, 0x01, 0x09, 0x00, 0x00, 0x58, 0x34}), (Answers{k02}));  // status
  // FC 16 from 0x010A (calibrations) for 3 registers: read-only and past the end.
  EXPECT_EQ(answers(r, {0x01, 0x10, 0x01, 0x0A, 0x00, 0x03, 0x06, 0x00, 0x00, 0x00, 0x00, 0x00,
                        0x00, 0xC2, 0x5C}),
            (Answers{{0x01, 0x90, 0x02, 0xCD, 0xC1}}));
  // FC 3 of 0x010B (beams) and one past it.
  EXPECT_EQ(answers(r, {0x01, 0x03, 0x01, 0x0B, 0x00, 0x02, 0xB4, 0x35}),
            (Answers{{0x01, 0x83, 0x02, 0xC0, 0xF1}}));
  EXPECT_EQ(r.device().counters().refused_writes, 2U);
  EXPECT_EQ(r.device().counters().bad_function, 2U);
  EXPECT_EQ(r.device().counters().bad_start, 1U);
  EXPECT_EQ(r.device().counters().writes, 0U);
}

TEST_F(PolarisConfig, ValuesOutsideTheirRangeGetException03AndChangeNothing) {
  const Bytes k03{0x01, 0x86, 0x03, 0x02, 0x61};  // FC 6 | 0x80, Illegal Data Value
  EXPECT_EQ(answers(r, {0x01, 0x06, 0x01, 0x00, 0x00, 0x04, 0x89, 0xF5}), (Answers{k03}));  // mode 4
  // Start address 499 and 12288: just outside 500..12287 [Polaris manual §7.4.2].
  EXPECT_EQ(answers(r, {0x01, 0x06, 0x01, 0x01, 0x01, 0xF3, 0x98, 0x23}), (Answers{k03}));
  EXPECT_EQ(answers(r, {0x01, 0x06, 0x01, 0x01, 0x30, 0x00, 0xCD, 0xF6}), (Answers{k03}));
  // FC 16: mode FL4 (good) and start 499 (bad): all or nothing, the mode stays FL1.
  EXPECT_EQ(answers(r, {0x01, 0x10, 0x01, 0x00, 0x00, 0x02, 0x04, 0x00, 0x02, 0x01, 0xF3, 0x1E,
                        0x2A}),
            (Answers{{0x01, 0x90, 0x03, 0x0C, 0x01}}));
  // FC 16 byte count 2 for 2 registers, and quantity 0: a bad quantity.
  EXPECT_EQ(answers(r, {0x01, 0x10, 0x01, 0x00, 0x00, 0x02, 0x02, 0x00, 0x02, 0x37, 0x15}),
            (Answers{{0x01, 0x90, 0x03, 0x0C, 0x01}}));
  EXPECT_EQ(answers(r, {0x01, 0x10, 0x01, 0x00, 0x00, 0x00, 0x00, 0x34, 0x90}),
            (Answers{{0x01, 0x90, 0x03, 0x0C, 0x01}}));
  // FC 3 of 0 registers of the block.
  EXPECT_EQ(answers(r, {0x01, 0x03, 0x01, 0x00, 0x00, 0x00, 0x44, 0x36}),
            (Answers{{0x01, 0x83, 0x03, 0x01, 0x31}}));
  EXPECT_EQ(answers(r, kReadMode), (Answers{kModeFl1}));
  EXPECT_EQ(answers(r, kReadFl1), (Answers{kFl1Data}));
  EXPECT_EQ(r.device().options().start_address, std::nullopt);
  EXPECT_EQ(r.device().counters().refused_writes, 6U);
  EXPECT_EQ(r.device().counters().bad_request, 1U);
}

// "Implemented Functions: Read Holding Registers: Function Code 0x03, Read Input Registers:
// Function Code 0x04 ... In case of CRC error or incorrect function code, the Exception code
// in the response message will be 'Negative Acknowledgment' (0x07)" [Polaris manual §8.1.2].
// A write that touches no configuration register (the data block at 0x2000, say) is such an
// incorrect function: 07, nothing changed, counted as bad_function; with the NAK mode off
// (standard Modbus) the register does not exist: 02.
TEST(PolarisWriteOutside, FunctionSixAndSixteenOutsideTheBlockGetNegativeAcknowledge) {
  Rig r(config_options());
  interrupt_objects(r);
  // FC 6, register 0x2000 (the data block's first word), value 0x00FF.
  EXPECT_EQ(answers(r, {0x01, 0x06, 0x20, 0x00, 0x00, 0xFF, 0xC2, 0x4A}),
            (Answers{{0x01, 0x86, 0x07, 0x03, 0xA2}}));
  // FC 16 from 0x2000, 1 register, 2 bytes, value 0x0009.
  EXPECT_EQ(answers(r, {0x01, 0x10, 0x20, 0x00, 0x00, 0x01, 0x02, 0x00, 0x09, 0x47, 0x94}),
            (Answers{{0x01, 0x90, 0x07, 0x0D, 0xC2}}));
  // FC 16 of 0x00FE..0x00FF: ends just before the block -> 07; of 0x00FF..0x0100: reaches
  // into the block -> the block's refusal, 02 (0x00FF is no register of it).
  EXPECT_EQ(answers(r, {0x01, 0x10, 0x00, 0xFE, 0x00, 0x02, 0x04, 0x00, 0x01, 0x00, 0xFF, 0x6C,
                        0xE7}),
            (Answers{{0x01, 0x90, 0x07, 0x0D, 0xC2}}));
  EXPECT_EQ(answers(r, {0x01, 0x10, 0x00, 0xFF, 0x00, 0x02, 0x04, 0x00, 0x01, 0x00, 0x02, 0x6C,
                        0xAA}),
            (Answers{{0x01, 0x90, 0x02, 0xCD, 0xC1}}));
  EXPECT_EQ(answers(r, kReadMode), (Answers{kModeFl1}));
  EXPECT_EQ(answers(r, kReadFl1), (Answers{kFl1Data}));  // the data block unchanged
  const Counters& c = r.device().counters();
  EXPECT_EQ(c.bad_function, 3U);
  EXPECT_EQ(c.refused_writes, 1U);
  EXPECT_EQ(c.writes, 0U);
}

TEST(PolarisWriteOutside, StandardModbusAnswersIllegalDataAddress) {
  Options o = config_options();
  o.nak_on_error = false;
  Rig r(o);
  interrupt_objects(r);
  // FC 6, register 0x2000, value 10: 02 Illegal Data Address.
  EXPECT_EQ(answers(r, {0x01, 0x06, 0x20, 0x00, 0x00, 0x0A, 0x02, 0x0D}),
            (Answers{{0x01, 0x86, 0x02, 0xC3, 0xA1}}));
  EXPECT_EQ(r.device().counters().bad_function, 1U);
}

TEST_F(PolarisConfig, BroadcastWritesAreIgnored) {
  // "Broadcast is not supported" [Polaris manual §8.1]: a write to address 0, meant for the
  // other slaves of a shared line, changes nothing here, valid or not, and is not answered
  // (silent(): nothing arrived within the window and nothing is still on the wire).
  EXPECT_TRUE(r.silent({0x00, 0x06, 0x01, 0x00, 0x00, 0x09, 0x49, 0xE1}));  // mode 9
  EXPECT_TRUE(r.silent({0x00, 0x06, 0x01, 0x00, 0x00, 0x02, 0x08, 0x26}));  // mode FL4
  EXPECT_TRUE(r.silent({0x00, 0x06, 0x01, 0x08, 0x00, 0x01, 0xC9, 0xE5}));  // calibrate
  EXPECT_EQ(answers(r, kReadMode), (Answers{kModeFl1}));
  EXPECT_EQ(answers(r, kReadFl1), (Answers{kFl1Data}));  // not busy: no calibration runs
  const Counters& c = r.device().counters();
  EXPECT_EQ(c.broadcasts, 3U);
  EXPECT_EQ(c.writes, 0U);
  EXPECT_EQ(c.refused_writes, 0U);
}

TEST_F(PolarisConfig, NakModeWrittenSwitchesTheBadFunctionAnswer) {
  const Bytes fc5{0x01, 0x05, 0x20, 0x00, 0x00, 0x01, 0x07, 0xCA};  // FC 5: not served
  EXPECT_EQ(answers(r, fc5), (Answers{{0x01, 0x85, 0x07, 0x03, 0x52}}));  // 07 (the manual)
  // The area cleared: auto-calibration needs it free [Polaris manual §7.2].
  ASSERT_FALSE(r.device().set_interrupted({}, r.now()));
  const Bytes standard{0x01, 0x10, 0x01, 0x00, 0x00, 0x09, 0x12,  // 9 registers from 0x0100
                       0x00, 0x02,                                // data mode FL4
                       0x10, 0x00,                                // start 0x1000
                       0x00, 0x01,                                // reverse
                       0x00, 0x01,                                // hole detection
                       0x00, 0x03,                                // PN2 filter 3
                       0x00, 0x14,                                // scan time 20 ms
                       0x00, 0x01,                                // MSB first
                       0x00, 0x00,                                // NAK off: standard Modbus
                       0x00, 0x01,                                // command: auto-calibration
                       0x55, 0xD0};
  EXPECT_EQ(answers(r, standard), (Answers{{0x01, 0x10, 0x01, 0x00, 0x00, 0x09, 0x01, 0xF3}}));
  const Options& o = r.device().options();
  EXPECT_EQ(o.mode, DataMode::kFl4);
  EXPECT_EQ(o.start_address, 0x1000);
  EXPECT_EQ(o.direction, ScanDirection::kReverse);
  EXPECT_EQ(o.detection, Detection::kHole);
  EXPECT_EQ(o.pn2_filter, 3);
  EXPECT_EQ(o.scan_time, milliseconds(20));
  EXPECT_EQ(o.bit_order, BitOrder::kMsbFirst);
  EXPECT_FALSE(o.nak_on_error);
  EXPECT_TRUE(r.device().calibrating(r.now()));
  EXPECT_EQ(answers(r, fc5), (Answers{{0x01, 0x85, 0x01, 0x83, 0x50}}));  // 01 (standard)
}

}  // namespace
}  // namespace rs4sim::polaris
