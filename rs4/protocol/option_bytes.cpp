#include "rs4/protocol/option_bytes.h"

#include <algorithm>

namespace rs4sim::rs4::protocol {
namespace {

constexpr std::uint8_t kCountMask = 0x03;
constexpr unsigned kStateShift = 2;
constexpr std::uint8_t kStateMask = 0x07;
constexpr std::uint8_t kPasswordBit = 0x20;
constexpr std::uint8_t kAcknowledgeBit = 0x40;
constexpr std::uint8_t kReserved7 = 0x80;
constexpr std::uint8_t kMoreBit = 0x80;  // option 2 bit 7 / option 3 bit 7
constexpr std::uint8_t kOption3Reserved = 0x40;
constexpr unsigned kSecondPairShift = 3;
constexpr std::uint8_t kPairMask = 0x07;

std::uint8_t bit(bool value, unsigned n) noexcept {
  return value ? static_cast<std::uint8_t>(1U << n) : std::uint8_t{0};
}

std::uint8_t encode_flags(const ScannerFlags& f) noexcept {
  return static_cast<std::uint8_t>(
      bit(f.protective_field_occupied, 0) | bit(f.warning_field_occupied, 1) | bit(f.warning, 2) |
      bit(f.fault, 3) | bit(f.restart_interlock, 4) | bit(f.second_protective_field_occupied, 5) |
      bit(f.second_warning_field_occupied, 6));
}

ScannerFlags decode_flags(std::uint8_t b) noexcept {
  auto on = [b](unsigned n) { return (b & (1U << n)) != 0; };
  return {on(0), on(1), on(2), on(3), on(4), on(5), on(6)};
}

Result<std::uint8_t> decode_option1(std::uint8_t b, OptionBytes& o) noexcept {
  const auto count = static_cast<std::uint8_t>(b & kCountMask);
  if (count == 0) return ProtocolError::kBadOptionCount;
  if ((b & kReserved7) != 0) return ProtocolError::kReservedBitSet;
  const auto state = static_cast<std::uint8_t>((b >> kStateShift) & kStateMask);
  if (state > static_cast<std::uint8_t>(Option1State::kFault)) {
    return ProtocolError::kBadOperatingState;
  }
  o.state = static_cast<Option1State>(state);
  o.password = (b & kPasswordBit) != 0;
  o.acknowledge = (b & kAcknowledgeBit) != 0;
  return count;
}

std::error_code decode_option3(std::uint8_t b, OptionBytes& o) noexcept {
  if ((b & kMoreBit) == 0) return ProtocolError::kOption3MarkerMissing;
  if ((b & kOption3Reserved) != 0) return ProtocolError::kReservedBitSet;
  o.first_field_pair = static_cast<std::uint8_t>(b & kPairMask);
  o.second_field_pair = static_cast<std::uint8_t>((b >> kSecondPairShift) & kPairMask);
  if (o.first_field_pair > kMaxFieldPair || o.second_field_pair > kMaxFieldPair) {
    return ProtocolError::kBadFieldPair;
  }
  return {};
}

}  // namespace

bool ScannerFlags::any() const noexcept { return encode_flags(*this) != 0; }

Result<std::size_t> encode_option_bytes(const OptionBytes& o, std::vector<std::uint8_t>& out) {
  if (o.first_field_pair > kMaxFieldPair || o.second_field_pair > kMaxFieldPair) {
    return ProtocolError::kBadFieldPair;
  }
  const bool with3 = o.first_field_pair != 0 || o.second_field_pair != 0;
  const bool with2 = with3 || o.flags.any();
  const std::size_t count = 1U + (with2 ? 1U : 0U) + (with3 ? 1U : 0U);
  const auto state = static_cast<unsigned>(o.state) & kStateMask;
  out.push_back(static_cast<std::uint8_t>(count | (state << kStateShift) |
                                          (o.password ? kPasswordBit : 0U) |
                                          (o.acknowledge ? kAcknowledgeBit : 0U)));
  if (with2)
    out.push_back(static_cast<std::uint8_t>(encode_flags(o.flags) | (with3 ? kMoreBit : 0U)));
  if (with3) {
    out.push_back(static_cast<std::uint8_t>(kMoreBit | o.first_field_pair |
                                            (o.second_field_pair << kSecondPairShift)));
  }
  return count;
}

Result<DecodedOptions> decode_option_bytes(std::span<const std::uint8_t> bytes) {
  if (bytes.empty()) return ProtocolError::kTruncated;
  DecodedOptions d;
  auto count = decode_option1(bytes[0], d.options);
  if (!count) return count.error();
  d.size = count.value();
  if (bytes.size() < d.size) return ProtocolError::kTruncated;
  if (d.size >= 2) {
    const std::uint8_t opt2 = bytes[1];
    if (opt2 == 0) return ProtocolError::kZeroOptionByte;
    // Option 2 bit 7 announces option 3; it must agree with the count in option 1.
    if (((opt2 & kMoreBit) != 0) != (d.size == 3)) return ProtocolError::kBadOptionCount;
    d.options.flags = decode_flags(opt2);
  }
  if (d.size == 3) {
    if (auto ec = decode_option3(bytes[2], d.options)) return ec;
  }
  return d;
}

std::error_code encode_prefix(std::uint8_t code, const TelegramPrefix& prefix,
                              std::vector<std::uint8_t>& out) {
  out.push_back(code);
  auto options = encode_option_bytes(prefix.options, out);
  if (!options) {
    out.pop_back();
    return options.error();
  }
  if (prefix.options.password)
    out.insert(out.end(), prefix.password.begin(), prefix.password.end());
  return {};
}

Result<DecodedPrefix> decode_prefix(std::span<const std::uint8_t> body) {
  if (body.empty()) return ProtocolError::kTruncated;
  DecodedPrefix d;
  d.code = body[0];
  auto options = decode_option_bytes(body.subspan(1));
  if (!options) return options.error();
  d.prefix.options = options.value().options;
  d.size = 1 + options.value().size;
  if (d.prefix.options.password) {
    const std::size_t size = d.prefix.password.size();
    if (body.size() < d.size + size) return ProtocolError::kTruncated;
    std::copy_n(body.begin() + static_cast<std::ptrdiff_t>(d.size), size,
                d.prefix.password.begin());
    d.size += size;
  }
  return d;
}

}  // namespace rs4sim::rs4::protocol
