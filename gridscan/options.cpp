#include "gridscan/options.h"

#include "gridscan/scene.h"

#include <algorithm>
#include <cctype>

namespace rs4sim::gridscan {
namespace {

using namespace std::chrono_literals;

bool is_version(const std::string& v) {
  const auto digit = [](char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; };
  return v.size() == 5 && digit(v[0]) && digit(v[1]) && v[2] == '.' && digit(v[3]) && digit(v[4]);
}

bool is_part_number(const std::string& p) {
  return p.size() == 6 &&
         std::ranges::all_of(p, [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
}

std::string validate_scene(const Options& o) {
  if (o.door_position && *o.door_position > o.elements) {
    return "door position " + std::to_string(*o.door_position) + " outside 0.." +
           std::to_string(o.elements);
  }
  if ((o.blocked & ~element_mask(o.elements)) != 0) {
    return "blocked elements beyond element " + std::to_string(o.elements);
  }
  if (o.soiling > 3) return "soiling level " + std::to_string(o.soiling) + " outside 0..3";
  return {};
}

}  // namespace

std::string Options::validate() const {
  if (elements < kMinElements || elements > kMaxElements) {
    return "elements " + std::to_string(elements) + " outside 12..60";
  }
  if (!is_version(sw_version)) return "SW version \"" + sw_version + "\" is not xx.yy";
  if (!is_version(hw_version)) return "HW version \"" + hw_version + "\" is not xx.yy";
  if (!is_part_number(part_number)) {
    return "part number \"" + part_number + "\" is not 6 digits";
  }
  if (cycle && (*cycle < 1ms || *cycle > 1s)) return "cycle time outside 1 ms..1 s";
  if (ready_time < 0ms || ready_time > 60s) return "power-up time outside 0..60 s";
  if (config_window < 0s) return "configuration window negative";
  if (!(idle_gap_chars >= 1.0 && idle_gap_chars <= 100.0)) {
    return "idle gap outside 1..100 character times";
  }
  if (idle_gap() >= cycle_time()) return "idle gap not shorter than the cycle time";
  return validate_scene(*this);
}

stream::Duration typical_cycle(unsigned elements) {
  // 30 ms at 22, 62 ms at 60 ([GridScan manual §11], Table 1, typical), in microseconds.
  const auto us = 30000 + (static_cast<long long>(elements) - 22) * 32000 / 38;
  return std::chrono::microseconds(us);
}

CycleRange cycle_range(unsigned elements) {
  // min 18 + (N-22)*30/38 ms, max 40 + (N-22)*36/38 ms, in microseconds.
  const auto n = static_cast<long long>(elements) - 22;
  return {std::chrono::microseconds(18000 + n * 30000 / 38),
          std::chrono::microseconds(40000 + n * 36000 / 38)};
}

std::string check_cycle(unsigned elements, stream::Duration cycle) {
  const CycleRange r = cycle_range(elements);
  if (cycle >= r.min && cycle <= r.max) return {};
  const auto ms = [](stream::Duration d) {
    const auto us = std::chrono::duration_cast<std::chrono::microseconds>(d).count();
    std::string s = std::to_string(us / 1000);
    if (us % 1000 != 0) {
      std::string frac = std::to_string(1000 + us % 1000).substr(1);
      while (frac.back() == '0') frac.pop_back();
      s += "." + frac;
    }
    return s;
  };
  return "t_CYCLE " + ms(cycle) + " ms outside " + ms(r.min) + ".." + ms(r.max) + " ms for " +
         std::to_string(elements) + " elements [GridScan manual §11]";
}

stream::Duration Options::cycle_time() const { return cycle.value_or(typical_cycle(elements)); }

stream::Duration Options::idle_gap() const {
  return stream::character_time(kLineSettings, idle_gap_chars);
}

}  // namespace rs4sim::gridscan
