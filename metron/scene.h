#pragma once
// What the curtain sees: which beams are interrupted, the level of its input, and whether
// the Transmitter and Receiver are optically synchronised. Beams are numbered from 1 (the
// first beam) as in the manual's beam-status example [METRON manual "Request active beam
// status command"]. The measurement values are the project's EXTENSION (wire_table.h).

#include "codec/error_category.h"
#include "metron/wire_table.h"

#include <cstdint>
#include <span>
#include <string_view>
#include <system_error>
#include <vector>

namespace rs4sim::metron {

// Why a scene change was refused.
enum class SceneError : std::uint8_t {
  kNoSuchBeam = 1,  // a beam number outside 1..beams()
};
[[nodiscard]] std::string_view to_string(SceneError e) noexcept;
[[nodiscard]] constexpr const char* error_category_name(SceneError) noexcept {
  return "metron.scene";
}
[[nodiscard]] inline std::error_code make_error_code(SceneError e) noexcept {
  return codec::make_error_code_of(e);
}

class Scene {
 public:
  explicit Scene(std::uint16_t beams) : interrupted_(beams, false) {}

  [[nodiscard]] std::uint16_t beams() const {
    return static_cast<std::uint16_t>(interrupted_.size());
  }
  // The given beams interrupted, the others free. A beam outside 1..beams() refuses the
  // whole call (SceneError::kNoSuchBeam) and changes nothing.
  std::error_code set_interrupted(std::span<const std::uint16_t> beams);
  // The interrupted beams, ascending.
  [[nodiscard]] std::vector<std::uint16_t> interrupted() const;
  // One beam; beam numbers outside 1..beams() are ignored.
  void set_interrupted(std::uint16_t beam, bool interrupted);
  void clear();
  [[nodiscard]] bool interrupted(std::uint16_t beam) const;
  [[nodiscard]] bool any_interrupted() const;

  void set_input(bool high) { input_high_ = high; }
  [[nodiscard]] bool input_high() const { return input_high_; }
  void set_synchronised(bool s) { synchronised_ = s; }
  [[nodiscard]] bool synchronised() const { return synchronised_; }

  // One byte per measurement (values above 255 saturate; beams are at most 255).
  [[nodiscard]] std::uint8_t measure(Measurement m) const;

  // 1 bit per beam from the first beam, ceil(beams/8) bytes, unused bits 0
  // [METRON manual "Request active beam status command"]; the bit order is the table's.
  [[nodiscard]] std::vector<std::uint8_t> packed(bool lsb_first) const;

  friend bool operator==(const Scene&, const Scene&) = default;

 private:
  std::vector<bool> interrupted_;
  bool input_high_ = false;
  bool synchronised_ = true;
};

}  // namespace rs4sim::metron
