// A real Siemens master starting a real ET 200S, replayed to a GSD station (docs/gsd.md "Real
// traffic"): the capture of the telegrams between a master (address 1) and an ET 200S IM151-1
// HF (address 8, ident 0x80E0) with a PM-E power module and two 4DI cards, and the ET 200S's
// GSD as that project cut it down (modules only, no parameter definitions), both read from
// the real material beside the repository (tests/real_material.h). Every request of the
// capture goes to a station configured from that GSD with the capture's modules; each reply
// is compared with the ET 200S's reply: byte for byte where the protocol fixes it, and where
// the two legitimately differ, the test says why ([IEC 61158-6-3 Slave_Diag, Get_Cfg, Set_Prm,
// Chk_Cfg/Get_Cfg, Global_Control, Data_Exchange]).
//
// Facts derived by hand from the capture: 13 requests (4 Global_Control broadcasts, 9 to
// station 8: Slave_Diag, Get_Cfg, Set_Prm, Chk_Cfg, then 5 Slave_Diag) and 9 replies; the
// Set_Prm is Lock_Req + Sync_Req + Freeze_Req + WD_On (B8), WD factors 13 and 15, min TSDR
// 11, ident 0x80E0, group 0, then 25 bytes of User_Prm_Data; Chk_Cfg and Get_Cfg are 00 10 10.
#include "app/devices/gsd_station_file.h"
#include "dp/fdl/decoder.h"
#include "dp/pdu/sap.h"
#include "tests/real_material.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace rs4sim::app {
namespace {

using namespace std::chrono_literals;
using Bytes = std::vector<std::uint8_t>;
using dp::fdl::Telegram;

struct Collect final : dp::fdl::DecoderSink {
  void on_telegram(const Telegram& t) override { telegrams.push_back(t); }
  void on_decode_error(std::error_code e) override { errors.push_back(e); }
  std::vector<Telegram> telegrams;
  std::vector<std::error_code> errors;
};

// The capture: one telegram a line in hex (a request and its short acknowledgement may share
// a line), blank lines between exchanges. Its bytes go through the stream decoder as one line.
Collect read_capture(const std::filesystem::path& path) {
  std::ifstream in(path);
  Bytes bytes;
  std::string word;
  while (in >> word) bytes.push_back(static_cast<std::uint8_t>(std::stoul(word, nullptr, 16)));
  Collect c;
  dp::fdl::Decoder d;
  d.feed(bytes, c);
  d.idle(c);
  return c;
}

bool is_request(const Telegram& t) {
  return t.type != dp::fdl::FrameType::kShortAck && t.fc.is_request();
}

Bytes wire(const Telegram& t) {
  Bytes b;
  dp::fdl::encode(t, b);
  return b;
}

struct Replay {
  GsdStation station;
  dp::TimePoint now{std::chrono::hours(1)};

