// The retentive record (docs/proxy.md "Retentive record") and a restart mid-sync.
#include "proxy/retentive.h"

#include "storage/crc32.h"
#include "tests/proxy/sync_harness.h"

#include <gtest/gtest.h>

namespace rs4sim::proxy::testing {
namespace {

using Bytes = std::vector<std::uint8_t>;

TEST(Retentive, BytesAsDocumented) {
  RetentiveRecord r;
  r.state = RetentiveState::kSyncOpen;
  r.step = static_cast<std::uint8_t>(Step::kDownloadChunk);
  r.fb_busy = true;
  r.download_open = true;
  r.error_number_fb = 0x2302;
  r.error_code_sfc = 0xB500;
  r.error_number_rs4 = 0x0008;
  r.direction = 3;
  r.reason = 1;
  r.serial_number = 0x000003E9;
  r.set_crc32 = 0xCAFEBABE;
  const auto bytes = encode_retentive(r);
  const Bytes head{0x01,                    // format version
                   0x01,                    // state: sync open
                   0x0A,                    // step 10: download chunk
                   0x06,                    // flags: FB_BUSY, download open
                   0x23, 0x02,              // ERROR_NUMBER_FB
                   0xB5, 0x00,              // ERROR_CODE_SFC
                   0x00, 0x08,              // ERROR_NUMBER_RS4
                   0x03, 0x01,              // direction download, reason power-up
                   0x00, 0x00, 0x03, 0xE9,  // serial 1001
                   0xCA, 0xFE, 0xBA, 0xBE};
  ASSERT_EQ(Bytes(bytes.begin(), bytes.begin() + 20), head);
  const auto crc = storage::crc32(head);
  EXPECT_EQ(Bytes(bytes.begin() + 20, bytes.end()),
            (Bytes{static_cast<std::uint8_t>(crc >> 24), static_cast<std::uint8_t>(crc >> 16),
                   static_cast<std::uint8_t>(crc >> 8), static_cast<std::uint8_t>(crc)}));
  EXPECT_EQ(decode_retentive(bytes), r);
}

TEST(Retentive, RejectsDamagedRecords) {
  const auto good = encode_retentive({});
  EXPECT_TRUE(decode_retentive(good));
  EXPECT_FALSE(decode_retentive(std::span(good).first(23)));
  auto flipped = good;
  flipped[4] ^= 0x01;
  EXPECT_FALSE(decode_retentive(flipped));  // checksum
  auto version = good;
  version[0] = 2;
  EXPECT_FALSE(decode_retentive(version));
}

// A restart of rs4sim in the middle of a download: the restored machine never sends
// 99 success for the half-written set; it fails the sync (device to factory settings, asks
// again), and the next sync downloads the stored set completely.
TEST(Restart, MidDownloadFailsSafelyAndTheRetryRestoresTheSet) {
  SyncHarness h;
  const auto set = h.store_for_a_factory_device();
  ASSERT_TRUE(h.run_sync(Step::kDownloadCommit));  // all chunks written, commit not yet
  const auto saved = encode_retentive(h.sync->snapshot());
  EXPECT_EQ(saved[1], 0x01);  // sync open

  // "Restart": a new machine from the persisted bytes only.
  h.sync = std::make_unique<ProxySync>(h.config, h.archive);
  const auto record = decode_retentive(saved);
  ASSERT_TRUE(record);
  h.sync->restore(*record);
  h.device.request = false;  // a sync is still open on the device: no Proxy-Request
  ASSERT_TRUE(h.sync->ready(h.now));
  EXPECT_EQ(encode_retentive(h.sync->snapshot())[2], saved[2]);  // a second restart: same step
  const auto issued_before = h.issued.size();
  ASSERT_TRUE(h.run_sync());
  EXPECT_EQ(h.sync->outputs().error_number_fb, 0x2601);  // where it was cut: before COMMIT
  EXPECT_TRUE(h.sync->outputs().config_set_to_default);
  ASSERT_TRUE(h.device.last_end);
  EXPECT_EQ(h.device.last_end->outcome, rs4::protocol::ProxyOutcome::kFailed);
  EXPECT_FALSE(h.device.released);
  EXPECT_TRUE(h.device.download_broken);  // DOWNLOAD_BREAK first
  for (std::size_t i = issued_before; i < h.issued.size(); ++i) {
    const auto* w = std::get_if<RecordWrite>(&h.issued[i].request);
    if (w != nullptr && w->data[4] == 0x99) {
      EXPECT_NE(w->data[5], 0x00);  // never success
    }
  }
  // The device asks again (retry); after the delay the set goes back completely.
  h.expect_retry_restores(set);
}

TEST(Restart, DamagedRecordIsTakenAsAnOpenSync) {
  SyncHarness h;
  auto bytes = encode_retentive({});
  bytes[5] ^= 0xFF;
  const auto record = decode_retentive(bytes);
  EXPECT_FALSE(record);
  // The owner's rule (docs/proxy.md): no valid record → restore a kSyncOpen one.
  RetentiveRecord open;
  open.state = RetentiveState::kSyncOpen;
  h.sync->restore(open);
  h.device.request = false;
  ASSERT_TRUE(h.run_sync());
  EXPECT_FALSE(h.device.sync_running);
  EXPECT_FALSE(h.device.released);
}

TEST(Restart, IdleRecordRestoresOutputsOnly) {
  SyncHarness h;
  RetentiveRecord r;
  r.error_number_fb = 0x0501;
  r.config_set_to_default = true;
  h.sync->restore(r);
  EXPECT_FALSE(h.sync->active());
  EXPECT_EQ(h.sync->outputs().error_number_fb, 0x0501);
  EXPECT_TRUE(h.sync->outputs().config_set_to_default);
  h.device.request = false;
  EXPECT_FALSE(h.sync->ready(h.now));
}

}  // namespace
}  // namespace rs4sim::proxy::testing
