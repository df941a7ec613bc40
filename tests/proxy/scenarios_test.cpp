// The four start-up scenarios of [RS4 manual §7.1, §7.2] and the proxy's other decisions
// (docs/proxy.md "Decisions"), against the device double and a real SqliteArchive.
#include "rs4/protocol/parameter_transfer.h"
#include "rs4/protocol/telegram.h"
#include "storage/crc32.h"
#include "tests/proxy/sync_harness.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace rs4sim::proxy::testing {
namespace {

using rs4::protocol::ProxyOutcome;
using rs4::protocol::SyncDirection;
using rs4::protocol::SyncReason;

// The commands written, in order (first block of each).
std::vector<std::uint8_t> commands(const std::vector<IssuedRecord>& issued) {
  std::vector<std::uint8_t> out;
  bool in_command = false;
  for (const auto& r : issued) {
    const auto* w = std::get_if<RecordWrite>(&r.request);
    if (w == nullptr) {
      in_command = false;
      continue;
    }
    if (!in_command && w->data.size() > 4) out.push_back(w->data[4]);
    in_command = true;
  }
  return out;
}

TEST(Scenario, FirstCommissioningLeavesFactorySettingsAndSaysSo) {
  SyncHarness h;
  h.device.factory = true;
  h.device.direction = SyncDirection::kDownload;
  ASSERT_TRUE(h.run_sync());
  const auto& out = h.sync->outputs();
  EXPECT_TRUE(out.config_set_to_default);
  EXPECT_EQ(out.error_number_fb, 0);
  EXPECT_FALSE(out.fb_busy);
  EXPECT_TRUE(h.device.released);
  EXPECT_EQ(h.device.set, DeviceDouble::factory_set());
  EXPECT_FALSE(h.real->current(SyncHarness::kStation));  // nothing learnt
  EXPECT_EQ(commands(h.issued), (std::vector<std::uint8_t>{0x98, 0x60, 0x60, 0x99}));
}

TEST(Scenario, ParameterChangeReplacesTheCurrentSetAndHistoryKeepsTheOld) {
  SyncHarness h;
  const auto old_set = SyncHarness::custom_set(3);
  const auto v1 = h.store(old_set, "1001");
  h.device_changed_to(SyncHarness::custom_set(5), SyncReason::kPcAdapterRemoved);
  ASSERT_TRUE(h.run_sync());
  EXPECT_EQ(h.sync->outputs(), FbOutputs{});
  EXPECT_TRUE(h.device.released);
  const auto current = h.real->current(SyncHarness::kStation).value();
  EXPECT_EQ(current.set.blob, h.device.set);
  EXPECT_EQ(current.version.source, storage::VersionSource::kUpload);
  EXPECT_EQ(current.version.serial_number, "1001");
  const auto history = h.real->history(SyncHarness::kStation).value();
  ASSERT_EQ(history.size(), 2u);
  EXPECT_EQ(history[0].id, v1.id);
  EXPECT_EQ(h.real->get(v1.id).value().set.blob, old_set);
  // Every chunk read twice.
  const auto cmds = commands(h.issued);
  EXPECT_EQ(std::count(cmds.begin(), cmds.end(), 0x61), 2 * 9);
}

// A user's parametrisation over PROFIBUS (reason 4, docs/proxy-protocol.md) is uploaded like a
// change through the PC adapter, and the sync log names it as such, not as a PC adapter removal.
TEST(Scenario, UserParametrisationIsUploadedUnderItsOwnReason) {
  SyncHarness h;
  h.store(SyncHarness::custom_set(3), "1001");
  h.device_changed_to(SyncHarness::custom_set(6), SyncReason::kUserParametrisation);
  ASSERT_TRUE(h.run_sync());
  EXPECT_EQ(h.sync->outputs(), FbOutputs{});
  EXPECT_EQ(h.real->current(SyncHarness::kStation).value().set.blob, h.device.set);
  const auto log = h.real->sync_log(SyncHarness::kStation, 10).value();
  ASSERT_FALSE(log.empty());
  EXPECT_EQ(log.front().reason, "user-parametrisation");
  EXPECT_EQ(log.front().direction, storage::SyncDirection::kUpload);
}

// What the proxy records with a version (docs/storage.md "What maintenance records"): the
// scenario as the comment, the master's user and host, the station's site and line.
TEST(Scenario, AnUploadRecordsItsScenarioWhoAndWhere) {
  SyncHarness h;
  h.config.recording = Recording{{"plc-team", "ws-maint-03"}, "Hamburg", "Press line 1", false};
  h.sync = std::make_unique<ProxySync>(h.config, h.archive);
  h.store(SyncHarness::custom_set(3), "1001");
  h.device_changed_to(SyncHarness::custom_set(5), SyncReason::kPcAdapterRemoved);
  ASSERT_TRUE(h.run_sync());
  const auto v = h.real->current(SyncHarness::kStation).value().version;
  EXPECT_EQ(v.note, "scenario 2, parameter change: the device's set uploaded by the proxy");
  EXPECT_EQ(v.user, "plc-team");
  EXPECT_EQ(v.host, "ws-maint-03");
  const auto stations = h.real->stations().value();
  ASSERT_EQ(stations.size(), 1u);
  EXPECT_EQ(stations[0].site, "Hamburg");
  EXPECT_EQ(stations[0].line, "Press line 1");
}

// --skip-identical: an upload of the set the archive already holds as current stores nothing
// (the sync itself succeeds and releases); without the option it is a new version.
TEST(Scenario, SkipIdenticalStoresNoVersionForAnUploadOfTheCurrentSet) {
  for (const bool skip : {true, false}) {
    SCOPED_TRACE(skip ? "skip_identical" : "default");
    SyncHarness h;
    h.config.recording.skip_identical = skip;
    h.sync = std::make_unique<ProxySync>(h.config, h.archive);
    const auto v1 = h.store(SyncHarness::custom_set(3), "1001");
    h.device_changed_to(SyncHarness::custom_set(3), SyncReason::kPcAdapterRemoved);
    ASSERT_TRUE(h.run_sync());
    EXPECT_EQ(h.sync->outputs(), FbOutputs{});
    EXPECT_TRUE(h.device.released);
    const auto history = h.real->history(SyncHarness::kStation).value();
    EXPECT_EQ(history.size(), skip ? 1u : 2u);
    EXPECT_EQ(h.real->current(SyncHarness::kStation).value().version.id == v1.id, skip);
  }
}

TEST(Scenario, NormalStartReleasesAtOnceThenVerifiesInTheBackground) {
  SyncHarness h;
  const auto set = h.store_the_devices_set();
  ASSERT_TRUE(h.run_sync());
  EXPECT_EQ(h.sync->outputs(), FbOutputs{});
  EXPECT_TRUE(h.device.released);
  const auto cmds = commands(h.issued);
  const auto end = std::find(cmds.begin(), cmds.end(), 0x99);
  const auto first_upload = std::find(cmds.begin(), cmds.end(), 0x61);
  ASSERT_NE(end, cmds.end());
  ASSERT_NE(first_upload, cmds.end());
  EXPECT_LT(end, first_upload);  // released before anything was uploaded
  EXPECT_EQ(std::vector<std::uint8_t>(cmds.begin(), end + 1),
            (std::vector<std::uint8_t>{0x98, 0x60, 0x60, 0x99}));
  EXPECT_EQ(std::count(cmds.begin(), cmds.end(), 0x61), 2 * 9);
  EXPECT_EQ(h.real->history(SyncHarness::kStation).value().size(), 1u);
  const auto log = h.real->sync_log(SyncHarness::kStation, 10).value();
  ASSERT_EQ(log.size(), 2u);
  EXPECT_EQ(log[0].outcome, storage::SyncOutcome::kSucceeded);
  EXPECT_EQ(log[0].reason, "power-up");
  EXPECT_EQ(log[1].reason, "background-verify");
}

TEST(Scenario, DeviceExchangeDownloadsTheStoredSetAndStoresTheNewSerial) {
  SyncHarness h;
  const auto set = SyncHarness::custom_set(3);
  h.store(set, "999");
  h.device.set = SyncHarness::custom_set(7);  // the new device's own set
  ASSERT_TRUE(h.run_sync());
  EXPECT_EQ(h.sync->outputs(), FbOutputs{});
  EXPECT_TRUE(h.device.released);
  EXPECT_EQ(h.device.set, set);
  const auto current = h.real->current(SyncHarness::kStation).value();
  EXPECT_EQ(current.version.serial_number, "1001");
  EXPECT_EQ(current.version.source, storage::VersionSource::kDownload);
  EXPECT_EQ(current.set.blob, set);
  const auto cmds = commands(h.issued);
  EXPECT_EQ(std::count(cmds.begin(), cmds.end(), 0x63), 9);
  EXPECT_EQ(cmds.back(), 0x99);
}

TEST(Scenario, FactoryDeviceWithAStoredSetGetsItBack) {
  SyncHarness h;
  const auto set = h.store_for_a_factory_device();
  ASSERT_TRUE(h.run_sync());
  EXPECT_EQ(h.sync->outputs(), FbOutputs{});
  EXPECT_EQ(h.device.set, set);
  EXPECT_EQ(h.real->history(SyncHarness::kStation).value().size(), 1u);  // same serial
}

TEST(Scenario, NoStoredSetOnVerifyLearnsTheDevicesSet) {
  SyncHarness h;
  h.device.set = SyncHarness::custom_set(4);
  ASSERT_TRUE(h.run_sync());
  EXPECT_EQ(h.real->current(SyncHarness::kStation).value().set.blob, h.device.set);
}

TEST(Scenario, PendingRestoreIsDownloadedAndMarkedDone) {
  SyncHarness h;
  const auto a = SyncHarness::custom_set(3);
  const auto b = SyncHarness::custom_set(4);
  const auto v1 = h.store(a, "1001");
  h.store(b, "1001");
  const auto restored = h.real->restore(v1.id, {}, "back to A").value();
  h.device.set = b;
  ASSERT_TRUE(h.run_sync());
  EXPECT_EQ(h.sync->outputs(), FbOutputs{});
  EXPECT_EQ(h.device.set, a);
  const auto current = h.real->current(SyncHarness::kStation).value();
  EXPECT_EQ(current.version.id, restored.id);
  EXPECT_FALSE(current.version.pending_download);
}

// [RS4 manual §5.1.1] bit 2 "Tritt während der Parameterkontrolle ein Fehler auf, wird es wieder
// auf 1 gesetzt": a failed background verify after the release is reported to the device with
// 99 failed (it rolls back and asks again), FB_BUSY drops, the failure is logged, and the retry
// downloads the stored set.
TEST(Scenario, FailedBackgroundVerifyTellsTheDeviceAndTheRetryRestores) {
  SyncHarness h;
  const auto set = h.store_the_devices_set();
  h.inject = Injection{Step::kVerifyUpload1, FailureKind::kRead};
  ASSERT_TRUE(h.run_sync());
  const auto& out = h.sync->outputs();
  EXPECT_EQ(out.error_number_fb, 0x5001);
  EXPECT_FALSE(out.fb_busy);
  EXPECT_TRUE(out.config_set_to_default) << "the device rolled back";
  const auto cmds = commands(h.issued);
  ASSERT_GE(cmds.size(), 6u);
  EXPECT_EQ(std::count(cmds.begin(), cmds.end(), 0x99), 2) << "99 success, then 99 failed";
  EXPECT_EQ(cmds.back(), 0x99);
  ASSERT_TRUE(h.device.last_end);
  EXPECT_EQ(h.device.last_end->outcome, ProxyOutcome::kFailed);
  EXPECT_TRUE(h.device.request) << "Proxy-Request again";
  EXPECT_FALSE(h.device.released);
  EXPECT_EQ(h.device.reason, SyncReason::kRetry);
  const auto log = h.real->sync_log(SyncHarness::kStation, 10).value();
  ASSERT_EQ(log.size(), 2u);
  EXPECT_EQ(log[1].reason, "background-verify");
  EXPECT_EQ(log[1].outcome, storage::SyncOutcome::kFailed);
  h.expect_retry_restores(set);
}

// ---- comparisons: the adapter error sent with 99 failed
TEST(Comparison, EchoCrcOfAChunkWrongBreaksTheDownload) {
  SyncHarness h;
  h.store_for_a_factory_device();
  int chunks = 0;
  h.device.answer_hook = [&](std::uint8_t cmd, std::vector<std::uint8_t>& answer) {
    if (cmd == 0x63 && ++chunks == 3) answer.back() ^= 0x01;  // echo CRC of chunk 2
  };
  ASSERT_TRUE(h.run_sync());
  EXPECT_EQ(h.sync->outputs().error_number_fb, 0x2302);
  EXPECT_TRUE(h.device.download_broken);
  ASSERT_TRUE(h.device.last_end);
  EXPECT_EQ(h.device.last_end->outcome, ProxyOutcome::kFailed);
  EXPECT_EQ(h.device.last_end->error, 0x2B12);
  EXPECT_TRUE(h.sync->outputs().config_set_to_default);
}

TEST(Comparison, ChunkDiffersOnReadRepetition) {
  SyncHarness h;
  h.device.set = SyncHarness::custom_set(5);
  h.device.direction = SyncDirection::kUpload;
  int uploads = 0;
  h.device.answer_hook = [&](std::uint8_t cmd, std::vector<std::uint8_t>& answer) {
    // chunk 4, second read: data and its CRC changed consistently
    if (cmd != 0x61 || ++uploads != 10) return;
    // 61 opt status chunk count len(2) crc(4) data: flip a data byte, fix the chunk's CRC
    answer[11] ^= 0xFF;
    const auto crc = storage::crc32(std::span(answer).subspan(11));
    for (int i = 0; i < 4; ++i)
      answer[7 + static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(crc >> (24 - 8 * i));
  };
  ASSERT_TRUE(h.run_sync());
  EXPECT_EQ(h.sync->outputs().error_number_fb, 0x1202);
  ASSERT_TRUE(h.device.last_end);
  EXPECT_EQ(h.device.last_end->error, 0x2B24);
  EXPECT_FALSE(h.real->current(SyncHarness::kStation));  // nothing stored
}

TEST(Comparison, ActiveCrcAfterCommitWrong) {
  SyncHarness h;
  h.store_for_a_factory_device();
  h.device.answer_hook = [](std::uint8_t cmd, std::vector<std::uint8_t>& answer) {
    if (cmd == 0x64) answer.back() ^= 0x01;
  };
  ASSERT_TRUE(h.run_sync());
  EXPECT_EQ(h.sync->outputs().error_number_fb, 0x2802);
  EXPECT_EQ(h.device.last_end->error, 0x2B09);
}

TEST(Comparison, IdentifyDiffersOnRepetition) {
  SyncHarness h;
  int identifies = 0;
  h.device.answer_hook = [&](std::uint8_t cmd, std::vector<std::uint8_t>& answer) {
    if (cmd == 0x60 && ++identifies == 2) answer.back() ^= 0x01;  // change counter
  };
  ASSERT_TRUE(h.run_sync());
  EXPECT_EQ(h.sync->outputs().error_number_fb, 0x0602);
  EXPECT_EQ(h.device.last_end->error, 0x2B09);
}

// ---- device refusals: ERROR_NUMBER_RS4
// A transfer answer whose status byte is not 0: the status is ERROR_NUMBER_RS4, the step's
// bad-record position is ERROR_NUMBER_FB (22 02: download begin [RS4 manual §6.4]).
TEST(DeviceRefusal, StatusByteIsErrorNumberRs4) {
  SyncHarness h;
  h.store_for_a_factory_device();
  h.device.answer_hook = [](std::uint8_t cmd, std::vector<std::uint8_t>& answer) {
    if (cmd != 0x62) return;
    rs4::protocol::TransferAnswer a;  // the RS4's refusal of a begin with another set size
    a.code = rs4::protocol::TransferCode::kDownloadBegin;
    a.options.state = rs4::protocol::Option1State::kMeasuring;
    a.status = rs4::protocol::TransferStatus::kSizeMismatch;
    answer = rs4::protocol::encode_answer(a).value();
  };
  ASSERT_TRUE(h.run_sync());
  const auto& out = h.sync->outputs();
  EXPECT_EQ(out.error_number_fb, 0x2202);
  EXPECT_EQ(out.error_number_rs4, 4);  // TransferStatus::kSizeMismatch
  EXPECT_FALSE(h.device.released);
}

// A user command aborted the sync on the device side ([RS4 manual §5.2]): the proxy's download
// begin then comes outside a sync, and the device answers it as the adapter does, with the RS4's
// error telegram 0x53 0503 (wrong password; bytes pinned in
// tests/rs4/adapter/proxy_commands_test.cpp, DownloadOutsideASyncIsRefused).
TEST(DeviceRefusal, DownloadOutsideTheSyncIsTheRs4sWrongPassword) {
  SyncHarness h;
  h.store_for_a_factory_device();
  std::vector<std::uint8_t> refusal;
  h.device.answer_hook = [&](std::uint8_t cmd, std::vector<std::uint8_t>& answer) {
    if (cmd == 0x60) h.device.sync_running = false;
    if (cmd == 0x62) refusal = answer;
  };
  ASSERT_TRUE(h.run_sync());
  ASSERT_GE(refusal.size(), 7U);
  EXPECT_EQ(refusal.front(), 0x53);
  EXPECT_EQ(std::vector<std::uint8_t>(refusal.end() - 6, refusal.end()),
            (std::vector<std::uint8_t>{0x05, 0x03, 0x00, 0x62, 0x00, 0x05}));
  const auto& out = h.sync->outputs();
  EXPECT_EQ(out.error_number_fb, 0x2202);
  EXPECT_EQ(out.error_number_rs4, 0x0503);
  EXPECT_FALSE(h.device.released);
}

TEST(DeviceRefusal, Rs4ErrorTelegramNumberIsErrorNumberRs4) {
  SyncHarness h;
  h.device.answer_hook = [](std::uint8_t cmd, std::vector<std::uint8_t>& answer) {
    if (cmd != 0x60) return;
    rs4::protocol::ErrorTelegram e;
    e.prefix.options.state = rs4::protocol::Option1State::kFault;
    e.report.number = 0x0123;
    answer = rs4::protocol::encode_telegram(e).value();
  };
  ASSERT_TRUE(h.run_sync());
  EXPECT_EQ(h.sync->outputs().error_number_fb, 0x0502);
  EXPECT_EQ(h.sync->outputs().error_number_rs4, 0x0123);
}

// ---- timing and enable
TEST(Timing, AnswerNotReadyIsPolled) {
  SyncHarness h;
  h.device.factory = true;
  h.device.direction = SyncDirection::kDownload;
  h.device.not_ready_reads = 3;
  const auto start = h.now;
  ASSERT_TRUE(h.run_sync());
  EXPECT_EQ(h.sync->outputs().error_number_fb, 0);
  EXPECT_TRUE(h.device.released);
  EXPECT_GE(h.now - start, 4 * 3 * h.config.timing.poll_interval);
}

TEST(Timing, NoAnswerInTimeIsAReadFailure) {
  SyncHarness h;
  h.device.answer_hook = [](std::uint8_t cmd, std::vector<std::uint8_t>& answer) {
    if (cmd == 0x60) answer.clear();
  };
  const auto start = h.now;
  ASSERT_TRUE(h.run_sync());
  EXPECT_EQ(h.sync->outputs().error_number_fb, 0x0501);
  EXPECT_EQ(h.sync->outputs().error_code_sfc, 0);
  EXPECT_GE(h.now - start, h.config.timing.answer_timeout);
}

TEST(Enable, NoSyncWithoutProxyEnable) {
  SyncHarness h;
  h.enable = false;
  EXPECT_FALSE(h.run_sync());
  EXPECT_EQ(h.device.commands, 0u);
}

TEST(Enable, NoSyncWithoutProxyRequest) {
  SyncHarness h;
  h.device.request = false;
  EXPECT_FALSE(h.run_sync());
}

TEST(Enable, StaleRequestStartsNothingAndWaits) {
  SyncHarness h;
  h.device.request = false;
  h.sync->set_input_byte(0x04);  // the master still sees the bit
  h.sync->set_proxy_enable(true);
  ASSERT_TRUE(h.sync->ready(h.now));
  h.sync->start(h.now);
  for (int i = 0; i < 20; ++i) {
    if (auto r = h.sync->take_request(h.now)) {
      const auto* w = std::get_if<RecordWrite>(&*r);
      h.sync->on_record_result(w != nullptr ? h.device.write(w->data) : h.device.read(240), h.now);
    }
  }
  EXPECT_FALSE(h.sync->active());
  EXPECT_EQ(h.sync->outputs(), FbOutputs{});
  EXPECT_FALSE(h.device.sync_running);
  EXPECT_FALSE(h.sync->ready(h.now));
  EXPECT_TRUE(h.sync->ready(h.now + h.config.retry_delay));
}

// [RS4 manual §6.5] "Es findet keine Kommunikation statt, solange der optische PC-Adapter am
// RS4/PROFIsafe angebracht ist": with input bit 3 set the FB does not start, even with
// Proxy-Request pending; it starts once bit 3 drops.
TEST(Enable, NoSyncWhileThePcAdapterIsAttached) {
  SyncHarness h;
  h.device.pc_adapter = true;
  ASSERT_TRUE(h.device.request);
  EXPECT_FALSE(h.run_sync());
  EXPECT_EQ(h.device.commands, 0u);
  h.device.pc_adapter = false;
  EXPECT_TRUE(h.run_sync());
}

// A PC adapter attached after the FB started (it saw Proxy-Request without bit 3): the READ shows
// flow state 010, and the FB stops at once — not after 2 × 130 s of polling (its READ and the
// failure report's) — with the READ position, sfc 0, no failure report and the flag kept.
TEST(Timing, FlowState010EndsTheSyncAtOnce) {
  SyncHarness h;
  h.device.pc_adapter = true;
  h.sync->set_input_byte(0x04);  // the byte of the cycle before bit 3 came
  h.sync->set_proxy_enable(true);
  ASSERT_TRUE(h.sync->ready(h.now));
  const auto start = h.now;
  h.sync->start(h.now);
  ASSERT_TRUE(h.resume());
  const auto& out = h.sync->outputs();
  EXPECT_EQ(out.error_number_fb, 0x0301) << "98: READ failed";
  EXPECT_EQ(out.error_code_sfc, 0);
  EXPECT_FALSE(out.fb_busy);
  EXPECT_FALSE(out.config_set_to_default);
  EXPECT_EQ(h.device.commands, 0u) << "the adapter ignored every WRITE";
  EXPECT_EQ(commands(h.issued), (std::vector<std::uint8_t>{0x98})) << "no failure report";
  EXPECT_LT(h.now - start, h.config.timing.poll_interval) << "one WRITE and one READ";
  EXPECT_FALSE(h.sync->ready(h.now + h.config.retry_delay)) << "bit 3 still set";
  h.device.pc_adapter = false;
  h.advance(h.config.retry_delay);
  EXPECT_TRUE(h.run_sync());
  EXPECT_EQ(h.sync->outputs().error_number_fb, 0);
}

TEST(Retry, FailedSyncIsRetriedAfterTheDelayAndSucceeds) {
  SyncHarness h;
  const auto set = h.store_the_devices_set();
  h.inject = Injection{Step::kIdentify1, FailureKind::kRead};
  ASSERT_TRUE(h.run_sync());
  EXPECT_EQ(h.sync->outputs().error_number_fb, 0x0501);
  EXPECT_TRUE(h.device.request);  // the device asks again (reason retry)
  EXPECT_FALSE(h.run_sync());     // too early
  h.expect_retry_restores(set);   // outputs reset, the stored set goes back
}

// [RS4 manual §6.4]: a new run of the FB resets ERROR_NUMBER_FB, ERROR_CODE_SFC and
// ERROR_NUMBER_RS4, not CONFIG_SET_TO_DEFAULT, which "kommt direkt vom Scanner": a device that
// rolled back after a failed download still reads 1 during the retry's download, and 0 once the
// stored set is in (the flag of the 99 answer).
TEST(Retry, ConfigSetToDefaultStaysOneThroughTheRetryDownload) {
  SyncHarness h;
  const auto set = SyncHarness::custom_set(3);
  h.store(set, "1001");
  h.device.set = SyncHarness::custom_set(7);  // another set: the stored one goes down
  h.inject = Injection{Step::kDownloadChunk, FailureKind::kWrite};
  ASSERT_TRUE(h.run_sync());
  ASSERT_EQ(h.sync->outputs().error_number_fb, 0x2401);
  ASSERT_TRUE(h.sync->outputs().config_set_to_default) << "the device rolled back";
  ASSERT_TRUE(h.device.factory);
  h.advance(h.config.retry_delay);
  ASSERT_TRUE(h.run_sync(Step::kDownloadChunk));
  const auto during = h.sync->outputs();
  EXPECT_TRUE(during.fb_busy);
  EXPECT_EQ(during.error_number_fb, 0) << "reset by the new run";
  EXPECT_EQ(during.error_code_sfc, 0);
  EXPECT_EQ(during.error_number_rs4, 0);
  EXPECT_TRUE(during.config_set_to_default) << "the device still holds its factory setting";
  ASSERT_TRUE(h.resume());
  EXPECT_EQ(h.sync->outputs(), FbOutputs{}) << "the 99 answer: no longer factory settings";
  EXPECT_EQ(h.device.set, set);
}

// A proxy that starts new (no earlier output) learns the flag from the device's 98 answer.
TEST(Retry, ConfigSetToDefaultComesFromTheBeginAnswer) {
  SyncHarness h;
  h.store_for_a_factory_device();
  ASSERT_FALSE(h.sync->outputs().config_set_to_default);
  ASSERT_TRUE(h.run_sync(Step::kDownloadBegin));
  EXPECT_TRUE(h.sync->outputs().config_set_to_default);
  ASSERT_TRUE(h.resume());
  EXPECT_FALSE(h.sync->outputs().config_set_to_default);
}

}  // namespace
}  // namespace rs4sim::proxy::testing
