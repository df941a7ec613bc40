// libFuzzer: ProxySync against the proxy tests' device double (tests/proxy/device_double.h),
// with the input choosing the scenario and, record by record, whether the device's answer
// passes faithfully, is mutated, refused, lost or replaced by arbitrary bytes; sometimes the
// machine is "restarted" through its retentive record. Must never crash, and:
//   - FB_BUSY is set exactly while the machine is active;
//   - ERROR_NUMBER_FB is 0 or one of the codes the manual lists ([RS4 manual §6.4]);
//   - when the device releases its OSSD (99 success) and the archive has a set, the device
//     holds exactly that set (never a release with an unverified set).
#include "proxy/proxy_sync.h"
#include "proxy/retentive.h"
#include "rs4/scanner/parameter_codec.h"
#include "storage/crc32.h"
#include "storage/sqlite_archive.h"
#include "tests/proxy/device_double.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <span>
#include <string>

namespace {

using namespace rs4sim;
using proxy::testing::DeviceDouble;

class Input {
 public:
  explicit Input(std::span<const std::uint8_t> bytes) : bytes_(bytes) {}
  std::uint8_t byte() { return pos_ < bytes_.size() ? bytes_[pos_++] : 0; }
  std::span<const std::uint8_t> take(std::size_t n) {
    n = std::min(n, bytes_.size() - pos_);
    const auto out = bytes_.subspan(pos_, n);
    pos_ += n;
    return out;
  }
  bool empty() const { return pos_ >= bytes_.size(); }

 private:
  std::span<const std::uint8_t> bytes_;
  std::size_t pos_ = 0;
};

bool listed(std::uint16_t code) {
  static constexpr std::uint16_t kListed[] = {
      0x0101, 0x0201, 0x0401, 0x0801, 0x1001, 0x1101, 0x2101, 0x2401, 0x2601, 0x2701, 0x2901,
      0x3201, 0x3301, 0x4001, 0x4501, 0x0301, 0x0501, 0x0601, 0x0701, 0x1201, 0x2201, 0x2301,
      0x2801, 0x3001, 0x3101, 0x3401, 0x4101, 0x5001, 0x0302, 0x0502, 0x0602, 0x0902, 0x1202,
      0x2202, 0x2302, 0x2802, 0x3002, 0x3102, 0x3402, 0x4102, 0x1301, 0x4201, 0x2501};
  return code == 0 || std::find(std::begin(kListed), std::end(kListed), code) != std::end(kListed);
}

// Sets differing in their response time steps 0..3, encoded once.
const std::vector<std::uint8_t>& variant_set(std::uint8_t steps) {
  static const auto kSets = [] {
    std::array<std::vector<std::uint8_t>, 4> sets;
    for (std::uint8_t i = 0; i < sets.size(); ++i) {
      auto set = rs4::scanner::factory_default();
      set.response_steps = i;
      sets[i] = rs4::scanner::encode(set);
    }
    return sets;
  }();
  return kSets[steps % kSets.size()];
}

void set_up(Input& in, DeviceDouble& dev, storage::ParameterArchive& archive,
            const storage::StationKey& station) {
  const std::uint8_t setup = in.byte();
  dev.direction = static_cast<rs4::protocol::SyncDirection>(1 + setup % 3);
  dev.factory = (setup & 0x04) != 0;
  dev.set = variant_set(static_cast<std::uint8_t>((setup >> 3) & 0x03));
  dev.not_ready_reads = (setup >> 5) & 0x01;
  if ((setup & 0x40) != 0) {
    const auto& blob = variant_set(static_cast<std::uint8_t>((setup >> 7) + 1));
    storage::StoreRequest r;
    r.station = station;
    r.serial_number = (setup & 0x80) != 0 ? "999" : "1001";
    r.blob = blob;
    r.crc32 = storage::crc32(blob);
    (void)archive.store(r);
  }
}

proxy::RecordResult answer(Input& in, DeviceDouble& dev, const proxy::RecordRequest& request) {
  const std::uint8_t c = in.byte();
  const auto* write = std::get_if<proxy::RecordWrite>(&request);
  switch (c % 8) {
    case 5: return proxy::RecordResult::negative(in.byte(), in.byte());
    case 6: return proxy::RecordResult::no_response();
    case 7: {  // arbitrary bytes as the record
      const auto n = in.byte();
      const auto bytes = in.take(n);
      return write != nullptr ? proxy::RecordResult::success()
                              : proxy::RecordResult::success({bytes.begin(), bytes.end()});
    }
    default: break;
  }
  auto r = write != nullptr ? dev.write(write->data)
                            : dev.read(std::get<proxy::RecordRead>(request).length);
  if (c % 8 == 4 && !r.data.empty()) r.data[in.byte() % r.data.size()] ^= in.byte();
  return r;
}

void check(const proxy::ProxySync& sync, const DeviceDouble& dev, bool released_before,
           storage::ParameterArchive& archive, const storage::StationKey& station) {
  const auto& out = sync.outputs();
  if (out.fb_busy != sync.active()) std::abort();
  if (!listed(out.error_number_fb)) std::abort();
  if (dev.released && !released_before) {
    const auto current = archive.current(station);
    if (current && current.value().set.blob != dev.set) std::abort();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Input in({data, size});
  // Opening an archive costs more than a run: one archive serves 1000 runs, each on a
  // station of its own.
  static std::unique_ptr<storage::SqliteArchive> archive;
  static std::uint64_t runs = 0;
  if (runs++ % 1000 == 0) archive = storage::SqliteArchive::open(":memory:").value();
  const storage::StationKey station{"bus" + std::to_string(runs), 4};
  DeviceDouble dev;
  set_up(in, dev, *archive, station);
  proxy::ProxySyncConfig config;
  config.station = station;
  auto sync = std::make_unique<proxy::ProxySync>(config, *archive);
  sync->set_proxy_enable(true);
  dp::TimePoint now{};
  for (int i = 0; i < 4000 && !in.empty(); ++i) {
    sync->set_input_byte(dev.input_byte());
    if (sync->ready(now)) sync->start(now);
    if (in.byte() == 0xFF) {  // restart through the retentive record
      const auto bytes = proxy::encode_retentive(sync->snapshot());
      sync = std::make_unique<proxy::ProxySync>(config, *archive);
      sync->set_proxy_enable(true);
      sync->restore(proxy::decode_retentive(bytes).value());
      continue;
    }
    const bool released = dev.released;
    if (auto request = sync->take_request(now)) {
      const auto result = answer(in, dev, *request);
      now += std::chrono::milliseconds(1 + in.byte() % 4);
      sync->on_record_result(result, now);
    } else {
      now = std::max(now + std::chrono::milliseconds(1), sync->next_wakeup().value_or(now));
      sync->tick(now);
    }
    check(*sync, dev, released, *archive, station);
  }
  return 0;
}
