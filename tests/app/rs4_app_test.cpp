// `rs4sim demo` (RS4 scenario) and `rs4sim run --device rs4` at the app layer.
#include "app/cli/command.h"
#include "app/demos/demos.h"
#include "app/runtime/run_session.h"
#include "app/runtime/shell.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <iostream>
#include <sstream>

namespace rs4sim::app {
namespace {

// The options of `rs4sim run --device rs4`, run through the runtime's shell.
struct Rs4RunOptions {
  DeviceOptions device;
  LinkOptions link;
};
int run_rs4_device(const Rs4RunOptions& o, std::ostream& out) {
  return run_device(*find_device("rs4"), o.device, o.link, out);
}

TEST(Rs4Demo, EveryStepHappensAndIsNarrated) {
  std::ostringstream out;
  RunSession session(out);
  EXPECT_EQ(run_rs4_demo(session, out, DemoOptions{}), 0) << out.str();
  const std::string text = out.str();
  for (const char* line :
       {"DP start-up done", "F-host in RUN", "RS4 operational", "OSSD bit 0", "restart interlock",
        "field pair 1 → 2", "0x2600", "COM_CMD_MESS_16_RT", "529/529 equal",
        "diagnosis alarm coming", "diagnosis alarm going", "ACK_REI",
        "CONFIG_SET_TO_DEFAULT 1, ERROR_NUMBER_FB 0x0000",
        "upload [####################] 8507/8507 bytes", "archived: version 1, 8507 bytes",
        "download [####################] 8507/8507 bytes",
        "the new RS4 runs the archived set (response time 160 ms); the archive now names serial "
        "number 344865",
        "demo complete"}) {
    EXPECT_NE(text.find(line), std::string::npos) << "missing: " << line << "\n" << text;
  }
  EXPECT_EQ(text.find("FAILED"), std::string::npos) << text;
  if (std::getenv("RS4SIM_SHOW_DEMO") != nullptr) std::cout << text;
}

TEST(Rs4Run, MemoryLinkReachesDataExchange) {
  Rs4RunOptions o;
  o.device.address = 12;
  o.link.duration = 5;
  o.device.boot_time_ms = 1000;
  std::ostringstream out;
  EXPECT_EQ(run_rs4_device(o, out), 0) << out.str();
  EXPECT_NE(out.str().find("rs4 12: LED off"), std::string::npos) << out.str();
  EXPECT_NE(out.str().find("RS4 measuring"), std::string::npos) << out.str();
}

TEST(Rs4Run, BadArgumentsAreUsageErrors) {
  const auto bad = [](auto edit) {
    Rs4RunOptions o;
    edit(o);
    std::ostringstream out;
    EXPECT_THROW(run_rs4_device(o, out), UsageError);
  };
  bad([](Rs4RunOptions& o) { o.device.address = 127; });  // [RS4 manual §4.5]: must not be used
  bad([](Rs4RunOptions& o) { o.device.address = -1; });
  bad([](Rs4RunOptions& o) { o.device.boot_time_ms = -5; });
  // --link can: refused by the parser (app/cli/link_cli.h, cli_run_bad_link); the one
  // name-to-kind table knows no such link.
  EXPECT_FALSE(parse_link_kind("can"));
  bad([](Rs4RunOptions& o) { o.link.link = LinkKind::kSerial; });  // no --port
  bad([](Rs4RunOptions& o) {
    o.link.link = LinkKind::kUdp;
    o.link.listen = "127.0.0.1:5001";
  });  // no --peer
  bad([](Rs4RunOptions& o) {
    o.link.link = LinkKind::kPty;
    o.link.baud = "1234";
  });
  bad([](Rs4RunOptions& o) { o.link.duration = -1; });
  // Several RS4s (--address repeated): each address checked, none twice, --rs232 with one
  // only, no in-memory link (rs4sim master --slave ... simulates several).
  bad([](Rs4RunOptions& o) {
    o.link.link = LinkKind::kPty;
    o.device.more_addresses = {5, 127};
  });
  bad([](Rs4RunOptions& o) {
    o.link.link = LinkKind::kPty;
    o.device.address = 5;
    o.device.more_addresses = {6, 5};
  });
  bad([](Rs4RunOptions& o) {
    o.link.link = LinkKind::kPty;
    o.device.more_addresses = {4};  // the default address 4, given again
  });
  bad([](Rs4RunOptions& o) {
    o.link.link = LinkKind::kPty;
    o.device.more_addresses = {5};
    o.device.rs232 = "pty";
  });
  bad([](Rs4RunOptions& o) { o.device.more_addresses = {5}; });  // --link memory
}

}  // namespace
}  // namespace rs4sim::app
