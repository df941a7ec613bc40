#pragma once
// Binary encoding of the RS4 parameter set — EXTENSION ([docs/decisions.md#rs4-extensions]),
// layout in docs/rs4-scanner.md "Encoding". Deterministic: one set, one byte string.
// All multi-byte fields are big-endian (high byte first, as every RS4 value, [RS4 manual §5.2.3]).
// The proxy transfers it in chunks; its checksum is CRC-32/ISO-HDLC over these bytes.
//
// decode() checks syntax only (length, magic, version, reserved byte); the meaning is
// checked by validate() (parameter_set.h) — decode_and_validate() does both.

#include "rs4/scanner/parameter_set.h"

#include <boost/outcome/std_result.hpp>

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace rs4sim::rs4::scanner {

inline constexpr std::uint8_t kParameterFormatVersion = 1;
inline constexpr std::size_t kParameterHeaderSize = 43;
inline constexpr std::size_t kParameterPairSize = 2 * kSegmentCount * 2;  // 2116
inline constexpr std::size_t kParameterSetSize =
    kParameterHeaderSize + kFieldPairCount * kParameterPairSize;  // 8507

std::vector<std::uint8_t> encode(const ParameterSet& set);
boost::outcome_v2::std_result<ParameterSet> decode(std::span<const std::uint8_t> bytes);
// Syntax, then meaning; a semantic failure returns the ParameterError of the first issue.
boost::outcome_v2::std_result<ParameterSet> decode_and_validate(
    std::span<const std::uint8_t> bytes);

// CRC-32/ISO-HDLC over encode(set).
std::uint32_t checksum(const ParameterSet& set);

// The transfer form ([docs/proxy-protocol.md]): encode() of the set with the identity and the
// user passwords zeroed. It is what the proxy uploads, archives and downloads: identity
// belongs to the device and a download never overwrites the passwords ([RS4 manual §7.2.4]),
// so neither travels. (Zeroed passwords do not validate: a received transfer form is
// merged with the device's set, merge_download(), before validate().)
std::vector<std::uint8_t> encode_for_transfer(const ParameterSet& set);
// CRC-32/ISO-HDLC over encode_for_transfer(set): the set CRC-32 of IDENTIFY, the upload and
// the download; after a download it equals the downloaded blob's CRC although the device
// kept its own passwords.
std::uint32_t transfer_checksum(const ParameterSet& set);
// A set in the transfer form (as the proxy archives it): syntax, then meaning, where the blank
// passwords count as empty (they are the device's, never transferred). The set is returned as
// decoded, passwords zero. A semantic failure returns the ParameterError of the first issue.
boost::outcome_v2::std_result<ParameterSet> decode_transfer_form(
    std::span<const std::uint8_t> bytes);

}  // namespace rs4sim::rs4::scanner
