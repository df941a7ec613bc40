#pragma once
// Reading and writing the RS4 parameter set over the RS4's RS232 port behind the PC adapter
// ([docs/rs232.md], EXTENSION commands 0x60..0x65 with the proxy's payloads,
// [docs/proxy-protocol.md]): IDENTIFY, UPLOAD_CHUNK 0..n-1; DOWNLOAD_BEGIN, DOWNLOAD_CHUNK
// 0..n-1, DOWNLOAD_COMMIT with the password. No I/O here: `Exchange` sends one framed
// command and returns the RS4's answer to it (the caller skips the 0x23 stream and times out).

#include "rs4/rs232/rs232_client.h"
#include "rs4/scanner/parameter_set.h"

#include <functional>
#include <optional>
#include <span>
#include <string>

namespace rs4sim::rs4::param_doc {

// One framed command out, the answer to it back (nullopt: no answer in time).
using Exchange = std::function<std::optional<rs232::Answer>(std::span<const std::uint8_t> frame)>;

struct LiveSet {
  std::optional<scanner::ParameterSet> set;  // engaged on success
  std::string error;                         // what failed otherwise
};

// The device's set, uploaded in the transfer form (identity from IDENTIFY, user passwords
// empty: they never leave the device, [RS4 manual §7.2.4]).
LiveSet read_live_set(const Exchange& exchange);

// Downloads `set` (transfer form: the device keeps its passwords and identity) and checks the
// CRC-32 the RS4 reports for the set now active. Empty string on success, else the reason.
std::string write_live_set(const Exchange& exchange, const scanner::ParameterSet& set,
                           const scanner::Password& password);

}  // namespace rs4sim::rs4::param_doc
