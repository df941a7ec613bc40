#pragma once
// The adapter's error memory ([RS4 manual §5.2.2] PROFI_CMD_ERROR / _GET_ERROR,
// [RS4 manual §5.3.2] counts in the diagnosis alarm): per microcontroller μC1/μC2 a ring of 20
// error numbers with write index and age flag, the newest error and how often each number occurred
// since power-on. Kept over an adapter reset (0x94), lost at power-off.

#include "rs4/protocol/adapter_answer.h"

#include <cstdint>
#include <map>

namespace rs4sim::rs4::adapter {

enum class Processor : std::uint8_t { kUc1, kUc2 };

class ErrorMemory {
 public:
  // Enters `error` into the processor's ring and counts it.
  void record(Processor p, std::uint16_t error);
  // One adapter cycle passed: age flags of rings without a new error in it become 1.
  void end_cycle() noexcept;
  void clear() noexcept { *this = ErrorMemory{}; }

  // Occurrences of `error` in the processor since power-on (saturating at 0xFFFF).
  [[nodiscard]] std::uint16_t count(Processor p, std::uint16_t error) const noexcept;
  [[nodiscard]] const protocol::ErrorRingBuffer& ring(Processor p) const noexcept;
  [[nodiscard]] bool empty(Processor p) const noexcept;
  [[nodiscard]] protocol::LastErrorAnswer last_error() const noexcept;  // 0x84
  [[nodiscard]] protocol::ErrorMemoryAnswer memory() const noexcept {
    return {uc2_, uc1_};
  }  // 0x91

 private:
  protocol::ErrorRingBuffer uc1_, uc2_;
  std::map<std::uint16_t, std::uint16_t> count1_, count2_;
  bool new1_ = false, new2_ = false;
};

}  // namespace rs4sim::rs4::adapter
