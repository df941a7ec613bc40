#pragma once
// What a byte link (stream/byte_runner.h, stream/memory_line.h) counts of its traffic. A
// link never throws on bad wire input: the device decides what a frame is and counts its
// own rejects; the link counts bytes, chunks and frames.

#include <cstdint>

namespace rs4sim::stream {

struct ByteCounters {
  std::uint64_t bytes_received = 0;
  std::uint64_t chunks_received = 0;   // reads as the OS delivered them (UDP: datagrams)
  std::uint64_t damaged_received = 0;  // characters with a parity or framing error
  std::uint64_t bytes_sent = 0;
  std::uint64_t frames_sent = 0;  // frames the devices handed to the link (take_transmit)
  std::uint64_t link_errors = 0;  // OS-level send/receive failures (serial/UDP)

  friend bool operator==(const ByteCounters&, const ByteCounters&) = default;
};

}  // namespace rs4sim::stream
