#pragma once
// CRC-32/ISO-HDLC (the zlib/Ethernet CRC: poly 0x04C11DB7 reflected, init and xorout
// 0xFFFFFFFF; check value of "123456789" is 0xCBF43926), computed with zlib.

#include <cstdint>
#include <span>

namespace rs4sim::storage {

std::uint32_t crc32(std::span<const std::uint8_t> bytes) noexcept;

}  // namespace rs4sim::storage
