// `rs4sim archive show` names a device one way (issue: the header said serial 74565 while the
// parameters said "device type 0 / serial 0"): the proxy archives the transfer form, whose
// identity is zero, and records the device it came from; show takes the identity from there.
#include "tests/app/archive_cli_fixture.h"

namespace rs4sim::app::testing {
namespace {

// The version as the proxy stores it: the transfer form, device type "0x0004" as its text of
// the IDENTIFY answer's word 4, serial 74565 (0x00012345, the simulated unit's default).
void store_demo_version(const std::filesystem::path& archive) {
  auto a = storage::SqliteArchive::open(archive).value();
  auto set = rs4::scanner::factory_default();
  set.identity = {};  // the transfer form carries no identity (docs/rs4-scanner.md)
  const auto blob = rs4::scanner::encode_for_transfer(set);
  storage::StoreRequest r;
  r.station = {"demo", 4};
  r.device_type = "0x0004";
  r.serial_number = "74565";
  r.blob = blob;
  r.crc32 = rs4::scanner::transfer_checksum(set);
  r.summary = rs4::report::summary_json(set);
  r.at = storage::Timestamp{std::chrono::milliseconds{1'764'600'000'000}};
  ASSERT_TRUE(a->store(r));
}

// One form everywhere (docs/archive-cli.md "Identity"): device type "0x0004", serial number
// "74565", under the names "device type" / "serial number" (DEVICE TYPE / SERIAL NUMBER,
// device_type / serial_number), in list, history and show, as text and as JSON; show's
// parameters name the device the version records, not the transfer form's zeros.
TEST_F(ArchiveCli, IdentityIsTheSameTextInListHistoryShowAndJson) {
  store_demo_version(archive_);
  const auto list = run("list");
  ASSERT_EQ(list.exit_code, 0) << list.err;
  EXPECT_NE(list.out.find("DEVICE TYPE  SERIAL NUMBER"), std::string::npos) << list.out;
  EXPECT_NE(list.out.find("demo        4  0x0004       74565  "), std::string::npos) << list.out;
  const auto history = run("history --bus demo --address 4");
  EXPECT_NE(history.out.find("  SERIAL NUMBER  "), std::string::npos) << history.out;
  EXPECT_NE(history.out.find("  74565  "), std::string::npos) << history.out;
  const auto show = run("show --bus demo --address 4");
  EXPECT_NE(show.out.find(", serial number 74565\n"), std::string::npos) << show.out;
  EXPECT_NE(show.out.find("  device type          0x0004\n"), std::string::npos) << show.out;
  EXPECT_NE(show.out.find("  serial number        74565\n"), std::string::npos) << show.out;

  const auto list_json = parse_json(run("list --json").out);
  const ptree* demo = nullptr;
  for (const auto& [key, s] : list_json.get_child("stations")) {
    if (s.get<std::string>("bus") == "demo") demo = &s;
  }
  ASSERT_NE(demo, nullptr);
  EXPECT_EQ(demo->get<std::string>("device_type"), "0x0004");
  EXPECT_EQ(at(demo->get_child("serial_numbers"), 0).get_value<std::string>(), "74565");
  EXPECT_EQ(demo->get<std::string>("current.serial_number"), "74565");
  const auto show_json = run("show --bus demo --address 4 --json").out;
  EXPECT_NE(show_json.find(R"("device_type":"0x0004","serial_number":"74565")"),
            std::string::npos)
      << show_json;
  const auto doc = parse_json(show_json);
  EXPECT_EQ(doc.get<std::string>("version.serial_number"), "74565");
  EXPECT_EQ(doc.get<std::string>("parameters.serial_number"), "74565");
}

}  // namespace
}  // namespace rs4sim::app::testing
