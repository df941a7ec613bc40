// The capture file format, byte for byte. Known answers: the libpcap file format
// (tcpdump.org "pcap-savefile", nanosecond magic 0xA1B23C4D, version 2.4) and the link-layer
// type numbers of tcpdump.org "linktypes" (LINKTYPE_USER0 = 147, LINKTYPE_PROFIBUS_DL = 257).
#include "dp/link/pcap.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

namespace rs4sim::dp::link {
namespace {

using Bytes = std::vector<std::uint8_t>;

TEST(Pcap, FileHeaderOfUser0) {
  const auto h = pcap_file_header(PcapLinkType::kUser0);
  const Bytes expected{
      0x4D, 0x3C, 0xB2, 0xA1,  // magic 0xA1B23C4D little-endian: nanosecond timestamps
      0x02, 0x00,              // version major 2
      0x04, 0x00,              // version minor 4
      0x00, 0x00, 0x00, 0x00,  // thiszone 0 (UTC)
      0x00, 0x00, 0x00, 0x00,  // sigfigs 0
      0xFF, 0xFF, 0x00, 0x00,  // snap length 65535
      0x93, 0x00, 0x00, 0x00,  // link type 147 LINKTYPE_USER0
  };
  EXPECT_EQ(Bytes(h.begin(), h.end()), expected);
  const auto dl = pcap_file_header(PcapLinkType::kProfibusDl);
  EXPECT_EQ(dl[20], 0x01);  // 257 = 0x0101
  EXPECT_EQ(dl[21], 0x01);
}

TEST(Pcap, RecordCarriesTheFrameAndANanosecondTimestamp) {
  // FDL status request of master 1 to station 4, SD1 ([IEC 61158-4-3 frame formats]):
  // 10 DA SA FC FCS 16
  const Bytes frame{0x10, 0x04, 0x01, 0x49, 0x4E, 0x16};
  Bytes out;
  append_pcap_record(out, frame,
                     std::chrono::seconds(1'700'000'000) + std::chrono::nanoseconds(123'456'789));
  const Bytes expected{
      0x00, 0xF1, 0x53, 0x65,  // seconds 1700000000 = 0x6553F100
      0x15, 0xCD, 0x5B, 0x07,  // nanoseconds 123456789 = 0x075BCD15
      0x06, 0x00, 0x00, 0x00,  // captured length 6
      0x06, 0x00, 0x00, 0x00,  // original length 6
      0x10, 0x04, 0x01, 0x49, 0x4E, 0x16,
  };
  EXPECT_EQ(out, expected);
  Bytes negative;
  append_pcap_record(negative, frame, std::chrono::nanoseconds(-5));
  EXPECT_EQ(Bytes(negative.begin(), negative.begin() + 8), Bytes(8, 0x00));
}

TEST(Pcap, FileIsHeaderThenRecordsAndReportsOpenErrors) {
  const auto path = std::filesystem::temp_directory_path() / "rs4sim_pcap_test.pcap";
  {
    PcapFile file;
    ASSERT_FALSE(PcapFile::open(path, PcapLinkType::kUser0, file));
    const Bytes sc{0xE5};  // short acknowledge
    ASSERT_FALSE(file.write(sc, std::chrono::milliseconds(2)));
    ASSERT_FALSE(file.write(sc, std::chrono::milliseconds(3)));
    EXPECT_EQ(file.records(), 2U);
  }
  std::ifstream in(path, std::ios::binary);
  const Bytes all((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_EQ(all.size(), kPcapFileHeaderSize + 2 * (kPcapRecordHeaderSize + 1));
  EXPECT_EQ(all[kPcapFileHeaderSize + 4], 0x80);  // 2 ms = 2000000 ns = 0x001E8480
  EXPECT_EQ(all.back(), 0xE5);
  std::filesystem::remove(path);

  PcapFile bad;
  EXPECT_EQ(PcapFile::open("/nonexistent-dir/x.pcap", PcapLinkType::kUser0, bad),
            std::errc::no_such_file_or_directory);
  EXPECT_TRUE(bad.write(Bytes{0xE5}, std::chrono::seconds(0)));
}

// Records reach the file at the first record, then whenever 100 ms of record time passed, on
// flush() and when the file is closed: a viewer of the growing file lags at most 100 ms of
// link time.
TEST(Pcap, RecordsReachTheFileWithin100MsOfRecordTime) {
  const auto path = std::filesystem::temp_directory_path() / "rs4sim_pcap_flush_test.pcap";
  const auto on_disk = [&] { return std::filesystem::file_size(path); };
  constexpr auto kOne = kPcapRecordHeaderSize + 1;
  const Bytes sc{0xE5};
  {
    PcapFile file;
    ASSERT_FALSE(PcapFile::open(path, PcapLinkType::kUser0, file));
    EXPECT_EQ(on_disk(), kPcapFileHeaderSize);
    ASSERT_FALSE(file.write(sc, std::chrono::milliseconds(0)));
    EXPECT_EQ(on_disk(), kPcapFileHeaderSize + kOne) << "the first record";
    ASSERT_FALSE(file.write(sc, std::chrono::milliseconds(99)));
    EXPECT_EQ(on_disk(), kPcapFileHeaderSize + kOne) << "99 ms later: buffered";
    ASSERT_FALSE(file.write(sc, std::chrono::milliseconds(100)));
    EXPECT_EQ(on_disk(), kPcapFileHeaderSize + 3 * kOne) << "100 ms later: written";
    ASSERT_FALSE(file.write(sc, std::chrono::milliseconds(101)));
    ASSERT_FALSE(file.flush());
    EXPECT_EQ(on_disk(), kPcapFileHeaderSize + 4 * kOne) << "flush()";
    ASSERT_FALSE(file.write(sc, std::chrono::milliseconds(102)));
  }
  EXPECT_EQ(on_disk(), kPcapFileHeaderSize + 5 * kOne) << "closed";
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace rs4sim::dp::link
