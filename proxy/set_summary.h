#pragma once
// Texts the proxy stores with a set in the archive (storage/types.h StoreRequest).

#include <cstdint>
#include <span>
#include <string>

namespace rs4sim::proxy {

// A one-line summary of an encoded RS4 parameter set (docs/rs4-scanner.md "Encoding"), or
// "undecodable set (<reason>)" when the bytes do not decode.
std::string set_summary(std::span<const std::uint8_t> blob);

}  // namespace rs4sim::proxy
