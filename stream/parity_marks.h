#pragma once
// Bytes as a serial port delivers them with INPCK | PARMRK (and neither IGNPAR nor ISTRIP)
// [termios(3) PARMRK]: a character received with a parity or framing error arrives as the
// three bytes FF 00 X (X the character as received), a literal FF as FF FF, every other byte
// as itself. ParityMarks undoes that, sans I/O, across reads (a mark may be split between two
// chunks): the good bytes in runs, each damaged character on its own, in line order. This is
// what lets a device apply its own rule to a damaged character (the METRON rejects the whole
// message, [METRON manual "ERROR HANDLING"]) instead of the port dropping it (IGNPAR).

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

namespace rs4sim::stream {

class ParityMarks {
 public:
  using Good = std::function<void(std::span<const std::uint8_t> bytes)>;
  using Damaged = std::function<void(std::uint8_t byte)>;

  // Decodes `chunk`; a mark cut short at its end is completed by the next call.
  void feed(std::span<const std::uint8_t> chunk, const Good& good, const Damaged& damaged);
  // Bytes of an unfinished mark held back (0, 1: FF, or 2: FF 00).
  [[nodiscard]] std::size_t pending() const noexcept { return pending_; }
  [[nodiscard]] std::uint64_t damaged_count() const noexcept { return damaged_; }
  // FF followed by a byte other than FF or 00 (termios never sends it): both delivered as
  // received, counted.
  [[nodiscard]] std::uint64_t stray_marks() const noexcept { return stray_; }

 private:
  std::size_t pending_ = 0;
  std::uint64_t damaged_ = 0;
  std::uint64_t stray_ = 0;
  std::vector<std::uint8_t> run_;
};

}  // namespace rs4sim::stream
