// `rs4sim master` at the app layer, in-process on the memory link (simulated RS4s on the
// manual clock): the console and JSON reports, and the plugin seam a parameter proxy uses
// (react to Proxy-Request, read a record, report its own event).
#include "app/runtime/master_service.h"

#include "app/runtime/master_report.h"
#include "dp/master/master_error.h"
#include "rs4/adapter/cyclic_bytes.h"

#include <gtest/gtest.h>

#include <chrono>
#include <sstream>

namespace rs4sim::app {
namespace {

namespace device = rs4::device;

MasterServiceOptions options(std::vector<std::uint8_t> addresses, bool json) {
  MasterServiceOptions o;
  for (auto a : addresses) {
    device::Rs4MasterOptions r;
    r.address = a;
    o.station.slaves.push_back(r);
  }
  o.json = json;
  o.simulated_boot_ms = 3000;
  return o;
}

LinkOptions memory(double seconds) {
  LinkOptions l;
  l.link = LinkKind::kMemory;
  l.duration = seconds;
  return l;
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(MasterService, ConsoleShowsOneLinePerChangeOfEachRs4) {
  std::ostringstream out;
  EXPECT_EQ(run_master(options({4, 5}, false), memory(10), out), 0) << out.str();
  const auto text = out.str();
  EXPECT_EQ(text.rfind("master 1 on memory, RS4 at 4,5\n", 0), 0U) << text;
  for (const char* rs4 : {"RS4 4: ", "RS4 5: "}) {
    const std::string line = std::string(rs4) + "DP data exchange, PROFIsafe run, OSSD 0, ";
    EXPECT_EQ(count(text, line + "Proxy-Request 0"), 1U) << text;
    EXPECT_EQ(count(text, line + "Proxy-Request 1"), 2U) << text;  // the change + the end line
    EXPECT_NE(text.find(std::string("end: ") + rs4), std::string::npos) << text;
  }
}

TEST(MasterService, JsonHasOneObjectPerLine) {
  std::ostringstream out;
  EXPECT_EQ(run_master(options({4}, true), memory(10), out), 0);
  std::istringstream lines(out.str());
  std::string line;
  std::size_t n = 0;
  while (std::getline(lines, line)) {
    ++n;
    EXPECT_EQ(line.front(), '{') << line;
    EXPECT_EQ(line.back(), '}') << line;
    EXPECT_EQ(line.rfind("{\"t\":", 0), 0U) << line;
  }
  EXPECT_GE(n, 5U);
  const auto text = out.str();
  EXPECT_NE(text.find("\"event\":\"start\",\"link\":\"memory\",\"rs4\":[4]"), std::string::npos);
  EXPECT_NE(text.find("\"station\":4,\"event\":\"dp\",\"state\":\"DataExchange\","
                      "\"data_exchange\":true"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("\"station\":4,\"event\":\"profisafe\",\"state\":\"run\""),
            std::string::npos);
  EXPECT_NE(text.find("\"proxy_request\":true"), std::string::npos);
  EXPECT_NE(text.find("\"event\":\"stop\""), std::string::npos);
}

// [IEC 61158-6-3 slave supervision]: a slave in data exchange that stops answering (no reply
// within TSL, then max_retry_limit retries) is lost: a line of its own with the likely cause;
// a slave that never answered (start-up) is not "lost".
TEST(MasterReport, ASlaveThatStopsAnsweringInDataExchangeIsReportedLostWithTheHint) {
  using dp::master::PollState;
  const auto no_answer = dp::master::make_error_code(dp::master::MasterError::kNoAnswer);
  for (const bool json : {false, true}) {
    device::Rs4MasterStation station(options({4}, json).station);
    std::ostringstream out;
    const dp::TimePoint t0{};
    MasterReport report(out, json, t0);
    report.explain_lost_slaves(1, "the likely cause");
    report.events({device::DpStateChanged{4, PollState::kStatusRequest, no_answer}}, station,
                  t0 + std::chrono::seconds(1));
    EXPECT_EQ(out.str().find("lost"), std::string::npos) << out.str();
    report.events({device::DpStateChanged{4, PollState::kDataExchange, {}}}, station,
                  t0 + std::chrono::seconds(2));
    report.events({device::DpStateChanged{4, PollState::kStatusRequest, no_answer}}, station,
                  t0 + std::chrono::milliseconds(2500));
    const std::string text = out.str();
    if (json) {
      EXPECT_NE(text.find(R"({"t":2.500,"station":4,"event":"lost","retries":1,)"
                          R"("hint":"the likely cause"})"),
                std::string::npos)
          << text;
    } else {
      EXPECT_NE(text.find("2.500 s  RS4 4 lost: no reply after 1 retry; the likely cause\n"),
                std::string::npos)
          << text;
    }
    EXPECT_EQ(count(text, "lost"), 1U) << text;
  }
}

// The likely cause named with a lost slave depends on the link: a starved process on a pty
// (also a serial --port that is a pty's path) or UDP, the line on a real serial port, none on
// the in-memory bus.
TEST(MasterService, TheLostSlavesLikelyCauseFitsTheLink) {
  LinkOptions l;
  EXPECT_EQ(lost_slave_hint(l), "");
  l.link = LinkKind::kPty;
  EXPECT_NE(lost_slave_hint(l).find("slave process on a pty may be starved of CPU time: run it "
                                    "with --rt-priority 50"),
            std::string::npos);
  l.link = LinkKind::kSerial;
  l.port = "/dev/pts/3";
  EXPECT_NE(lost_slave_hint(l).find("--rt-priority 50"), std::string::npos);
  l.port = "/dev/ttyUSB0";
  EXPECT_EQ(lost_slave_hint(l).rfind("check the line (wiring, termination, rate)", 0), 0U);
  l.link = LinkKind::kUdp;
  EXPECT_NE(lost_slave_hint(l).find("--rt-priority 50"), std::string::npos);
}

// A stand-in for the parameter proxy: on Proxy-Request it reads the record (slot 0,
// index 2) once and reports the outcome as its own event.
class ProbePlugin final : public MasterPlugin {
 public:
  void start(device::Rs4MasterStation& station, dp::TimePoint now) override {
    (void)now;
    started = station.slave_addresses().size();
  }
  void on_event(const device::Rs4MasterEvent& e, device::Rs4MasterStation& station,
                MasterReport& report, dp::TimePoint now) override {
    if (std::holds_alternative<device::MasterCycle>(e)) ++cycles;
    if (const auto* in = std::get_if<device::InputByteChanged>(&e)) {
      if ((in->current & rs4::adapter::kInputProxyRequest) != 0 && !asked) {
        asked = station.read_record(in->address).has_value();
      }
    }
    if (const auto* r = std::get_if<device::RecordResult>(&e)) {
      ++results;
      report.custom(now, r->address, "proxy", "probe read done",
                    {{"step", std::string("probe")}, {"ok", !r->error}});
    }
  }
  std::size_t started = 0;
  std::size_t cycles = 0;
  std::size_t results = 0;
  bool asked = false;
};

TEST(MasterService, PluginSeesEventsActsOnTheStationAndReports) {
  for (const bool json : {false, true}) {
    ProbePlugin probe;
    std::ostringstream out;
    EXPECT_EQ(run_master(options({4}, json), memory(5), out, {&probe}), 0);
    EXPECT_EQ(probe.started, 1U);
    EXPECT_GT(probe.cycles, 100U);  // a tick every 10 ms cycle
    EXPECT_TRUE(probe.asked);
    EXPECT_EQ(probe.results, 1U);
    const auto text = out.str();
    if (json) {
      EXPECT_NE(text.find("\"station\":4,\"event\":\"record\",\"id\":"), std::string::npos);
      EXPECT_NE(text.find("\"event\":\"proxy\",\"step\":\"probe\",\"ok\":"), std::string::npos)
          << text;
    } else {
      EXPECT_NE(text.find("s  RS4 4: probe read done"), std::string::npos) << text;
    }
  }
}

}  // namespace
}  // namespace rs4sim::app

#include "app/runtime/master_proxy.h"
#include "storage/sqlite_archive.h"

#include <filesystem>

namespace rs4sim::app {
namespace {

// Where each RS4's sync began and ended in the console text.
struct SyncSpan {
  std::size_t begin = std::string::npos;
  std::size_t end = std::string::npos;
};
SyncSpan span_of(const std::string& text, const std::string& rs4) {
  return {text.find(rs4 + ": proxy begin"), text.find(rs4 + ": idle, CONFIG_SET_TO_DEFAULT")};
}

std::string run_two_with_proxy(std::size_t max_parallel) {
  const auto file = std::filesystem::temp_directory_path() /
                    ("rs4sim_proxy_" + std::to_string(max_parallel) + ".sqlite3");
  std::filesystem::remove(file);
  auto archive = storage::SqliteArchive::open(file).value();
  ProxyPluginOptions o;
  o.max_parallel = max_parallel;
  ProxyPlugin proxy(*archive, o);
  std::ostringstream out;
  EXPECT_EQ(run_master(options({4, 5}, false), memory(10), out, {&proxy}), 0) << out.str();
  archive.reset();
  std::filesystem::remove(file);
  return out.str();
}

// Two RS4s ask at once (both boot together): with one sync at a time per bus ([RS4 manual §6.4, §6.5]
// advice, the default) the second starts only after the first ended; with two they overlap.
TEST(MasterService, ProxySerialisesTwoScannersAskingAtOnce) {
  const auto serial = run_two_with_proxy(1);
  const auto a = span_of(serial, "RS4 4");
  const auto b = span_of(serial, "RS4 5");
  ASSERT_NE(a.end, std::string::npos) << serial;
  ASSERT_NE(b.end, std::string::npos) << serial;
  EXPECT_LT(a.end, b.begin) << serial;

  const auto parallel = run_two_with_proxy(2);
  const auto c = span_of(parallel, "RS4 4");
  const auto d = span_of(parallel, "RS4 5");
  ASSERT_NE(d.begin, std::string::npos) << parallel;
  EXPECT_LT(d.begin, c.end) << parallel;
}

// [RS4 manual §5.3] every read is made twice and compared (docs/proxy.md): the console names
// each read once, as read twice and compared, and no "(repeat)" line looks like a retry; the
// JSON lines keep every step, the compare reads included.
TEST(MasterService, TheConsoleNamesEachReadOnceTheJsonEveryStep) {
  for (const bool json : {false, true}) {
    const auto file = std::filesystem::temp_directory_path() /
                      ("rs4sim_proxy_console_" + std::to_string(json) + ".sqlite3");
    std::filesystem::remove(file);
    auto archive = storage::SqliteArchive::open(file).value();
    ProxyPlugin proxy(*archive, ProxyPluginOptions{});
    std::ostringstream out;
    EXPECT_EQ(run_master(options({4}, json), memory(10), out, {&proxy}), 0) << out.str();
    archive.reset();
    std::filesystem::remove(file);
    const auto text = out.str();
    // A factory-set RS4 and an empty archive: the sync identifies (twice), finds the factory
    // set and ends with CONFIG_SET_TO_DEFAULT, no upload (docs/proxy.md).
    if (json) {
      EXPECT_EQ(count(text, R"x("step":"identify")x"), 1U) << text;
      EXPECT_EQ(count(text, R"x("step":"identify (repeat)")x"), 1U) << text;
      continue;
    }
    EXPECT_EQ(text.find("(repeat)"), std::string::npos) << text;
    EXPECT_EQ(count(text, "RS4 4: identify"), 1U) << text;
    EXPECT_EQ(count(text, "RS4 4: identify (read twice, compared), FB_BUSY"), 1U) << text;
    EXPECT_EQ(count(text, "RS4 4: idle, CONFIG_SET_TO_DEFAULT"), 1U) << text;
  }
}

}  // namespace
}  // namespace rs4sim::app
