// The position map of docs/proxy.md ([RS4 manual §6.4], ERROR_NUMBER_FB).
#include "proxy/positions.h"

#include <array>

namespace rs4sim::proxy {

namespace {
struct Entry {
  std::string_view name;
  StepPositions at;
};
// Indexed by Step. The manual's lists ([RS4 manual §6.4]): write failures 02 04 08 10 11 21
// 24 26 27 29 32 33 40 45; read failures 03 05 06 07 12 22 23 28 30 31 34 41 50; bad records
// 03 05 06 09 12 22 23 28 30 31 34 41; copies 01 25 (load → work) and 13 42 (work → load).
constexpr std::array<Entry, kStepCount> kMap{{
    {"idle", {}},
    {"load current set", {0, 0, 0, 0x01}},
    {"proxy begin", {0x02, 0x03, 0x03, 0}},
    {"identify", {0x04, 0x05, 0x05, 0}},
    {"identify (repeat)", {0x04, 0x06, 0x06, 0}},
    {"upload chunk", {0x08, 0x07, 0x09, 0}},
    {"upload chunk (repeat)", {0x10, 0x12, 0x12, 0}},
    {"store uploaded set", {0, 0, 0, 0x13}},
    {"load set to download", {0, 0, 0, 0x25}},
    {"download begin", {0x21, 0x22, 0x22, 0}},
    {"download chunk", {0x24, 0x23, 0x23, 0}},
    {"download commit", {0x26, 0x28, 0x28, 0}},
    {"identify after download", {0x27, 0x30, 0x30, 0}},
    {"identify after download (repeat)", {0x29, 0x31, 0x31, 0}},
    {"store serial number", {0, 0, 0, 0x42}},
    {"proxy end", {0x40, 0x41, 0x41, 0}},
    {"verify: identify", {0x32, 0x34, 0x34, 0}},
    {"verify: identify (repeat)", {0x33, 0x34, 0x34, 0}},
    {"verify: upload chunk", {0x11, 0x50, 0x34, 0}},
    {"verify: upload chunk (repeat)", {0x45, 0x50, 0x34, 0}},
    {"download break", {}},
    {"proxy end (failed)", {}},
    {"retry wait", {}},
}};
}  // namespace

StepPositions positions(Step step) noexcept {
  const auto i = static_cast<std::size_t>(step);
  return i < kMap.size() ? kMap[i].at : StepPositions{};
}

std::string_view to_string(Step step) noexcept {
  const auto i = static_cast<std::size_t>(step);
  return i < kMap.size() ? kMap[i].name : std::string_view("?");
}

std::uint16_t error_number_fb(Step step, FailureKind kind) noexcept {
  const auto p = positions(step);
  std::uint8_t pp = 0;
  std::uint8_t kk = 0x01;
  switch (kind) {
    case FailureKind::kWrite: pp = p.write; break;
    case FailureKind::kRead: pp = p.read; break;
    case FailureKind::kBadRecord:
      pp = p.bad;
      kk = 0x02;
      break;
    case FailureKind::kCopy: pp = p.copy; break;
  }
  if (pp == 0) return 0;
  return static_cast<std::uint16_t>((pp << 8) | kk);
}

}  // namespace rs4sim::proxy
