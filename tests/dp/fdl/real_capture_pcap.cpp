// Test-side converter (tests/tools/real_capture_dissector_test.sh): a bus capture stored as a
// hex string (hex_capture.h) to a pcap file for the project's Wireshark dissector
// (docs/capture.md "Real bus traffic"). Every frame the streaming decoder finds becomes one
// record, as it was on the wire: the telegrams, and the frames whose framing is right but whose
// content DP refuses (DecoderSink::on_refused_frame); the noise between them is left out. The
// capture has no timestamps: a record's time is its frame's byte offset in the line, in
// microseconds, so that Wireshark keeps the order and shows where each frame was.
// usage: real_capture_pcap CAPTURE.txt OUT.pcap   (prints the frame counts; exit 1 on an error)
#include "dp/link/pcap.h"
#include "hex_capture.h"
#include "line_frames.h"

#include <chrono>
#include <cstdio>

int main(int argc, char** argv) {
  using namespace rs4sim::dp;
  if (argc != 3) {
    std::fprintf(stderr, "usage: real_capture_pcap CAPTURE.txt OUT.pcap\n");
    return 2;
  }
  std::string error;
  const auto capture = fdl::testing::read_hex_capture(argv[1], error);
  if (!capture) {
    std::fprintf(stderr, "real_capture_pcap: %s\n", error.c_str());
    return 1;
  }
  const fdl::testing::LineFrames line(capture->bytes);
  link::PcapFile file;
  std::error_code e = link::PcapFile::open(argv[2], link::PcapLinkType::kUser0, file);
  for (const auto& f : line.frames) {
    if (!e) e = file.write(f.bytes, std::chrono::microseconds(f.offset));
  }
  if (!e) e = file.flush();
  if (e) {
    std::fprintf(stderr, "real_capture_pcap: %s: %s\n", argv[2], e.message().c_str());
    return 1;
  }
  std::size_t refused = 0;
  for (const auto& f : line.frames) refused += f.refused ? 1U : 0U;
  std::printf("records %zu sd1 %zu sd2 %zu sd3 %zu token %zu sc %zu refused %zu mismatches %zu\n",
              line.frames.size(), line.count(fdl::kSd1), line.count(fdl::kSd2),
              line.count(fdl::kSd3), line.count(fdl::kSd4), line.count(fdl::kSc), refused,
              line.mismatches);
  return line.mismatches == 0 ? 0 : 1;
}
