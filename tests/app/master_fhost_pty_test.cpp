// Our master with its F-host and three F-devices on one line over a pseudo-terminal pair, in one
// process with the real clock (docs/profisafe.md "Our master as F-host for GSD F-devices"): on
// the slave side an RS4 (V1, its own F-host path), a V1 GSD F-device (f_module_v1.gsd) and a V2
// GSD F-device (f_module_v2.gsd's preset F-module); on the master side `rs4sim master`'s
// MasterService with manual acknowledgement and the GsdMaster API. All three reach PROFIsafe RUN;
// then, for each in turn, a CRC2 fault injected on the device's side (the run side's fault
// injection: the RS4's CORRUPT_CRC2, the F-device's corrupt_crc2) passivates that F-host only,
// ACK_REQ follows once the device answers correctly again, and ACK_REI reintegrates it. Waits
// are bounded and end as soon as the condition holds.
#include "app/runtime/master_service.h"
#include "dp/link/profibus_line.h"
#include "dp/link/station_runner.h"
#include "rpc/gsd_master_service.h"
#include "tests/app/gsd_master_f_calls.h"
#include "rs4/adapter/cyclic_bytes.h"
#include "rs4/device/rs4_device.h"
#include "stream/pty.h"
#include "stream/serial_transport.h"

#include <gtest/gtest.h>

#include <functional>
#include <sstream>

namespace rs4sim::app {
namespace {

namespace asio = boost::asio;
namespace device = rs4::device;
using namespace std::chrono_literals;
using Bytes = std::vector<std::uint8_t>;

const std::string kCorpus = RS4SIM_GSD_CORPUS;

struct PtyLine {
  asio::io_context io;
  stream::PseudoTerminal pty;
  dp::RealClock clock;
  std::ostringstream out;
  std::unique_ptr<stream::SerialTransport> slave_side, master_side;
  std::unique_ptr<dp::link::StationRunner> rs, rm;
  std::unique_ptr<device::Rs4Device> rs4;
  std::vector<std::unique_ptr<GsdStation>> gsd;
  std::unique_ptr<MasterService> service;
  testing::InlineExecutor executor;
  std::unique_ptr<rpc::GsdMasterService> api;

