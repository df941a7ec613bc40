#include "polaris/model.h"

#include "polaris/model_tables.inc"

#include <array>
#include <span>
#include <string_view>

namespace rs4sim::polaris {

namespace {

constexpr std::array<std::string_view, 6> kFamilyNames{"PLi02", "PLi05", "PLi12",
                                                      "PL10",  "PL24",  "PL48"};

// The model tables [Polaris manual §2.1, §2.2] as polaris/model_tables.txt gives them, read at
// compile time: a line that does not read (or a family out of its place) throws, which stops
// the build.
class TableReader {
 public:
  explicit constexpr TableReader(std::string_view text) : text_(text) {}

  // The next model row (comment and empty lines skipped); false at the end.
  constexpr bool next(Family& family, Model& model) {
    while (at_ < text_.size()) {
      auto end = text_.find('\n', at_);
      if (end == std::string_view::npos) end = text_.size();
      line_ = text_.substr(at_, end - at_);
      at_ = end + 1;
      pos_ = 0;
      skip_blanks();
      if (pos_ == line_.size() || line_[pos_] == '#') continue;
      family = family_of(word());
      model.h_mm = number();
      model.beams = number();
      model.response_01ms = number();
      model.response_2nd_01ms = number();
      return true;
    }
    return false;
  }

 private:
  constexpr void skip_blanks() {
    while (pos_ < line_.size() && (line_[pos_] == ' ' || line_[pos_] == '\t')) ++pos_;
  }
  constexpr std::string_view word() {
    skip_blanks();
    const std::size_t from = pos_;
    while (pos_ < line_.size() && line_[pos_] != ' ' && line_[pos_] != '\t') ++pos_;
    return line_.substr(from, pos_ - from);
  }
  constexpr std::uint16_t number() {
    const std::string_view w = word();
    if (w.empty() || w.size() > 4) throw "polaris/model_tables.txt: a row needs four numbers";
    std::uint16_t v = 0;
    for (const char c : w) {
      if (c < '0' || c > '9') throw "polaris/model_tables.txt: not a number";
      v = static_cast<std::uint16_t>(v * 10 + (c - '0'));
    }
    return v;
  }
  static constexpr Family family_of(std::string_view name) {
    for (std::size_t i = 0; i < kFamilyNames.size(); ++i) {
      if (kFamilyNames[i] == name) return static_cast<Family>(i);
    }
    throw "polaris/model_tables.txt: not a family name";
  }

  std::string_view text_;
  std::size_t at_ = 0;
  std::string_view line_;
  std::size_t pos_ = 0;
};

constexpr std::size_t row_count(std::string_view text) {
  TableReader reader(text);
  Family f{};
  Model m;
  std::size_t n = 0;
  while (reader.next(f, m)) ++n;
  return n;
}

// Every model, family after family (in the order of Family), and where each family starts.
struct Tables {
  std::array<Model, row_count(detail::kModelTablesText)> models{};
  std::array<std::size_t, kFamilyNames.size() + 1> start{};
};

constexpr Tables read_tables(std::string_view text) {
  Tables t;
  TableReader reader(text);
  Family f{};
  std::size_t n = 0;
  std::size_t family = 0;
  while (reader.next(f, t.models[n])) {
    const auto index = static_cast<std::size_t>(f);
    if (index < family) throw "polaris/model_tables.txt: the families out of their order";
    for (; family < index; ++family) t.start[family + 1] = n;
    ++n;
  }
  for (; family < kFamilyNames.size(); ++family) t.start[family + 1] = n;
  return t;
}

constexpr Tables kTables = read_tables(detail::kModelTablesText);

std::size_t index_of(Family f) noexcept {
  const auto i = static_cast<std::size_t>(f);
  return i < kFamilyNames.size() ? i : 0;
}

}  // namespace

std::string_view to_string(Family f) noexcept { return kFamilyNames[index_of(f)]; }

std::optional<Family> parse_family(std::string_view text) noexcept {
  for (std::size_t i = 0; i < kFamilyNames.size(); ++i) {
    if (kFamilyNames[i] == text) return static_cast<Family>(i);
  }
  return std::nullopt;
}

std::span<const Model> models(Family f) noexcept {
  const std::size_t i = index_of(f);
  return std::span<const Model>(kTables.models)
      .subspan(kTables.start[i], kTables.start[i + 1] - kTables.start[i]);
}

const Model* find_model(Family f, std::uint16_t beams) noexcept {
  for (const Model& m : models(f)) {
    if (m.beams == beams) return &m;
  }
  return nullptr;
}

std::optional<std::uint16_t> beams_for_height(Family f, std::uint16_t h_mm) noexcept {
  for (const Model& m : models(f)) {
    if (m.h_mm == h_mm) return m.beams;
  }
  return std::nullopt;
}

std::optional<std::uint16_t> height_for_beams(Family f, std::uint16_t beams) noexcept {
  if (const Model* m = find_model(f, beams)) return m->h_mm;
  return std::nullopt;
}

BeamRange beam_range(Family f) noexcept {
  const std::span<const Model> m = models(f);
  return {m.front().beams, m.back().beams};
}

}  // namespace rs4sim::polaris