  explicit Replay(GsdStationSpec spec) : station(std::move(spec)) { station.on_time(now); }
  // The request 5 ms after the last one (the watchdog, 1950 ms, never runs out); the reply.
  std::optional<Telegram> request(const Telegram& t) {
    now += 5ms;
    if (const auto at = station.next_deadline(); at && *at <= now) station.on_time(now);
    station.on_telegram(t, now);
    auto reply = station.take_transmit();
    EXPECT_FALSE(station.take_transmit()) << "one reply per request";
    return reply;
  }
};

std::string absent(const char* what) {
  return std::string("the real material ") + what + " is absent from " +
         rs4sim::testing::real_material_dir().string() + " (RS4SIM_REAL_DIR names another place)";
}

// A Slave_Diag reply of the station against the ET 200S's (`first`: before any Set_Prm).
void compare_diag(const Telegram& got, const Telegram& real, bool first) {
  // The reply's frame: SD2 from 8 to 1, FC 08 (DL), SSAP 60 to DSAP 62, as the ET 200S.
  EXPECT_EQ(got.type, real.type);
  EXPECT_EQ(got.fc, real.fc);
  EXPECT_EQ(got.dsap, real.dsap);
  EXPECT_EQ(got.ssap, real.ssap);
  ASSERT_GE(got.data.size(), 6U);
  ASSERT_GE(real.data.size(), 6U);
  if (first) {
    // Before any Set_Prm the ET 200S's reply is the six standard bytes alone
    // (Station_Not_Ready; Prm_Req; no master, FF; ident 80 E0): ours is the same frame.
    EXPECT_EQ(wire(got), wire(real));
    return;
  }
  // After Set_Prm and Chk_Cfg. Legitimately different: the ET 200S keeps Stat_Diag
  // (Station_Status_2 bit 1) set for its first four diagnoses while its modules start, which
  // a GSD does not describe and our station does not need; and it appends 34 bytes of
  // identifier-related and module status blocks (Ext_Diag not set) that the GSD does not
  // describe either. The rest of the six standard bytes is the same: Station_Status_1 00,
  // Station_Status_2 0C (WD_On and the fixed bit 2), Station_Status_3 00, master 1, ident
  // 80 E0.
  const Bytes ours(got.data.begin(), got.data.begin() + 6);
  Bytes theirs(real.data.begin(), real.data.begin() + 6);
  theirs[1] = static_cast<std::uint8_t>(theirs[1] & ~0x02);
  EXPECT_EQ(ours, theirs);
  EXPECT_EQ(ours, (Bytes{0x00, 0x0C, 0x00, 0x01, 0x80, 0xE0}));
  EXPECT_EQ(got.data.size(), 6U);
}

// Data exchange (not in the capture, which ends with Global_Control): the master's next
// request would be Data_Exchange with no outputs, SD1 10 08 01 5D 66 16 (the last request had
// FCB 1); the reply carries the two input bytes, 05 from slot 2 and 0A from slot 3: SD2 LE 5,
// DA 1, SA 8, FC 08, FCS 01+08+08+05+0A = 20.
void exchange_data(Replay& r) {
  ASSERT_FALSE(r.station.application().set_inputs(1, Bytes{0x05}));
  ASSERT_FALSE(r.station.application().set_inputs(2, Bytes{0x0A}));
  Telegram dx;
  ASSERT_FALSE(dp::fdl::decode_frame(Bytes{0x10, 0x08, 0x01, 0x5D, 0x66, 0x16}, dx));
  const auto reply = r.request(dx);
  ASSERT_TRUE(reply);
  EXPECT_EQ(wire(*reply),
            (Bytes{0x68, 0x05, 0x05, 0x68, 0x01, 0x08, 0x08, 0x05, 0x0A, 0x20, 0x16}));
}

TEST(Et200sReplay, TheRealStartUpSequenceBringsTheGsdStationIntoDataExchange) {
  const auto capture_file = rs4sim::testing::real_file("captures/et200s-startup.txt");
  const auto gsd_file = rs4sim::testing::real_file("gsd/si0180e0-trimmed.gsd");
  if (!capture_file || !gsd_file) GTEST_SKIP() << absent("(ET 200S capture and GSD)");
  const Collect capture = read_capture(*capture_file);
  EXPECT_TRUE(capture.errors.empty()) << capture.errors.front().message();
  const auto& ts = capture.telegrams;
  ASSERT_EQ(ts.size(), 22U);
  ASSERT_EQ(std::count_if(ts.begin(), ts.end(), is_request), 13);

  // The capture's modules, named as the GSD names them: slot 1 PM-E (Cfg 00), slots 2 and 3
  // a 4DI card (Cfg 10, one input byte each).
  Replay r(load_gsd_station(gsd_file->string(), {"PM-E DC24V", "4DI DC24V", "4DI DC24V"}, 8));
  ASSERT_EQ(r.station.spec().setup.cfg, (std::vector<std::uint8_t>{0x00, 0x10, 0x10}));
  std::size_t diagnoses = 0;
  for (std::size_t i = 0; i < ts.size(); ++i) {
    if (!is_request(ts[i])) continue;
    SCOPED_TRACE("request " + std::to_string(i) + " FC " + std::to_string(ts[i].fc.raw));
    const auto got = r.request(ts[i]);
    const bool answered = i + 1 < ts.size() && !is_request(ts[i + 1]);
    ASSERT_EQ(got.has_value(), answered) << "Global_Control is never answered, the rest always";
    if (!answered) continue;
    if (ts[i].dsap == dp::pdu::sap::kSlaveDiag) {
      compare_diag(*got, ts[i + 1], diagnoses++ == 0);
    } else {  // Get_Cfg (00 10 10), the short acknowledgements of Set_Prm and Chk_Cfg
      EXPECT_EQ(wire(*got), wire(ts[i + 1]));
    }
  }
  EXPECT_EQ(diagnoses, 6U);
  // The 25 bytes of User_Prm_Data were taken (the GSD defines none: docs/gsd.md).
  EXPECT_TRUE(r.station.application().prm_fault().empty()) << r.station.application().prm_fault();
  EXPECT_EQ(r.station.application().user_prm_data().size(), 25U);
  EXPECT_EQ(r.station.slave().state(), dp::slave::State::kDataExch);
  exchange_data(r);
}

// A GSD without parameter definitions: any User_Prm_Data is taken, up to Max_User_Prm_Data_Len
// when the file gives it; a GSD with definitions still wants exactly its own.
TEST(GsdStationUndefinedPrm, TakesAnyUserPrmDataUpToTheGsdMaximum) {
  const auto dir =
      std::filesystem::temp_directory_path() / ("rs4sim_noprm_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto write = [&](const std::string& name, const std::string& extra) {
    std::ofstream(dir / name) << "#Profibus_DP\nGSD_Revision = 1\nVendor_Name = \"rs4sim test\"\n"
                                 "Model_Name = \"no parameters\"\nIdent_Number = 0x4711\n"
                                 "Protocol_Ident = 0\nStation_Type = 0\n1.5M_supp = 1\n"
                                 "MaxTsdr_1.5M = 150\n"
                              << extra << "Module = \"1 byte in\" 0x10\nEndModule\n";
    return (dir / name).string();
  };
  const auto accepts = [](const std::string& file, std::size_t n) {
    const GsdStationSpec spec = load_gsd_station(file, {}, 3);
    GsdApplication app(spec);  // keeps a reference to the spec
    dp::pdu::SetPrm prm;
    prm.ident_number = 0x4711;
    prm.user_data.assign(n, std::uint8_t{0x5A});
    const bool ok = app.check_parameters(prm, dp::TimePoint{}) == dp::slave::PrmVerdict::kAccept;
    EXPECT_EQ(ok, app.prm_fault().empty()) << app.prm_fault();
    return ok;
  };
  const auto none = write("none.gsd", "");
  EXPECT_TRUE(accepts(none, 0));
  EXPECT_TRUE(accepts(none, 25));
  EXPECT_TRUE(accepts(none, 237));  // 244 - 7, the most a Set_Prm carries
  const auto bounded = write("bounded.gsd", "Max_User_Prm_Data_Len = 4\n");
  EXPECT_TRUE(accepts(bounded, 4));
  EXPECT_FALSE(accepts(bounded, 5));
  const auto two = write("two.gsd", "User_Prm_Data_Len = 2\nUser_Prm_Data = 0x01,0x02\n");
  EXPECT_TRUE(accepts(two, 2));
  EXPECT_FALSE(accepts(two, 0));
  EXPECT_FALSE(accepts(two, 25));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace rs4sim::app
