#include "rs4/adapter/error_memory.h"

namespace rs4sim::rs4::adapter {

void ErrorMemory::record(Processor p, std::uint16_t error) {
  auto& ring = p == Processor::kUc1 ? uc1_ : uc2_;
  auto& counts = p == Processor::kUc1 ? count1_ : count2_;
  ring.push(error);
  auto& n = counts[error];
  if (n < 0xFFFF) ++n;
  (p == Processor::kUc1 ? new1_ : new2_) = true;
}

void ErrorMemory::end_cycle() noexcept {
  // Table 5.2-8: age flag 0 = the error occurred in the last cycle, 1 = older.
  if (!new1_) uc1_.mark_aged();
  if (!new2_) uc2_.mark_aged();
  new1_ = new2_ = false;
}

std::uint16_t ErrorMemory::count(Processor p, std::uint16_t error) const noexcept {
  const auto& counts = p == Processor::kUc1 ? count1_ : count2_;
  const auto it = counts.find(error);
  return it == counts.end() ? 0 : it->second;
}

const protocol::ErrorRingBuffer& ErrorMemory::ring(Processor p) const noexcept {
  return p == Processor::kUc1 ? uc1_ : uc2_;
}

bool ErrorMemory::empty(Processor p) const noexcept {
  return (p == Processor::kUc1 ? count1_ : count2_).empty();
}

protocol::LastErrorAnswer ErrorMemory::last_error() const noexcept {
  protocol::LastErrorAnswer a;
  if (!empty(Processor::kUc2)) {
    a.uc2_error = uc2_.newest();
    a.uc2_count = count(Processor::kUc2, a.uc2_error);
  }
  if (!empty(Processor::kUc1)) {
    a.uc1_error = uc1_.newest();
    a.uc1_count = count(Processor::kUc1, a.uc1_error);
  }
  return a;
}

}  // namespace rs4sim::rs4::adapter
