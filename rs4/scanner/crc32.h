#pragma once
// CRC-32/ISO-HDLC (the "zip/Ethernet" CRC-32): polynomial 0x04C11DB7 reflected
// (0xEDB88320), init 0xFFFFFFFF, reflected in/out, xorout 0xFFFFFFFF; check value over
// "123456789" = 0xCBF43926. Used as the parameter-set checksum (docs/rs4-scanner.md).

#include <cstdint>
#include <span>

namespace rs4sim::rs4::scanner {

std::uint32_t crc32_iso_hdlc(std::span<const std::uint8_t> bytes) noexcept;

}  // namespace rs4sim::rs4::scanner
