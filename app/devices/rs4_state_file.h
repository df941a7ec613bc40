#pragma once
// `rs4sim run --state FILE`: one RS4's non-volatile memory (rs4/device/rs4_state.h) in a
// file. Read once at start (a missing file is a new unit; a file that cannot be read, is
// corrupt, newer or another device's is refused with its path and the reason and left as it
// is), written whenever the memory changed (a set written, another unit, other switches):
// a temporary file beside it, fsync, rename, so a crash leaves the old or the new file and
// never half of one.

#include "dp/station.h"
#include "rs4/device/rs4_state.h"

#include <optional>
#include <string>

namespace rs4sim::app {

class Rs4StateFile {
 public:
  // Throws std::runtime_error "state file PATH: reason" for a file that exists but is refused.
  explicit Rs4StateFile(std::string path);

  [[nodiscard]] const std::string& path() const noexcept { return path_; }
  // The memory read at start; nullopt for a new file.
  [[nodiscard]] const std::optional<rs4::device::Rs4State>& loaded() const noexcept {
    return loaded_;
  }
  // Writes the device's memory if it changed since the last write (or since the load). A
  // failed write is reported on stderr and tried again at the next change.
  void keep(const rs4::device::Rs4Device& device);

 private:
  bool write(const rs4::device::Rs4Device& device);

  std::string path_;
  std::optional<rs4::device::Rs4State> loaded_;
  std::optional<rs4::device::StateMark> written_;
  std::optional<rs4::device::StateMark> failed_;  // the memory a write failed for
};

// A dp::Station in front of an RS4's station chain that keeps its state file after every
// call the link makes (telegrams every master cycle, the scanner's deadlines every scan):
// a change reaches the file within one bus cycle or one scan.
class KeptStation final : public dp::Station {
 public:
  KeptStation(dp::Station& inner, const rs4::device::Rs4Device& device, Rs4StateFile& file)
      : inner_(inner), device_(device), file_(file) {}
  [[nodiscard]] std::uint8_t address() const override { return inner_.address(); }
  void on_telegram(const dp::fdl::Telegram& t, dp::TimePoint now) override {
    inner_.on_telegram(t, now);
    file_.keep(device_);
  }
  void on_time(dp::TimePoint now) override {
    inner_.on_time(now);
    file_.keep(device_);
  }
  [[nodiscard]] std::optional<dp::TimePoint> next_deadline() const override {
    return inner_.next_deadline();
  }
  std::optional<dp::fdl::Telegram> take_transmit() override { return inner_.take_transmit(); }
  void on_malformed_frame(std::error_code why) override { inner_.on_malformed_frame(why); }
  [[nodiscard]] std::uint16_t min_tsdr_bits() const override { return inner_.min_tsdr_bits(); }

 private:
  dp::Station& inner_;
  const rs4::device::Rs4Device& device_;
  Rs4StateFile& file_;
};

}  // namespace rs4sim::app
