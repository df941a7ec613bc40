#include "rs4/report/field_svg.h"

#include "rs4/report/parameter_fields.h"

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

namespace rs4sim::rs4::report {
namespace {

using scanner::ParameterSet;

// Layout in SVG user units (px): 2 x 2 panels under a title line, a legend below.
constexpr int kPanelWidth = 420;
constexpr int kPanelHeight = 250;
constexpr int kMargin = 10;
constexpr int kTitleHeight = 36;
constexpr int kLegendHeight = 30;
constexpr int kWidth = 2 * kPanelWidth + 3 * kMargin;
constexpr int kHeight = kTitleHeight + 2 * kPanelHeight + kMargin + kLegendHeight;
constexpr double kOriginX = kPanelWidth / 2.0;  // the scanner inside its panel
constexpr double kOriginY = kPanelHeight - 34.0;
constexpr double kRadius = 180.0;  // px of the outermost ring
constexpr int kMaxRings = 5;

constexpr std::string_view kProtectiveStyle =
    R"(class="protective" fill="#e53935" fill-opacity="0.35" stroke="#c62828" stroke-width="1")";
constexpr std::string_view kWarningStyle =
    R"(class="warning" fill="none" stroke="#fb8c00" stroke-width="1.5")";
constexpr std::string_view kOldProtectiveStyle =
    R"(class="old-protective" fill="none" stroke="#616161" stroke-width="1" stroke-dasharray="4 3")";
constexpr std::string_view kOldWarningStyle =
    R"(class="old-warning" fill="none" stroke="#9e9e9e" stroke-width="1" stroke-dasharray="4 3")";

std::string num(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.1f", v);
  return b;
}

// Scale: ring spacing and the distance of the outermost ring, from the largest value drawn.
struct Scale {
  int step_mm = 500;
  int rings = 2;
  [[nodiscard]] double px_per_mm() const { return kRadius / (step_mm * rings); }
};

Scale scale_for(std::uint16_t max_mm) {
  for (const int step : {500, 1000, 2000, 2500, 5000}) {
    const int rings = std::max(1, (max_mm + step - 1) / step);
    if (rings <= kMaxRings) return {step, rings};
  }
  return {5000, 3};  // 15000 mm, the warning limit
}

std::uint16_t max_of(const ParameterSet& set) {
  std::uint16_t max_mm = 0;
  for (const auto& pair : set.pairs) {
    max_mm = std::max(
        {max_mm, contour_stats(pair.protective_mm).max_mm, contour_stats(pair.warning_mm).max_mm});
  }
  return max_mm;
}

// Point at `mm` along segment n's beam, in panel coordinates (y grows downwards).
std::string point(std::size_t n, double mm, const Scale& s) {
  const auto& beams = scanner::beam_table();
  const double r = mm * s.px_per_mm();
  return num(kOriginX + r * beams.cos[n]) + " " + num(kOriginY - r * beams.sin[n]);
}

std::string contour_path(const scanner::Contour& contour, const Scale& s, std::string_view style) {
  std::string d = "M" + num(kOriginX) + " " + num(kOriginY);
  for (std::size_t n = 0; n < scanner::kSegmentCount; ++n) d += "L" + point(n, contour[n], s);
  return "<path " + std::string(style) + " d=\"" + d + "Z\"/>\n";
}

std::string rings(const Scale& s) {
  std::string out;
  const std::size_t last = scanner::kSegmentCount - 1;
  for (int k = 1; k <= s.rings; ++k) {
    const double mm = k * s.step_mm;
    const double r = mm * s.px_per_mm();
    // The arc spans the scanned sector, segment 0 to 528 (190.08°: the large arc).
    out += "<path class=\"ring\" fill=\"none\" stroke=\"#bdbdbd\" stroke-width=\"0.5\" d=\"M" +
           point(0, mm, s) + "A" + num(r) + " " + num(r) + " 0 1 0 " + point(last, mm, s) +
           "\"/>\n";
    out += "<text class=\"ring-label\" x=\"" + num(kOriginX + r) + "\" y=\"" + num(kOriginY + 26) +
           "\" font-size=\"9\" text-anchor=\"middle\" fill=\"#757575\">" + num(mm / 1000.0) +
           " m</text>\n";
  }
  for (const std::size_t n : {std::size_t{0}, last}) {
    out += "<path class=\"sector\" stroke=\"#bdbdbd\" stroke-width=\"0.5\" d=\"M" + num(kOriginX) +
           " " + num(kOriginY) + "L" + point(n, s.step_mm * s.rings, s) + "\"/>\n";
  }
  return out;
}

struct Layer {
  const ParameterSet* set;
  std::string_view protective_style;
  std::string_view warning_style;
};

std::string panel(std::size_t p, const Scale& s, const std::vector<Layer>& layers, int start_pair) {
  const int col = static_cast<int>(p % 2);
  const int row = static_cast<int>(p / 2);
  const int x = kMargin + col * (kPanelWidth + kMargin);
  const int y = kTitleHeight + row * (kPanelHeight + kMargin);
  std::string out = "<g class=\"panel\" id=\"pair-" + std::to_string(p + 1) +
                    "\" transform=\"translate(" + std::to_string(x) + "," + std::to_string(y) +
                    ")\">\n";
  out += "<rect width=\"" + std::to_string(kPanelWidth) + "\" height=\"" +
         std::to_string(kPanelHeight) + "\" fill=\"#fafafa\" stroke=\"#e0e0e0\"/>\n";
  out += rings(s);
  for (const auto& layer : layers) {
    out += contour_path(layer.set->pairs[p].protective_mm, s, layer.protective_style);
    out += contour_path(layer.set->pairs[p].warning_mm, s, layer.warning_style);
  }
  out += "<circle cx=\"" + num(kOriginX) + "\" cy=\"" + num(kOriginY) +
         "\" r=\"3\" fill=\"#212121\"/>\n";
  out += "<text x=\"8\" y=\"16\" font-size=\"13\" font-weight=\"bold\">pair " +
         std::to_string(p + 1) + (static_cast<int>(p + 1) == start_pair ? " (start)" : "") +
         "</text>\n";
  return out + "</g>\n";
}

struct LegendEntry {
  std::string_view style;
  std::string label;
};

std::string legend(const std::vector<LegendEntry>& entries) {
  std::string out = "<g class=\"legend\" transform=\"translate(" + std::to_string(kMargin) + "," +
                    std::to_string(kHeight - kLegendHeight + 8) + ")\">\n";
  int x = 0;
  for (const auto& e : entries) {
    out += "<path " + std::string(e.style) + " d=\"M" + std::to_string(x) + " 2h24v10h-24Z\"/>\n";
    out += "<text x=\"" + std::to_string(x + 30) + "\" y=\"11\" font-size=\"11\">" +
           xml_escape(e.label) + "</text>\n";
    x += 40 + static_cast<int>(e.label.size()) * 6;
  }
  return out + "</g>\n";
}

std::string document(std::string_view title, std::uint16_t max_mm, const std::vector<Layer>& layers,
                     const std::vector<LegendEntry>& entries, int start_pair) {
  const Scale s = scale_for(max_mm);
  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + std::to_string(kWidth) +
         "\" height=\"" + std::to_string(kHeight) + "\" viewBox=\"0 0 " + std::to_string(kWidth) +
         " " + std::to_string(kHeight) + "\" font-family=\"sans-serif\">\n";
  out += "<title>" + xml_escape(title) + "</title>\n";
  out += "<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n";
  out += "<text x=\"" + std::to_string(kMargin) + "\" y=\"24\" font-size=\"16\">" +
         xml_escape(title) + "</text>\n";
  for (std::size_t p = 0; p < scanner::kFieldPairCount; ++p) out += panel(p, s, layers, start_pair);
  out += legend(entries);
  return out + "</svg>\n";
}

}  // namespace

std::string xml_escape(std::string_view text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string field_svg(const ParameterSet& set, std::string_view title) {
  return document(title, max_of(set), {{&set, kProtectiveStyle, kWarningStyle}},
                  {{kProtectiveStyle, "protective field"}, {kWarningStyle, "warning field"}},
                  set.start_pair);
}

std::string field_diff_svg(const ParameterSet& old_set, const ParameterSet& new_set,
                           const DiffLabels& labels) {
  const std::string old_label(labels.old_label);
  const std::string new_label(labels.new_label);
  return document(labels.title, std::max(max_of(old_set), max_of(new_set)),
                  {{&new_set, kProtectiveStyle, kWarningStyle},
                   {&old_set, kOldProtectiveStyle, kOldWarningStyle}},
                  {{kProtectiveStyle, new_label + " protective"},
                   {kWarningStyle, new_label + " warning"},
                   {kOldProtectiveStyle, old_label + " protective"},
                   {kOldWarningStyle, old_label + " warning"}},
                  new_set.start_pair);
}

}  // namespace rs4sim::rs4::report
