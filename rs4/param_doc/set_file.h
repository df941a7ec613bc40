#pragma once
// The RS4 parameter set file (`rs4sim param --file`, docs/param.md "Set files"): the set's
// encoding (docs/rs4-scanner.md "Encoding", 8507 bytes, full or transfer form) in a file.
// EXTENSION, the project's format:
//   format 1  the encoding alone (8507 bytes): no checksum, a damaged byte may decode as
//             another valid set; still read, with a warning.
//   format 2  the encoding, then a 9-byte trailer (8516 bytes):
//               offset 8507  4  "RS4F" (52 53 34 46)
//               offset 8511  1  file format 2
//               offset 8512  4  CRC-32/ISO-HDLC of bytes 0..8511, big-endian
//             A flip of any byte (any 1 to 32 bits of it) changes the CRC's verdict.
// Every reader of a set file goes through read_set_file(); `param set` writes format 2.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace rs4sim::rs4::param_doc {

inline constexpr std::uint8_t kSetFileFormat = 2;
inline constexpr std::size_t kSetFileTrailerSize = 9;

struct SetFileBytes {
  std::vector<std::uint8_t> encoding;  // the set's encoding, for scanner::decode()
  unsigned format = 0;                 // 1 or 2
  std::string warning;                 // format 1: it carries no checksum
};

struct SetFileRead {
  std::optional<SetFileBytes> bytes;  // nothing: refused, `error` says why
  std::string error;
};

// The encoding in a set file, its checksum checked (format 2), or why the file is refused: a
// size of neither format, a damaged trailer, a format this rs4sim does not read, a CRC-32
// that does not match (the file is damaged). The encoding itself is checked by the caller
// (scanner::decode_and_validate or decode_transfer_form).
SetFileRead read_set_file(std::span<const std::uint8_t> file);

// A set file of format 2 around `encoding`.
std::vector<std::uint8_t> set_file(std::span<const std::uint8_t> encoding);

}  // namespace rs4sim::rs4::param_doc
