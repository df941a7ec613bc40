// Fuzzes the streaming RS232 deframer ([roboticslibrary/rl LeuzeRs4.cpp]) with arbitrary chunks,
// and checks frame → deframe returns the body for any body the framer accepts.
// Input: [chunk size seed][stream bytes…]
#include "rs4/protocol/rs232.h"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

using namespace rs4sim::rs4::protocol;

namespace {

void check(bool ok) {
  if (!ok) __builtin_trap();
}

void round_trip(std::span<const std::uint8_t> body) {
  auto framed = frame_rs232(body);
  if (!framed) return;
  // Three zeros never occur between start and end mark ([roboticslibrary/rl LeuzeRs4.cpp]).
  const auto& wire = framed.value();
  for (std::size_t i = 2; i + 5 < wire.size(); ++i) {
    check(!(wire[i] == 0 && wire[i + 1] == 0 && wire[i + 2] == 0));
  }
  Rs232Deframer d(body.size() + 16);
  auto events = d.feed(wire);
  if (body.size() < 2) {  // CMD without OPT1 is too short for a frame
    check(events.size() == 1 && !events[0]);
    return;
  }
  check(events.size() == 1 && events[0]);
  check(std::equal(body.begin(), body.end(), events[0].value().begin(), events[0].value().end()));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::size_t chunk = 1 + data[0] % 64;
  const std::span<const std::uint8_t> stream(data + 1, size - 1);
  Rs232Deframer deframer(512);
  std::vector<Rs232Deframer::Event> events;
  for (std::size_t at = 0; at < stream.size(); at += chunk) {
    deframer.feed(stream.subspan(at, std::min(chunk, stream.size() - at)), events);
  }
  for (const auto& e : events) {
    if (e) check(e.value().size() >= 2 && e.value().size() <= 512 + 3);
  }
  check(deframer.counters().frames <= events.size());
  round_trip(stream);
  return 0;
}
