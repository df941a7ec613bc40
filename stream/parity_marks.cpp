#include "stream/parity_marks.h"

namespace rs4sim::stream {

void ParityMarks::feed(std::span<const std::uint8_t> chunk, const Good& good,
                       const Damaged& damaged) {
  run_.clear();
  const auto flush = [&] {
    if (!run_.empty()) good(run_);
    run_.clear();
  };
  for (const std::uint8_t b : chunk) {
    switch (pending_) {
      case 0:
        if (b == 0xFF) {
          pending_ = 1;
        } else {
          run_.push_back(b);
        }
        break;
      case 1:
        if (b == 0xFF) {  // FF FF: a literal FF
          run_.push_back(0xFF);
          pending_ = 0;
        } else if (b == 0x00) {  // FF 00: the damaged character follows
          pending_ = 2;
        } else {  // not a mark: deliver both as received
          ++stray_;
          run_.push_back(0xFF);
          run_.push_back(b);
          pending_ = 0;
        }
        break;
      default:  // FF 00 X
        flush();
        ++damaged_;
        damaged(b);
        pending_ = 0;
        break;
    }
  }
  flush();
}

}  // namespace rs4sim::stream
