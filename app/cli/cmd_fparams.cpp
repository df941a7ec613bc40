// `rs4sim fparams`: build a PROFIsafe F-parameter block and its F_Par_CRC (CRC1).
// Defaults are the RS4/PROFIsafe's fixed values ([RS4 manual §6.2, §6.3]): SIL2, 2-byte CRC,
// F_Block_ID 0, F_Par_Version 0, F_Source_Add 1, F_Dest_Add 504, F_WD_Time 10 ms.
// Impossible combinations are refused with a message and exit code 2.
// `--decode HEX [--address N]` shows what the RS4 makes of a received block (exit 1 unless
// diagnosis 0).
#include "app/cli/command.h"
#include "dp/pdu/sap.h"
#include "profisafe/f_parameters.h"
#include "rs4/safety/diagnosis.h"
#include "rs4/safety/profile.h"

#include <cctype>
#include <cstdint>
#include <cstdio>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

namespace rs4sim::app {
namespace {

using profisafe::CrcLength;
using profisafe::FParameters;

struct FparamsOptions {
  int sil = 2;
  int crc_length = 2;  // bytes
  int block_id = 0;
  int par_version = 0;
  long long source = 1;
  long long dest = 504;
  long long wd_time = 10;
  bool check_seqnr = false;
  std::optional<long long> ipar_crc;
  bool json = false;
  std::string decode;    // --decode HEX: parse and validate a received block instead
  unsigned address = 4;  // --address: the RS4's DP address for --decode
};

std::uint16_t address(long long v, const char* name) {
  if (v < 1 || v > 65534) {
    throw UsageError(std::string(name) +
                     " must be 1..65534 (0 and 65535 are not valid addresses), got " +
                     std::to_string(v));
  }
  return static_cast<std::uint16_t>(v);
}

CrcLength crc_length_code(const FparamsOptions& o) {
  // [IEC 61784-3-3 F-Parameters]: V1 has only the 2-byte CRC; V2 has 3- and 4-byte CRCs.
  if (o.par_version == 0 && o.crc_length != 2) {
    throw UsageError("--crc-length " + std::to_string(o.crc_length) +
                     " needs --par-version 1 (PROFIsafe V1 uses the 2-byte CRC only)");
  }
  if (o.par_version == 1 && o.crc_length == 2) {
    throw UsageError("--crc-length 2 needs --par-version 0 (PROFIsafe V2 uses a 3- or 4-byte CRC)");
  }
  return o.crc_length == 2   ? CrcLength::k2Byte
         : o.crc_length == 3 ? CrcLength::k3Byte
                             : CrcLength::k4Byte;
}

FParameters to_parameters(const FparamsOptions& o) {
  FParameters p;
  p.check_seqnr = o.check_seqnr;
  p.sil = static_cast<profisafe::Sil>(o.sil - 1);
  p.crc_length = crc_length_code(o);
  p.block_id = static_cast<std::uint8_t>(o.block_id);
  p.par_version = static_cast<std::uint8_t>(o.par_version);
  p.source_add = address(o.source, "--source (F_Source_Add)");
  p.dest_add = address(o.dest, "--dest (F_Dest_Add)");
  if (o.wd_time < 1 || o.wd_time > 65535) {
    throw UsageError("--wd-time (F_WD_Time) must be 1..65535 ms, got " + std::to_string(o.wd_time));
  }
  p.wd_time_ms = static_cast<std::uint16_t>(o.wd_time);
  if (o.ipar_crc) {
    if (o.par_version != 1)
      throw UsageError("--ipar-crc needs --par-version 1 (F_iPar_CRC exists in V2 only)");
    if (*o.ipar_crc < 0 || *o.ipar_crc > 0xFFFFFFFFLL)
      throw UsageError("--ipar-crc must be 0..4294967295");
    p.ipar_crc = static_cast<std::uint32_t>(*o.ipar_crc);
  }
  p.par_crc = profisafe::crc1(p);
  return p;
}

std::string hex(const std::array<std::uint8_t, profisafe::kFParametersSize>& b, const char* sep) {
  std::string s;
  char buf[3];
  for (std::size_t i = 0; i < b.size(); ++i) {
    std::snprintf(buf, sizeof buf, "%02X", b[i]);
    if (i != 0) s += sep;
    s += buf;
  }
  return s;
}

std::vector<std::uint8_t> parse_hex(const std::string& text) {
  std::vector<std::uint8_t> out;
  std::string digits;
  for (char ch : text) {
    if (ch == ' ' || ch == ':' || ch == '-') continue;
    if (!std::isxdigit(static_cast<unsigned char>(ch))) {
      throw UsageError(std::string("--decode: '") + ch + "' is not a hex digit");
    }
    digits += ch;
  }
  if (digits.size() % 2 != 0) throw UsageError("--decode: odd number of hex digits");
  for (std::size_t i = 0; i < digits.size(); i += 2) {
    out.push_back(static_cast<std::uint8_t>(std::stoul(digits.substr(i, 2), nullptr, 16)));
  }
  return out;
}

// --decode: what the RS4 at --address makes of a received block ([RS4 manual §6.3]).
int run_decode(const FparamsOptions& o) {
  if (o.address > dp::pdu::sap::kMaxStationAddress) {
    throw UsageError("--address must be a DP station address 0.." +
                     std::to_string(dp::pdu::sap::kMaxStationAddress));
  }
  const auto bytes = parse_hex(o.decode);
  const auto parsed = profisafe::parse_f_parameters(bytes);
  const auto v = profisafe::validate(bytes, rs4::safety::device_profile(o.address));
  const auto diagnosis = rs4::safety::diagnosis(v.fault);
  const auto pdu = rs4::safety::status_pdu(diagnosis);
  char line[160];
  if (parsed) {
    const FParameters& p = parsed.value();
    std::snprintf(
        line, sizeof line,
        "F_Check_SeqNr %d, F_Check_iPar %d, F_SIL code %u, F_CRC_Length code %u, F_Block_ID %u, "
        "F_Par_Version %u\n",
        p.check_seqnr ? 1 : 0, p.check_ipar ? 1 : 0, static_cast<unsigned>(p.sil),
        static_cast<unsigned>(p.crc_length), p.block_id, p.par_version);
    std::cout << line << "F_Source_Add " << p.source_add << ", F_Dest_Add " << p.dest_add
              << ", F_WD_Time " << p.wd_time_ms << " ms\n";
    std::snprintf(line, sizeof line, "F_Par_CRC received 0x%04X, computed 0x%04X\n",
                  v.received_crc1, v.computed_crc1);
    std::cout << line;
  } else {
    std::cout << "not a parameter block: " << parsed.error().message() << "\n";
  }
  std::snprintf(line, sizeof line, "RS4 diagnosis %u (%s), status PDU %02X %02X %02X %02X %02X\n",
                static_cast<unsigned>(diagnosis), rs4::safety::to_string(diagnosis), pdu[0], pdu[1],
                pdu[2], pdu[3], pdu[4]);
  std::cout << line;
  return v.ok() ? 0 : 1;
}

int run(const FparamsOptions& o) {
  if (!o.decode.empty()) return run_decode(o);
  const FParameters p = to_parameters(o);
  const auto block = profisafe::encode_f_parameters(p);
  char crc_hex[8];
  std::snprintf(crc_hex, sizeof crc_hex, "0x%04X", p.par_crc);
  if (o.json) {
    std::cout << "{\"block\":\"" << hex(block, "") << "\",\"f_par_crc\":" << p.par_crc
              << ",\"f_par_crc_hex\":\"" << crc_hex
              << "\",\"check_seqnr\":" << (p.check_seqnr ? "true" : "false") << ",\"sil\":" << o.sil
              << ",\"crc_length\":" << o.crc_length << ",\"block_id\":" << o.block_id
              << ",\"par_version\":" << o.par_version << ",\"source_add\":" << p.source_add
              << ",\"dest_add\":" << p.dest_add << ",\"wd_time_ms\":" << p.wd_time_ms;
    if (p.ipar_crc) std::cout << ",\"ipar_crc\":" << *p.ipar_crc;
    std::cout << "}\n";
    return 0;
  }
  std::cout << "F-parameter block: " << hex(block, " ") << "\n"
            << "F_Par_CRC (CRC1):  " << crc_hex << " = " << p.par_crc << "\n";
  return 0;
}

const CommandRegistration kRegistration{
    "fparams", "Build a PROFIsafe F-parameter block and its CRC1 (F_Par_CRC)",
    [](CLI::App& cmd) -> Action {
      auto o = std::make_shared<FparamsOptions>();
      cmd.add_option("--sil", o->sil, "F_SIL: 1..3")
          ->check(CLI::Range(1, 3))
          ->capture_default_str();
      cmd.add_option("--crc-length", o->crc_length, "F_CRC_Length in bytes: 2 (V1), 3 or 4 (V2)")
          ->check(CLI::IsMember({2, 3, 4}))
          ->capture_default_str();
      cmd.add_option("--block-id", o->block_id, "F_Block_ID: 0..7")
          ->check(CLI::Range(0, 7))
          ->capture_default_str();
      cmd.add_option("--par-version", o->par_version, "F_Par_Version: 0 (V1) or 1 (V2)")
          ->check(CLI::IsMember({0, 1}))
          ->capture_default_str();
      cmd.add_option("--source", o->source, "F_Source_Add: 1..65534")->capture_default_str();
      cmd.add_option("--dest", o->dest, "F_Dest_Add: 1..65534 (RS4: 500 + DP address)")
          ->capture_default_str();
      cmd.add_option("--wd-time", o->wd_time, "F_WD_Time in ms (RS4: 10..1000)")
          ->capture_default_str();
      cmd.add_flag("--check-seqnr", o->check_seqnr,
                   "F_Check_SeqNr = 1 (consecutive number in CRC2)");
      cmd.add_option("--ipar-crc", o->ipar_crc, "F_iPar_CRC (V2 only), fed into CRC1 first");
      cmd.add_flag("--json", o->json, "print JSON");
      cmd.add_option(
          "--decode", o->decode,
          "parse a received block (hex) and print the RS4's diagnosis; exit 1 if not accepted");
      cmd.add_option("--address", o->address,
                     "DP address of the RS4 for --decode (F_Dest_Add = 500 + it)")
          ->capture_default_str();
      return [o] { return run(*o); };
    }};

}  // namespace
}  // namespace rs4sim::app
