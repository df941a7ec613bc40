#include "stream/idle_gap_framer.h"

#include <algorithm>

namespace rs4sim::stream {

IdleGapFramer::IdleGapFramer(Duration gap, std::size_t max_frame)
    : gap_(gap), max_frame_(max_frame) {}

void IdleGapFramer::feed(std::span<const std::uint8_t> bytes, TimePoint now) {
  if (bytes.empty()) return;
  stats_.bytes += bytes.size();
  if (pending_ && now - pending_->last_byte >= gap_) complete_pending();
  if (!pending_) {
    pending_.emplace();
    pending_->first_byte = now;
  }
  pending_->last_byte = now;
  const std::size_t room = max_frame_ - std::min(max_frame_, pending_->bytes.size());
  const std::size_t take = std::min(room, bytes.size());
  pending_->bytes.insert(pending_->bytes.end(), bytes.begin(),
                         bytes.begin() + static_cast<std::ptrdiff_t>(take));
  if (take < bytes.size()) pending_->oversized = true;
}

std::optional<TimePoint> IdleGapFramer::deadline() const {
  if (!pending_) return std::nullopt;
  return pending_->last_byte + gap_;
}

std::optional<GapFrame> IdleGapFramer::poll(TimePoint now) {
  if (pending_ && now - pending_->last_byte >= gap_) complete_pending();
  if (ready_.empty()) return std::nullopt;
  GapFrame f = std::move(ready_.front());
  ready_.pop_front();
  return f;
}

void IdleGapFramer::reset() {
  pending_.reset();
  ready_.clear();
}

void IdleGapFramer::complete_pending() {
  ++stats_.frames;
  if (pending_->oversized) ++stats_.oversized;
  ready_.push_back(std::move(*pending_));
  pending_.reset();
}

}  // namespace rs4sim::stream
