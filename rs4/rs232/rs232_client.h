#pragma once
// The client side of the RS4's RS232 interface ([docs/rs232.md]): what a PC tool behind the
// optical PC adapter (`rs4sim param`, a robotics driver, the tests) needs to build commands and
// read the RS4's answers. Pure functions and a streaming reader; no I/O, no time.
//
//   encode_command(code, data, options)  → one framed command (00 00 … CHK 00 00 00)
//   encode_transfer(request, options)    → 0x60..0x65, the payload encoder the PROFIBUS proxy
//                                          uses ([docs/proxy-protocol.md]), RS232-framed
//   AnswerReader::feed(bytes)            → decoded answers: ack/nak, telegram, transfer answer

#include "rs4/protocol/option_bytes.h"
#include "rs4/protocol/parameter_transfer.h"
#include "rs4/protocol/rs232.h"
#include "rs4/protocol/telegram.h"
#include "rs4/rs232/rs232_codes.h"

#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <system_error>
#include <variant>
#include <vector>

namespace rs4sim::rs4::rs232 {

struct CommandOptions {
  bool acknowledge = false;                    // OPT1 bit 6: answer 0x16 / 0x17
  std::optional<protocol::Password> password;  // OPT1 bit 5: the 8-byte field follows
};

// "ROD4LE" → 52 4F 44 34 4C 45 FF FF. nullopt for more than 8 characters or a byte outside
// 0x20..0x7E (what the RS4 accepts, docs/rs4-scanner.md).
[[nodiscard]] std::optional<protocol::Password> make_password(std::string_view ascii);

// The command body CMD | OPT1 [| password] | data, unframed (what travels on PROFIBUS).
[[nodiscard]] std::vector<std::uint8_t> command_body(std::uint8_t code,
                                                     std::span<const std::uint8_t> data,
                                                     const CommandOptions& options = {});
// The body framed for the line. kBadCommandByte for code 0x00 / 0xFF.
[[nodiscard]] protocol::Result<std::vector<std::uint8_t>> encode_command(
    std::uint8_t code, std::span<const std::uint8_t> data, const CommandOptions& options = {});
// Convenience frames of the command set.
[[nodiscard]] protocol::Result<std::vector<std::uint8_t>> encode_set_baud(
    std::uint32_t baud, const CommandOptions& options = {});  // kBadAnswerValue: no such rate
[[nodiscard]] protocol::Result<std::vector<std::uint8_t>> encode_measurement_window(
    std::uint8_t resolution, std::uint16_t start, std::uint16_t stop,
    const CommandOptions& options);
[[nodiscard]] protocol::Result<std::vector<std::uint8_t>> encode_stream_control(
    bool on, const CommandOptions& options = {});
// 0x60..0x65 with the shared payload encoder (protocol::encode_request), RS232-framed.
[[nodiscard]] protocol::Result<std::vector<std::uint8_t>> encode_transfer(
    const protocol::TransferRequest& request, const CommandOptions& options = {});

// 0x16 / 0x17 from the RS4.
struct Acknowledge {
  bool positive = false;
  std::uint8_t command = 0;  // the code acknowledged
  std::uint16_t error = 0;   // 0x17 only: the error number (docs/rs232.md)
  protocol::OptionBytes options;
  friend bool operator==(const Acknowledge&, const Acknowledge&) = default;
};
// Flat (one variant): the RS4 telegrams of protocol::Rs4Telegram, the acknowledgements and the
// parameter-transfer answers.
using Answer = std::variant<Acknowledge, protocol::AliveTelegram, protocol::ErrorTelegram,
                            protocol::WarningTelegram, protocol::MeasurementTelegram,
                            protocol::TransferAnswer>;
// One answer body (CMD first) as the RS4 sends it.
[[nodiscard]] protocol::Result<Answer> decode_answer(std::span<const std::uint8_t> body);

// Streaming reader: chunks of any size in, one result per frame out (framing errors and
// undecodable bodies as error codes).
class AnswerReader {
 public:
  explicit AnswerReader(std::size_t max_body = 4096) : deframer_(max_body) {}
  std::vector<protocol::Result<Answer>> feed(std::span<const std::uint8_t> bytes);
  [[nodiscard]] const protocol::DeframerCounters& counters() const noexcept {
    return deframer_.counters();
  }

 private:
  protocol::Rs232Deframer deframer_;
};

}  // namespace rs4sim::rs4::rs232
