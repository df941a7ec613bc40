// `rs4sim archive show` names a device one way (issue: the header said serial 74565 while the
// parameters said "device type 0 / serial 0"): the proxy archives the transfer form, whose
// identity is zero, and records the device it came from; show takes the identity from there.
#include "tests/app/archive_cli_fixture.h"

namespace rs4sim::app::testing {
namespace {

TEST_F(ArchiveCli, ShowNamesTheDeviceTheVersionRecordsNotTheTransferFormsZeros) {
  {
    auto a = storage::SqliteArchive::open(archive_).value();
    auto set = rs4::scanner::factory_default();
    set.identity = {};  // the transfer form carries no identity (docs/rs4-scanner.md)
    const auto blob = rs4::scanner::encode_for_transfer(set);
    storage::StoreRequest r;
    r.station = {"demo", 4};
    r.device_type = "0x0004";  // as the proxy records the IDENTIFY answer's device type
    r.serial_number = "74565";
    r.blob = blob;
    r.crc32 = rs4::scanner::transfer_checksum(set);
    r.summary = rs4::report::summary_json(set);
    r.at = storage::Timestamp{std::chrono::milliseconds{1'764'600'000'000}};
    ASSERT_TRUE(a->store(r));
  }
  const auto r = run("show --bus demo --address 4");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("  device type          4\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("  serial number        74565\n"), std::string::npos) << r.out;
  const auto doc = parse_json(run("show --bus demo --address 4 --json").out);
  EXPECT_EQ(doc.get<std::string>("version.serial_number"), "74565");
  EXPECT_EQ(doc.get<std::string>("parameters.serial_number"), "74565");
}

}  // namespace
}  // namespace rs4sim::app::testing
