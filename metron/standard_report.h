#pragma once
// Standard line mode's report message [METRON manual "Standard line mode"]: the selected
// data, one byte each, sent as 1 raw byte (binary), 2 ASCII hex digits or 3 ASCII decimal
// digits, with or without a separator between data, with an optional checksum character.
// Table 1's lengths (n data: binary n+2 / 2n+1, hex 2n+2 / 3n+1, decimal 3n+2 / 4n+1, +1
// with checksum) fix the shape: one character before and one after the data, n-1
// separators, and a checksum of ONE character in every mode. The characters themselves
// were lost: EXTENSION ([docs/metron.md#standard-frame]), the wire table's characters in
// the order of WireTable::report, by default
//   Start | D1 [Sep D2 ...] | [Checksum] | End
// with the checksum sent as one raw byte, the one's complement of the sum of the data
// values (not of their ASCII digits; ReportLayout::checksum_over_characters sums those).

#include "metron/checksum.h"
#include "metron/options.h"
#include "metron/wire_table.h"
#include "stream/clock.h"
#include "stream/line_settings.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace rs4sim::metron {

struct ReportFormat {
  Format format = Format::kBinary;
  bool separator = false;
  bool checksum = false;
};

[[nodiscard]] std::vector<std::uint8_t> encode_report(std::span<const std::uint8_t> values,
                                                      const ReportFormat& f, const WireTable& table,
                                                      ChecksumReading reading);

// Where the checksum byte of a `frame_size`-byte report sits; nullopt without a checksum.
[[nodiscard]] std::optional<std::size_t> report_checksum_offset(const WireTable& table,
                                                                const ReportFormat& f,
                                                                std::size_t frame_size);

// Table 1 plus its footnote: the message length for n data.
[[nodiscard]] std::size_t report_length(std::size_t n, const ReportFormat& f);

// Equations 1 and 2: t_send = Length * b / (Baud * 1e-3) ms + 1 ms, b = 11 with parity,
// 10 without (the line's bits per character in general) [METRON manual "Standard line mode"].
[[nodiscard]] stream::Duration send_time(std::size_t length, const stream::LineSettings& line);

// Equation 3: t_late = n_byte * 11 * 0.05208 ms + t_response / 2, from the start of the
// host's message to the start of the reply [METRON manual "Slave line mode"].
[[nodiscard]] stream::Duration reply_delay(std::size_t n_byte, stream::Duration t_response);

}  // namespace rs4sim::metron
