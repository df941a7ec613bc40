#pragma once
// Structured parameter blocks in Set_Prm User_Prm_Data (DPV1_Status_3 Prm_Structure = 1),
// [IEC 61158-6-3 structured Prm_Data]:
//   [Structure_Length (incl. itself)] [Structure_Type] [Slot] [Index/Specifier] [data…]
// PROFIsafe F-parameter blocks use the same shape with type 0x05
// ([PROFIBUS GSD spec F-parameter keywords], inferred).

#include "codec/reader.h"
#include "dp/fdl/telegram.h"
#include "dp/pdu/errors.h"

#include <cstdint>
#include <optional>
#include <span>

namespace rs4sim::dp::pdu {

namespace prm_block_type {
inline constexpr std::uint8_t kPrmCmd = 0x02;  // redundancy (DPV2)
inline constexpr std::uint8_t kDxbLinkTable = 0x03;
inline constexpr std::uint8_t kIsochronous = 0x04;
inline constexpr std::uint8_t kFParameters = 0x05;  // PROFIsafe (UNCERTAIN
                                                    // [docs/decisions.md#dp-open-points])
inline constexpr std::uint8_t kDxbSubscriber = 0x07;
inline constexpr std::uint8_t kTimeAr = 0x08;
inline constexpr std::uint8_t kUserPrmData = 0x81;
}  // namespace prm_block_type

inline constexpr std::size_t kPrmBlockHead = 4;

struct PrmBlock {
  std::uint8_t type = 0;
  std::uint8_t slot = 0;
  std::uint8_t index = 0;              // Index/Specifier
  std::span<const std::uint8_t> data;  // Structure_Length − 4 bytes
  // The whole block incl. its 4-byte head (e.g. the 14-byte F-parameter block).
  std::span<const std::uint8_t> raw;
};

// Reads the blocks one by one (no allocation; blocks refer to the input bytes).
class PrmBlockReader {
 public:
  explicit PrmBlockReader(std::span<const std::uint8_t> user_prm_data) : in_(user_prm_data) {}
  // nullopt at the end. Errors: kBadPrmBlock (Structure_Length < 4 or beyond the data);
  // after an error the reader is at its end.
  Result<std::optional<PrmBlock>> next();

 private:
  codec::Reader in_;
};

// Appends one block (Errors: kValueOutOfRange if it exceeds 255 bytes, kTooLong if the DU
// would exceed 244 bytes).
Result<void> encode_prm_block(std::uint8_t type, std::uint8_t slot, std::uint8_t index,
                              std::span<const std::uint8_t> data, fdl::DataUnit& out);

}  // namespace rs4sim::dp::pdu
