// Device entry `polaris`: the virtual Optoscan Polaris measuring barrier with the RS485
// Modbus RTU output (polaris/device.h, docs/polaris.md), on pty, serial or UDP, 8N1 at
// 19200..115200 ([Polaris manual §8.1]). The flags fill a polaris::Options; its validate()
// has the last word.
//
//   rs4sim run --device polaris --link pty --model PL10 --beams 40 --mode FL4 --address 1
//   rs4sim run --device polaris --link memory --grpc 127.0.0.1:50051   (the simulated clock)
//              --baud 19200 --blocked 9-13,25-34
//   rs4sim run --device polaris --link pty --mode FL4,master,start=0,scan-time=20
//   --mode: a data mode (485MB | FL1 | FL4 | FL10), optionally followed by comma-separated
//           words, the PC tool's settings [Polaris manual §7.4.2]: slave | master,
//           direct | reverse, object | hole, lsb | msb (485MB bit order), nak | no-nak
//           (exception 07 on a CRC error or a bad function, or standard Modbus),
//           start=<register> (decimal or 0x hex), scan-time=<ms>, pn2-filter=<scans>
#include "app/devices/device_options.h"
#include "app/devices/device_registry.h"
#include "app/devices/line_segment.h"
#include "app/runtime/usage_error.h"
#include "modbus/rtu_frame.h"
#include "polaris/device.h"
#include "rpc/device_target.h"
#include "rpc/polaris_service.h"
#include "rpc/rs4_services.h"

#include <charconv>
#include <ostream>
#include <sstream>

namespace rs4sim::app {
namespace {

// The number after "key=" in a --mode word: decimal, or hex after 0x when `hex` (register
// numbers); at most `max`. The range of the setting is Options::validate()'s.
std::uint32_t mode_number(const std::string& mode, const std::string& word, std::size_t key_size,
                          std::uint32_t max, bool hex, const std::string& what) {
  std::string_view digits = std::string_view(word).substr(key_size);
  int base = 10;
  if (hex && (digits.starts_with("0x") || digits.starts_with("0X"))) {
    digits.remove_prefix(2);
    base = 16;
  }
  std::uint32_t value = 0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value, base);
  if (digits.empty() || ec != std::errc{} || end != digits.data() + digits.size() || value > max) {
    throw UsageError("--mode " + mode + ": '" + word + "': " + what);
  }
  return value;
}

// One word after the data mode: a role, direction, detection, bit order or error mode
// word, or key=value. False: not one of them.
bool apply_mode_word(const std::string& mode, const std::string& word, polaris::Options& p) {
  if (word == "slave" || word == "master") {
    p.role = word == "slave" ? polaris::Role::kSlave : polaris::Role::kMaster;
  } else if (word == "direct" || word == "reverse") {
    p.direction =
        word == "direct" ? polaris::ScanDirection::kDirect : polaris::ScanDirection::kReverse;
  } else if (word == "object" || word == "hole") {
    p.detection = word == "object" ? polaris::Detection::kObject : polaris::Detection::kHole;
  } else if (word == "lsb" || word == "msb") {
    p.bit_order = word == "lsb" ? polaris::BitOrder::kLsbFirst : polaris::BitOrder::kMsbFirst;
  } else if (word == "nak" || word == "no-nak") {
    p.nak_on_error = word == "nak";
  } else if (word.starts_with("start=")) {
    p.start_address = static_cast<std::uint16_t>(
        mode_number(mode, word, 6, 0xFFFF, true,
                    "start= takes a register number 0..65535 (slave: 500..12287), e.g. "
                    "start=8192 or start=0x2000"));
  } else if (word.starts_with("scan-time=")) {
    p.scan_time = std::chrono::milliseconds(
        mode_number(mode, word, 10, 0xFFFFFFFF, false,
                    "scan-time= takes milliseconds, 5..5000, e.g. scan-time=100"));
  } else if (word.starts_with("pn2-filter=")) {
    p.pn2_filter = static_cast<std::uint16_t>(
        mode_number(mode, word, 11, 0xFFFF, false, "pn2-filter= takes a number of scans, 1..255"));
  } else {
    return false;
  }
  return true;
}

void apply_mode(const std::string& mode, polaris::Options& p) {
  std::istringstream words(mode);
  std::string word;
  bool first = true;
  while (std::getline(words, word, ',')) {
    if (first) {
      const auto m = polaris::parse_data_mode(word);
      if (!m)
        throw UsageError("--mode " + mode + ": '" + word + "' is not 485MB, FL1, FL4 or FL10");
      p.mode = *m;
      first = false;
    } else if (!apply_mode_word(mode, word, p)) {
      throw UsageError("--mode " + mode + ": '" + word +
                       "' is none of slave, master, direct, reverse, object, hole, lsb, msb, "
                       "nak, no-nak, start=, scan-time=, pn2-filter=");
    }
  }
}

polaris::Options polaris_options(const DeviceOptions& o) {
  polaris::Options p;
  if (!o.model.empty()) {
    const auto f = polaris::parse_family(o.model);
    if (!f)
      throw UsageError("--model " + o.model + ": use PLi02, PLi05, PLi12, PL10, PL24 or PL48");
    p.family = *f;
  }
  if (o.beams) {
    if (*o.beams < 1 || *o.beams > 0xFFFF) {
      throw UsageError("--beams " + std::to_string(*o.beams) + ": out of range");
    }
    p.beams = static_cast<std::uint16_t>(*o.beams);
  }
  if (o.address) {
    if (!modbus::is_slave_address(*o.address)) {
      throw UsageError("--address " + std::to_string(*o.address) + ": a Modbus address is " +
                       std::to_string(modbus::kMinSlaveAddress) + ".." +
                       std::to_string(modbus::kMaxSlaveAddress) +
                       " [Modbus serial line V1.02 §2.2]");
    }
    p.address = static_cast<std::uint8_t>(*o.address);
  }
  if (o.baud) p.baud = *o.baud;
  if (!o.mode.empty()) apply_mode(o.mode, p);
  if (const auto why = p.validate(); !why.empty()) throw UsageError("polaris: " + why);
  check_blocked(o, p.beams, "beams");
  return p;
}

// --blocked as beam numbers (check_blocked() has checked them), empty without it.
std::vector<std::uint16_t> blocked_beams(const DeviceOptions& o) {
  std::vector<std::uint16_t> beams;
  if (o.blocked) {
    for (const int b : *o.blocked) beams.push_back(static_cast<std::uint16_t>(b));
  }
  return beams;
}

// The status line at the end of a run.
void print_line_status(std::ostream& out, const polaris::Device& device_,
                       const stream::ByteCounters& c) {
  const auto& k = device_.counters();
  out << "polaris: requests " << k.requests << ", CRC errors " << k.crc_errors << ", too short "
      << k.too_short << ", oversized " << k.oversized << ", broadcasts " << k.broadcasts
      << ", other addresses " << k.foreign_address << ", bad function " << k.bad_function
      << ", bad request " << k.bad_request << ", bad start " << k.bad_start << ", busy " << k.busy
      << ", configuration writes " << k.writes << " (refused " << k.refused_writes
      << "), calibrations " << device_.calibrations() << ", exceptions sent "
      << k.exceptions_sent << ", frames sent " << k.frames_sent << ", bytes received "
      << c.bytes_received << ", sent " << c.bytes_sent << ", link errors " << c.link_errors
      << std::endl;
}

class PolarisInstance final : public DeviceInstance {
 public:
  explicit PolarisInstance(const DeviceOptions& o)
      : device_(polaris_options(o)), blocked_(blocked_beams(o)) {}
  std::vector<stream::ByteDevice*> byte_devices() override { return {&tap_}; }
  [[nodiscard]] stream::LineProtocol line_protocol() const override {
    return stream::LineProtocol::kModbusRtu;
  }
  void start(dp::TimePoint now) override {
    (void)device_.set_interrupted(blocked_, now);  // checked against the beam count in validate
  }
  // SIGUSR1: the autocal input's pulse, an auto-calibration of 0.4 s per beam
  // [Polaris manual §7.2] (data reads answer exception 06 meanwhile); ignored while one runs.
  void on_user_signal(bool second, dp::TimePoint now) override {
    if (!second) (void)device_.start_calibration(now);
  }
  [[nodiscard]] std::string describe() const override {
    const auto& p = device_.options();
    return "Polaris " + std::string(polaris::to_string(p.family)) + " (" + std::to_string(p.beams) +
           " beams, " + std::string(polaris::to_string(p.mode)) + ", " +
           (p.role == polaris::Role::kSlave ? "Modbus slave " : "Modbus master to slave ") +
           std::to_string(p.address) + ", " + stream::to_string(device_.line_settings()) +
           "; SIGUSR1 starts an auto-calibration)";
  }
  void print_byte_status(std::ostream& out, const stream::ByteCounters& c) const override {
    print_line_status(out, device_, c);
  }

