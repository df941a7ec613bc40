#pragma once
// Chk_Cfg (DSAP 62) / Get_Cfg (DSAP 59) configuration identifiers, [IEC 61158-6-3 Chk_Cfg/Get_Cfg].
//
// General ("compact") identifier: 1 byte. Special identifier: header byte with bits 5..4 = 00,
// then the length byte(s) (output first, then input), then 0…14 manufacturer bytes.

#include "dp/fdl/telegram.h"
#include "dp/pdu/errors.h"

#include <boost/container/static_vector.hpp>

#include <cstdint>
#include <optional>
#include <span>

namespace rs4sim::dp::pdu {

inline constexpr std::size_t kCfgMaxLength = 244;  // Chk_Cfg DU 1…244 ([IEC 61158-6-3 Set_Prm])

// Length of one direction: `count` units of byte or word, consistent over the whole length.
struct IoLength {
  std::uint8_t count = 1;  // 1…16 (general) or 1…64 (special)
  bool words = false;
  bool consistent = false;
  [[nodiscard]] std::size_t bytes() const { return words ? 2U * count : count; }
  friend bool operator==(const IoLength&, const IoLength&) = default;
};

enum class CfgFormat : std::uint8_t { kGeneral, kSpecial };

struct CfgIdentifier {
  CfgFormat format = CfgFormat::kGeneral;
  std::optional<IoLength> input;
  std::optional<IoLength> output;
  // Special format only: manufacturer bytes (0…14), or "no manufacturer data, skip the
  // check" (code 15, Chk_Cfg only).
  boost::container::static_vector<std::uint8_t, 14> manufacturer_data;
  bool skip_manufacturer_check = false;

  [[nodiscard]] std::size_t input_bytes() const { return input ? input->bytes() : 0; }
  [[nodiscard]] std::size_t output_bytes() const { return output ? output->bytes() : 0; }
  [[nodiscard]] std::size_t encoded_size() const;
  friend bool operator==(const CfgIdentifier&, const CfgIdentifier&) = default;
};

enum class CfgService : std::uint8_t { kChkCfg, kGetCfg };

// Parses the identifier starting at du[0]; returns it and how many bytes it used.
struct CfgParse {
  CfgIdentifier identifier;
  std::size_t size = 0;
};
// Errors: kTooShort (empty, or length/manufacturer bytes missing), kBadIdentifier
// (manufacturer code 15 in a Get_Cfg reply, [IEC 61158-6-3 Chk_Cfg/Get_Cfg]).
Result<CfgParse> decode_cfg_identifier(std::span<const std::uint8_t> du, CfgService service);

// Walks a whole Chk_Cfg/Get_Cfg DU without storing the identifiers.
struct CfgSummary {
  std::size_t identifiers = 0;
  std::size_t input_bytes = 0;   // Data_Exchange input image length
  std::size_t output_bytes = 0;  // Data_Exchange output image length
  friend bool operator==(const CfgSummary&, const CfgSummary&) = default;
};
// Errors: kTooShort (empty DU for Chk_Cfg or truncated identifier), kTooLong (> 244),
// kBadIdentifier.
Result<CfgSummary> summarize_cfg(std::span<const std::uint8_t> du, CfgService service);

// Errors: kBadIdentifier (count out of range, general format with different in/out
// lengths, no I/O in general format), kTooLong (DU would exceed 244).
Result<void> encode_cfg_identifier(const CfgIdentifier& id, fdl::DataUnit& out);

// Builders for the usual shapes.
CfgIdentifier general_input(std::uint8_t count, bool words = false, bool consistent = false);
CfgIdentifier general_output(std::uint8_t count, bool words = false, bool consistent = false);
CfgIdentifier general_input_output(std::uint8_t count, bool words = false, bool consistent = false);
CfgIdentifier empty_slot();

}  // namespace rs4sim::dp::pdu
