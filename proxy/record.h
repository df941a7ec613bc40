#pragma once
// What ProxySync asks of the bus and what comes back, free of dp/master: a driver turns a
// RecordRequest into a DPV1 MSAC_C1 WRITE or READ of slot 0, index 2 ([RS4 manual §5.2]) and
// feeds the outcome back as a RecordResult (docs/proxy.md "Driver").

#include <cstdint>
#include <variant>
#include <vector>

namespace rs4sim::proxy {

inline constexpr std::uint8_t kRecordSlot = 0;    // [RS4 manual §5.2]: slot 0 only
inline constexpr std::uint8_t kRecordIndex = 2;   // index 2 (3 is treated identically)
inline constexpr std::uint8_t kReadLength = 240;  // the longest record ([RS4 manual §5.2])

// DPV1 WRITE of these bytes (one block: header + payload).
struct RecordWrite {
  std::vector<std::uint8_t> data;
  friend bool operator==(const RecordWrite&, const RecordWrite&) = default;
};
// DPV1 READ of up to `length` bytes.
struct RecordRead {
  std::uint8_t length = kReadLength;
  friend bool operator==(const RecordRead&, const RecordRead&) = default;
};
using RecordRequest = std::variant<RecordWrite, RecordRead>;

// ERROR_CODE_SFC is what the FB's SFC returned ([RS4 manual §6.4] "Fehlermeldungen dieser SFCs
// ... Die Entschlüsselung des SFC-Fehlercodes ist mit dem SIMATIC Referenzhandbuch
// ‚Systemsoftware für S7-300/400 System- und Standardfunktionen' möglich"): the RET_VAL of SFC 58
// WR_REC / SFC 59 RD_REC, W#16#80xx [docs/decisions.md#proxy-error-code-sfc].
inline constexpr std::uint16_t kSfcDpv1 = 0x8000;  // | Error_Code_1 of a DPV1 negative response
// No response at all: the slave did not answer, or is not in data exchange ("Dezentrale
// Peripherie nicht verfügbar").
inline constexpr std::uint16_t kSfcNoResponse = 0x80C5;

// The outcome of one WRITE or READ. `sfc` is ERROR_CODE_SFC for a failed one: W#16#80 with
// Error_Code_1 of the DPV1 negative response ([IEC 61158-6-3 MSAC_C1]), e.g. 0x80B5 for a state
// conflict; kSfcNoResponse when no response came (the slave did not answer, or the master could
// not send: the slave is not in data exchange). An answer the device does not deliver in time
// is no SFC error (every READ succeeded): the Exchange reports sfc 0.
struct RecordResult {
  bool ok = false;
  std::vector<std::uint8_t> data;  // READ: the record's bytes
  std::uint16_t sfc = 0;

  static RecordResult success(std::vector<std::uint8_t> bytes = {}) {
    return RecordResult{true, std::move(bytes), 0};
  }
  // Error_Code_2 is the device's own detail; the RET_VAL has no room for it.
  static RecordResult negative(std::uint8_t error_code_1, std::uint8_t error_code_2) {
    (void)error_code_2;
    return RecordResult{false, {}, static_cast<std::uint16_t>(kSfcDpv1 | error_code_1)};
  }
  static RecordResult no_response(std::uint16_t sfc = kSfcNoResponse) {
    return RecordResult{false, {}, sfc};
  }
};

}  // namespace rs4sim::proxy
