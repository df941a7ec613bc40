#pragma once
// Identification & Maintenance over MSAC_C1, [IEC 61158-6-3 MSAC_C1]:
//   Write.req 5F 00 FF 04 | 08 00 FD E8          (call header: Extended_Function_Num 0x08,
//                                                  reserved, I&M index BE)
//   Read.res+ 5E 00 FF 44 | 08 00 FD E8 | I&M0 record (64 bytes, multi-byte fields BE)
// Field semantics beyond sizes/offsets are UNCERTAIN ([IEC 61158-6-3 MSAC_C1]).

#include "dp/fdl/telegram.h"
#include "dp/pdu/errors.h"

#include <array>
#include <cstdint>
#include <span>

namespace rs4sim::dp::pdu {

inline constexpr std::uint8_t kImSlot = 0;
inline constexpr std::uint8_t kImRecordIndex = 255;        // DPV1 index of the call mechanism
inline constexpr std::uint8_t kImExtendedFunction = 0x08;  // IM_FN_CALL
inline constexpr std::uint16_t kIm0Index = 65000;          // I&M1..4 = 65001..65004
inline constexpr std::uint16_t kIm4Index = 65004;
inline constexpr std::size_t kImCallHeaderLength = 4;
inline constexpr std::size_t kImRecordLength = 64;

struct ImCallHeader {
  std::uint8_t extended_function = kImExtendedFunction;
  std::uint8_t reserved = 0;
  std::uint16_t im_index = kIm0Index;
  friend bool operator==(const ImCallHeader&, const ImCallHeader&) = default;
};

// Parses the call header at the start of a Write/Read data part; returns it and the bytes
// after it. Errors: kTooShort (< 4 bytes). Function/index checks are the device's
// ([IEC 61158-6-3 MSAC_C1]: function ≠ 0x08 → B8, unknown index → B0, wrong length → B6).
struct ImCall {
  ImCallHeader header;
  std::span<const std::uint8_t> record;
};
Result<ImCall> decode_im_call(std::span<const std::uint8_t> data);
Result<void> encode_im_call(const ImCallHeader& h, fdl::DataUnit& out);

// I&M0 record, 64 bytes ([IEC 61158-6-3 MSAC_C1] / [VPC3+ dp_if.h §13.0 sIM0]).
struct Im0 {
  std::array<std::uint8_t, 10> header{};  // manufacturer specific, zeros
  std::uint16_t manufacturer_id = 0;
  std::array<char, 20> order_id{};  // ASCII, space padded
  std::array<char, 16> serial_number{};
  std::uint16_t hardware_revision = 0;
  std::array<std::uint8_t, 4> software_revision{};  // 'V'|'R'|'P'|'U'|'T', x, y, z
  std::uint16_t revision_counter = 0;
  std::uint16_t profile_id = 0;
  std::uint16_t profile_specific_type = 0;
  std::array<std::uint8_t, 2> im_version{0x01, 0x01};
  std::uint16_t im_supported = 0;  // bit n = I&Mn supported; 0 = only I&M0
  friend bool operator==(const Im0&, const Im0&) = default;
};

// Errors: kTooShort / kTooLong (record must be exactly 64 bytes).
Result<Im0> decode_im0(std::span<const std::uint8_t> record);
Result<void> encode_im0(const Im0& im, fdl::DataUnit& out);

}  // namespace rs4sim::dp::pdu
