// `rs4sim run --device polaris`: the PC tool's settings as --mode words [Polaris manual §7.4.2]
// (app/devices/device_polaris.cpp), refused with a precise UsageError (exit 2) or taking
// effect on the wire: the device the entry builds answers Modbus requests in process, on
// a hand-run clock.
#include "app/devices/device_registry.h"
#include "app/runtime/usage_error.h"
#include "modbus/pdu.h"
#include "modbus/rtu_frame.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace rs4sim::app {
namespace {

using Bytes = std::vector<std::uint8_t>;
using std::chrono::microseconds;
using std::chrono::milliseconds;

const DeviceEntry& polaris_entry() {
  const DeviceEntry* e = find_device("polaris");
  if (e == nullptr) {
    ADD_FAILURE() << "no device entry 'polaris'";
    std::abort();  // every test here needs it
  }
  return *e;
}

// The device of `rs4sim run --device polaris` with these options, started at time zero.
struct EntryRun {
  explicit EntryRun(DeviceOptions o) {
    polaris_entry().validate(o);
    instance = polaris_entry().build(o);
    device = instance->byte_devices().at(0);
    instance->start(now);
    device->on_time(now);
  }

  // Runs the clock until the device sends a frame or `until`; the frame and its time.
  std::optional<std::pair<Bytes, stream::TimePoint>> run_until_sent(stream::TimePoint until) {
    for (;;) {
      if (auto f = device->take_transmit()) return std::pair{*f, now};
      const auto next = device->next_deadline();
      if (!next || *next > until) return std::nullopt;
      now = std::max(*next, now);
      device->on_time(now);
    }
  }

  std::optional<std::pair<Bytes, stream::TimePoint>> exchange(const Bytes& request) {
    device->on_bytes(request, now);
    return run_until_sent(now + milliseconds(50));
  }