  PtyLine() {
    const auto v1 = load_gsd_station(kCorpus + "/f_module_v1.gsd", {"PROFIsafe v1.x Module"}, 5);
    const auto v2 = load_gsd_station(kCorpus + "/f_module_v2.gsd", {}, 6);
    MasterServiceOptions o;
    device::Rs4MasterOptions r;
    r.address = 4;
    r.f_wd_time_ms = 1000;
    r.dp_watchdog = 2000ms;
    o.station.slaves.push_back(r);
    o.station.auto_ack_rei = false;
    o.station.bus = dp::master::BusParameters::defaults_for(dp::BaudRate::k1M5);
    o.station.bus.tsl = 16383;  // a real-time link: the longest slot time (as `rs4sim master`)
    o.gsd_watchdog = 2000ms;
    // Generous watchdogs for a loaded machine (`rs4sim master --f-wd-time 1000`): the devices
    // take 10..10000 ms from their GSDs and run their watchdog on the received value.
    o.gsd_slaves = {v1, v2};
    apply_gsd_f_wd_time(o.gsd_slaves, 1000);
    const auto line = dp::link::profibus_line(dp::BaudRate::k1M5);
    slave_side = std::make_unique<stream::SerialTransport>(io, pty.release_master(), line, "pty");
    master_side = std::make_unique<stream::SerialTransport>(io, pty.slave_path(), line);
    rs = std::make_unique<dp::link::StationRunner>(io, clock, *slave_side);
    rm = std::make_unique<dp::link::StationRunner>(io, clock, *master_side);
    device::Rs4DeviceConfig c;
    c.switches = device::switches_for(4);
    c.boot_time = 1000ms;
    rs4 = std::make_unique<device::Rs4Device>(c);
    rs->add(*rs4);
    for (const auto* spec : {&v1, &v2}) {
      gsd.push_back(std::make_unique<GsdStation>(*spec));
      rs->add(*gsd.back());
    }
    service = std::make_unique<MasterService>(o, LinkKind::kPty, out);
    for (auto* s : service->stations()) rm->add(*s);
    api = std::make_unique<rpc::GsdMasterService>(
        executor, service->gsd_slaves(),
        [this]() -> dp::master::Master& { return service->station().master(); });
  }
  ~PtyLine() {
    rm->stop();
    rs->stop();
  }
  void start() {
    service->start(clock.now());
    rs4->power_on(clock.now());
    rs->start();
    rm->start();
  }
  bool wait(const std::function<bool()>& done, dp::Duration timeout = 30s) {
    const auto end = dp::SteadyClock::now() + timeout;
    while (!done() && dp::SteadyClock::now() < end) {
      io.run_for(2ms);
      if (io.stopped()) io.restart();
    }
    return done();
  }
  v1::GsdMasterFModule f(std::uint32_t address) {
    return testing::GsdMasterFCalls{*api}.f_module(address);
  }
  profisafe::FHostState rs4_state() { return service->station().view(4)->safety; }
  // The F-state of the F-host of `address` as the API words it ("run", "ack-required", ...).
  std::string state(std::uint32_t address) {
    return address == 4 ? std::string(profisafe::to_token(rs4_state())) : f(address).f_state();
  }
  void acknowledge(std::uint32_t address) {
    if (address == 4) {
      ASSERT_TRUE(service->station().ack_rei(4));
      return;
    }
    const auto status = testing::GsdMasterFCalls{*api}.acknowledge(address, 0);
    ASSERT_TRUE(status.ok()) << status.error_message();
  }
  profisafe::PduFaults& faults(std::uint32_t address) {
    if (address == 4) return rs4->adapter().safety_faults();
    return gsd[address - 5]->application().f_module(0)->device().faults();
  }
};

// One CRC2 fault at `address`: that F-host passivates, the others stay in RUN; ACK_REQ once the
// device answers correctly again; ACK_REI reintegrates.
void crc2_fault_passivates_and_ack_rei_reintegrates(PtyLine& line, std::uint32_t address) {
  SCOPED_TRACE("F-device " + std::to_string(address));
  line.faults(address).corrupt_crc2 = 1;
  ASSERT_TRUE(line.wait([&] { return line.state(address) == "ack-required"; }))
      << line.state(address) << "\n"
      << line.out.str();
  if (address != 4) {
    EXPECT_EQ(line.f(address).last_fault(), "CRC2 error");
    EXPECT_GE(line.f(address).counters().at("crc_errors"), 1u);
    EXPECT_EQ(line.f(address).f_inputs(), std::string(line.f(address).f_data_length(), '\0'));
  } else {
    EXPECT_EQ(line.service->station().input_byte(4), 0);  // the substitute value
  }
  for (const std::uint32_t other : {4u, 5u, 6u}) {
    if (other != address) {
      EXPECT_EQ(line.state(other), "run") << "F-device " << other;
    }
  }
  line.acknowledge(address);
  ASSERT_TRUE(line.wait([&] { return line.state(address) == "run"; })) << line.out.str();
  EXPECT_TRUE(line.wait([&] { return line.service->healthy(); })) << line.out.str();
}

TEST(MasterFHostPty, Rs4AndV1AndV2GsdFDevicesReachRunAndEachReintegratesAfterACrc2Fault) {
  PtyLine line;
  const Bytes v1_in{0x11, 0x22, 0x33, 0x44};
  const Bytes v2_in{0x01, 0x02, 0x03, 0x04, 0x05, 0x06, 0x07, 0x08};
  line.gsd[0]->application().f_module(0)->set_f_inputs(v1_in);
  line.gsd[1]->application().f_module(0)->set_f_inputs(v2_in);
  line.start();
  ASSERT_TRUE(line.wait([&] { return line.service->healthy(); }))
      << "not all in data exchange with PROFIsafe RUN over the pty\n"
      << line.out.str();
  EXPECT_EQ(line.f(5).mode(), "V1");
  EXPECT_EQ(line.f(6).mode(), "V2");
  EXPECT_EQ(line.f(5).f_inputs(), std::string(v1_in.begin(), v1_in.end()));
  EXPECT_EQ(line.f(6).f_inputs(), std::string(v2_in.begin(), v2_in.end()));
  // The RS4's process data through its F-host: once the error bit of its F-host's start-up has
  // gone, a restart pulse of 300 ms (0.12..5 s, [RS4 manual §4.3]) in the output byte releases
  // its start interlock: OSSD on with the field free ([RS4 manual §5.1.1, §5.1.2]).
  const auto in = [&] { return line.service->station().input_byte(4); };
  ASSERT_TRUE(line.wait([&] { return (in() & rs4::adapter::kInputError) == 0; })) << line.out.str();
  ASSERT_TRUE(line.service->station().set_output_byte(4, 0x81));  // restart + field pair 1
  (void)line.wait([] { return false; }, 300ms);
  ASSERT_TRUE(line.service->station().set_output_byte(4, 0x01));
  EXPECT_TRUE(line.wait([&] { return (in() & rs4::adapter::kInputOssd) != 0; })) << line.out.str();
  for (const std::uint32_t address : {4u, 5u, 6u}) {
    crc2_fault_passivates_and_ack_rei_reintegrates(line, address);
  }
  EXPECT_EQ(line.f(5).counters().at("reintegrations"), 1u);
  EXPECT_EQ(line.f(6).counters().at("reintegrations"), 1u);
  const auto text = line.out.str();
  EXPECT_NE(text.find("GSD slave 5: PROFIsafe V1 slot 0: passivated (CRC2 error)"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("GSD slave 6: PROFIsafe V2 slot 0: ack-required"), std::string::npos)
      << text;
}

}  // namespace
}  // namespace rs4sim::app