  // rs4sim.v1.Polaris at its Modbus address, and Observation for the event stream.
  ServiceList services(const ServiceContext& c) override {
    const std::uint8_t address = device_.options().address;
    target_ = std::make_unique<rpc::LineDeviceTarget>(
        "polaris", rpc::polaris_watcher(address, device_), c.clock, c.io);
    tap_.set_hub(target_->events(), address);
    const rpc::LineContext line{c.executor, c.clock, address, tap_, target_->events()};
    return {std::make_shared<rpc::PolarisService>(line, device_),
            std::make_shared<rpc::ObservationService>(rpc::RunContext{*target_, c.executor})};
  }
  void stop_services() override {
    if (target_) target_->stop();
  }

 private:
  polaris::Device device_;
  rpc::TappedByteDevice tap_{device_};
  std::unique_ptr<rpc::LineDeviceTarget> target_;
  std::vector<std::uint16_t> blocked_;
};

// --link memory: the device alone on the simulated line, driven through the API
// (docs/polaris.md "Simulated clock"), at its Modbus address.
using PolarisSegment = LineSegment<polaris::Device, rpc::PolarisService>;
const LineDevice<polaris::Device> kPolarisLine{
    .kind = "polaris",
    .protocol = stream::LineProtocol::kModbusRtu,
    .address = [](const polaris::Device& d) { return d.options().address; },
    .watcher = rpc::polaris_watcher,
    .print_status = print_line_status,
};

void validate(DeviceOptions& o) {
  refuse_unused(o, "polaris",
                {DeviceFlag::kAddress, DeviceFlag::kBaud, DeviceFlag::kBeams, DeviceFlag::kModel,
                 DeviceFlag::kMode, DeviceFlag::kBlocked});
  (void)polaris_options(o);  // throws UsageError with the reason
}

}  // namespace

DeviceEntry polaris_device_entry() {
  return {
      .name = "polaris",
      .validate = validate,
      .build = [](const DeviceOptions& o) { return std::make_unique<PolarisInstance>(o); },
      .simulate =
          [](const DeviceOptions& o) {
            auto segment = std::make_unique<PolarisSegment>(kPolarisLine, polaris_options(o));
            if (o.blocked) {  // checked against the beam count in validate
              (void)segment->device().set_interrupted(blocked_beams(o), segment->now());
            }
            return segment;
          },
      .demo = run_polaris_demo,
      .byte_device = true,
  };
}

}  // namespace rs4sim::app