  stream::TimePoint now{milliseconds(10)};
  std::unique_ptr<DeviceInstance> instance;
  stream::ByteDevice* device = nullptr;
};

Bytes read_request(std::uint8_t address, std::uint16_t start, std::uint16_t quantity) {
  return modbus::encode(modbus::make_read_request(address, {0x03, start, quantity}));
}

// The registers of `run`'s answer to `request` (a read), in `words`.
void read_words(EntryRun& run, const Bytes& request, std::vector<std::uint16_t>& words) {
  const auto answer = run.exchange(request);
  ASSERT_TRUE(answer);
  modbus::RtuFrame f;
  ASSERT_FALSE(modbus::decode(answer->first, f));
  ASSERT_FALSE(modbus::parse_read_response(f, words));
}

std::string usage_error(DeviceOptions o) {
  try {
    polaris_entry().validate(o);
  } catch (const UsageError& e) {
    return e.what();
  }
  return "";
}

TEST(PolarisCli, StartAddressIsWhereTheBlockIsRead) {
  DeviceOptions o;
  o.model = "PL10";
  o.beams = 40;
  o.address = 5;
  o.mode = "FL1,start=0x1000";
  o.blocked = std::vector<int>{9, 10, 11, 12, 13, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34};
  EntryRun run(o);

  std::vector<std::uint16_t> words;
  ASSERT_NO_FATAL_FAILURE(read_words(run, read_request(5, 0x1000, 2), words));
  EXPECT_EQ(words, (std::vector<std::uint16_t>{9, 34}));  // FL1: overall first, last

  // The default block at 0x2000 is no longer there: exception 02.
  const auto refused = run.exchange(read_request(5, 0x2000, 2));
  ASSERT_TRUE(refused);
  EXPECT_EQ(refused->first, modbus::encode(modbus::make_exception(
                                5, 0x03, modbus::ExceptionCode::kIllegalDataAddress)));
}

// The answer leaves at the end of the scan in progress; a PL 10 with 40 beams (PL 10-400)
// scans in 1,3 ms, its first maximum response time [Polaris manual §2.2]. Scans run from
// the start (10 ms); the request ends at 10 ms + t3.5 (1.82 ms), in the second scan.
TEST(PolarisCli, TheModelsResponseTimeIsTheScan) {
  DeviceOptions o;
  o.model = "PL10";
  o.beams = 40;
  EntryRun run(o);
  const auto answer = run.exchange(read_request(1, 0x2000, 3));
  ASSERT_TRUE(answer);
  EXPECT_EQ(answer->second.time_since_epoch(), milliseconds(10) + 2 * microseconds(1300));
}

TEST(PolarisCli, MasterPushesToTheStartAddressEveryScanTime) {
  DeviceOptions o;
  o.address = 9;
  o.mode = "FL4,master,start=256,scan-time=20";
  EntryRun run(o);
  const auto first = run.run_until_sent(run.now + milliseconds(100));
  ASSERT_TRUE(first);
  EXPECT_EQ(first->second.time_since_epoch(), milliseconds(10) + milliseconds(20));
  modbus::RtuFrame f;
  ASSERT_FALSE(modbus::decode(first->first, f));
  modbus::WriteMultipleRequest push;
  ASSERT_FALSE(modbus::parse_write_multiple(f, push));
  EXPECT_EQ(f.address, 9);
  EXPECT_EQ(push.start, 256);
  EXPECT_EQ(push.words.size(), 10U);
  const auto second = run.run_until_sent(run.now + milliseconds(100));
  ASSERT_TRUE(second);
  EXPECT_EQ(second->second - first->second, milliseconds(20));
}

TEST(PolarisCli, NoNakIsStandardModbusAndMsbTurnsTheBits) {
  DeviceOptions o;
  o.model = "PL10";
  o.beams = 16;
  o.mode = "485MB,no-nak,msb";
  o.blocked = std::vector<int>{1};
  EntryRun run(o);
  Bytes bad = read_request(1, 0x2000, 1);
  bad.back() ^= 0xFF;
  EXPECT_FALSE(run.exchange(bad));  // CRC error: silence, not exception 07

  std::vector<std::uint16_t> words;
  ASSERT_NO_FATAL_FAILURE(read_words(run, read_request(1, 0x2000, 1), words));
  EXPECT_EQ(words, (std::vector<std::uint16_t>{0x7FFF}));  // beam 1 = the MSB, interrupted
}

TEST(PolarisCli, NakIsTheDefault) {
  DeviceOptions o;
  o.mode = "485MB,nak,lsb";
  EntryRun run(o);
  Bytes bad = read_request(1, 0x2000, 1);
  bad.back() ^= 0xFF;
  const auto answer = run.exchange(bad);
  ASSERT_TRUE(answer);
  EXPECT_EQ(answer->first, modbus::encode(modbus::make_exception(
                               1, 0x03, modbus::ExceptionCode::kNegativeAcknowledge)));
}

TEST(PolarisCli, BadSettingsAreUsageErrors) {
  const auto with_mode = [](const std::string& mode) {
    DeviceOptions o;
    o.mode = mode;
    return usage_error(o);
  };
  EXPECT_EQ(with_mode("FL4,start=0x2000,scan-time=5000,pn2-filter=255,hole,reverse"), "");
  EXPECT_EQ(with_mode("FL4,master,start=0"), "");
  EXPECT_EQ(with_mode("FL4,start=499"),
            "polaris: start address 499: must be 500..12287 in slave mode");
  EXPECT_EQ(with_mode("FL4,start=12288"),
            "polaris: start address 12288: must be 500..12287 in slave mode");
  EXPECT_EQ(with_mode("FL4,start=0x12G"),
            "--mode FL4,start=0x12G: 'start=0x12G': start= takes a register number 0..65535 "
            "(slave: 500..12287), e.g. start=8192 or start=0x2000");
  EXPECT_NE(with_mode("FL4,start=65536").find("'start=65536': start= takes"), std::string::npos);
  EXPECT_NE(with_mode("FL4,start=").find("'start=': start= takes"), std::string::npos);
  EXPECT_EQ(with_mode("FL4,scan-time=4"), "polaris: scan time 4 ms: must be 5..5000 ms");
  EXPECT_EQ(with_mode("FL4,scan-time=5001"), "polaris: scan time 5001 ms: must be 5..5000 ms");
  EXPECT_EQ(with_mode("FL4,scan-time=-5"),
            "--mode FL4,scan-time=-5: 'scan-time=-5': scan-time= takes milliseconds, 5..5000, "
            "e.g. scan-time=100");
  EXPECT_EQ(with_mode("FL4,pn2-filter=0"), "polaris: PN2 filter 0: must be 1..255 scans");
  EXPECT_EQ(with_mode("FL4,pn2-filter=256"), "polaris: PN2 filter 256: must be 1..255 scans");
  EXPECT_EQ(with_mode("FL4,pn2-filter=70000"),
            "--mode FL4,pn2-filter=70000: 'pn2-filter=70000': pn2-filter= takes a number of "
            "scans, 1..255");
  EXPECT_EQ(with_mode("FL4,msbfirst"),
            "--mode FL4,msbfirst: 'msbfirst' is none of slave, master, direct, reverse, object, "
            "hole, lsb, msb, nak, no-nak, start=, scan-time=, pn2-filter=, storage=, temporary, "
            "permanent, response-time=, response-column=");

  DeviceOptions o;
  o.address = 248;
  EXPECT_EQ(usage_error(o),
            "--address 248: a Modbus address is 1..247 [Modbus serial line V1.02 §2.2]");
  o.address = modbus::kMaxSlaveAddress;
  EXPECT_EQ(usage_error(o), "");
}

}  // namespace
}  // namespace rs4sim::app
