#pragma once
// Copying a telegram on the hot path (the FCB responder's stored reply, the memory bus's frames).
#include "dp/fdl/telegram.h"

#include <cstddef>
#include <cstring>
#include <tuple>

namespace rs4sim::dp::fdl {

// `dst = src` without static_vector's library memmove for the DU: a cyclic DU is a few bytes,
// less than the memmove costs; a long one is copied at once.
inline void copy_telegram(Telegram& dst, const Telegram& src) {
  std::tie(dst.type, dst.da, dst.sa, dst.fc, dst.dsap, dst.ssap) =
      std::tie(src.type, src.da, src.sa, src.fc, src.dsap, src.ssap);
  const std::size_t n = src.data.size();
  dst.data.resize(n, boost::container::default_init);
  if (n > 16) {
    std::memcpy(dst.data.data(), src.data.data(), n);
  } else {
    for (std::size_t i = 0; i < n; ++i) dst.data[i] = src.data[i];
  }
}

}  // namespace rs4sim::dp::fdl
