// SVG pictures: well-formed XML (parsed with Boost.PropertyTree's XML reader), 4 panels,
// deterministic bytes, coordinates computed by hand, escaped text.
#include "rs4/report/field_svg.h"

#include <boost/property_tree/ptree.hpp>
#include <boost/property_tree/xml_parser.hpp>
#include <gtest/gtest.h>

#include <sstream>

namespace rs4sim::rs4::report {
namespace {

using scanner::factory_default;

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto pos = text.find(what); pos != std::string::npos; pos = text.find(what, pos + 1)) ++n;
  return n;
}

// Throws boost::property_tree::xml_parser_error when the text is not well-formed XML.
boost::property_tree::ptree parse(const std::string& svg) {
  std::istringstream in(svg);
  boost::property_tree::ptree tree;
  boost::property_tree::read_xml(in, tree);
  return tree;
}

TEST(FieldSvg, FourPanelsWellFormed) {
  const std::string svg = field_svg(factory_default(), "station default/4 <v1> & \"x\"");
  boost::property_tree::ptree tree;
  ASSERT_NO_THROW(tree = parse(svg));
  std::size_t panels = 0;
  for (const auto& [name, child] : tree.get_child("svg")) {
    if (name == "g" && child.get<std::string>("<xmlattr>.class", "") == "panel") ++panels;
  }
  EXPECT_EQ(panels, 4U);
  EXPECT_EQ(tree.get<std::string>("svg.title"), "station default/4 <v1> & \"x\"");
  EXPECT_NE(svg.find("station default/4 &lt;v1&gt; &amp; &quot;x&quot;"), std::string::npos);
  EXPECT_EQ(count(svg, "<path class=\"protective\""), 4U + 1U);  // 4 panels + legend
  EXPECT_EQ(count(svg, "<path class=\"warning\""), 4U + 1U);
  EXPECT_EQ(svg, field_svg(factory_default(), "station default/4 <v1> & \"x\""));
}

TEST(FieldSvg, CoordinatesAndScale) {
  // Largest value 3500 mm (pair 4 warning) → rings every 1000 mm up to 4000 mm = 180 px,
  // 0.045 px/mm. Scanner at (210, 216) in its panel. Pair 1 protective 1000 mm = 45 px:
  // segment 14 (0°) at (255, 216), segment 264 (90°) at (210, 171).
  const std::string svg = field_svg(factory_default(), "t");
  EXPECT_EQ(count(svg, "class=\"ring\""), 4U * 4U);
  EXPECT_NE(svg.find(">1.0 m</text>"), std::string::npos);
  EXPECT_NE(svg.find(">4.0 m</text>"), std::string::npos);
  EXPECT_EQ(svg.find(">5.0 m</text>"), std::string::npos);
  const auto pair1 = svg.find("id=\"pair-1\"");
  const auto protective = svg.find("<path class=\"protective\"", pair1);
  const auto end = svg.find("/>", protective);
  const std::string path = svg.substr(protective, end - protective);
  EXPECT_NE(path.find("d=\"M210.0 216.0L"), std::string::npos) << path.substr(0, 200);
  EXPECT_NE(path.find("L255.0 216.0L"), std::string::npos);
  EXPECT_NE(path.find("L210.0 171.0L"), std::string::npos);
  EXPECT_EQ(count(path, "L"), 529U);
  EXPECT_NE(svg.find("pair 1 (start)</text>"), std::string::npos);
}

TEST(FieldSvg, DiffOverlaysOldDashedWithLegend) {
  auto changed = factory_default();
  for (std::size_t n = 100; n <= 140; ++n) changed.pairs[1].protective_mm[n] = 1850;
  const std::string svg =
      field_diff_svg(factory_default(), changed, {"diff 3 -> 7", "version 3", "version <7>"});
  ASSERT_NO_THROW(parse(svg));
  EXPECT_EQ(count(svg, "class=\"panel\""), 4U);
  EXPECT_EQ(count(svg, "<path class=\"old-protective\""), 4U + 1U);
  EXPECT_EQ(count(svg, "<path class=\"old-warning\""), 4U + 1U);
  EXPECT_EQ(count(svg, "stroke-dasharray=\"4 3\""), 2U * 5U);
  EXPECT_NE(svg.find(">version 3 protective</text>"), std::string::npos);
  EXPECT_NE(svg.find(">version &lt;7&gt; warning</text>"), std::string::npos);
  EXPECT_NE(svg.find("diff 3 -&gt; 7"), std::string::npos);
}

TEST(FieldSvg, ExtremeSetsScaleAndStayWellFormed) {
  // Every warning segment at the 15 m limit: rings every 5 m, 3 of them.
  auto far = factory_default();
  for (auto& pair : far.pairs) pair.warning_mm.fill(scanner::kMaxWarningMm);
  const std::string svg = field_svg(far, "far");
  ASSERT_NO_THROW(parse(svg));
  EXPECT_EQ(count(svg, "class=\"ring\""), 4U * 3U);
  EXPECT_NE(svg.find(">15.0 m</text>"), std::string::npos);
  // No field at all: one 0.5 m ring, every contour point at the scanner.
  auto empty = factory_default();
  for (auto& pair : empty.pairs) pair = {};
  const std::string none = field_diff_svg(far, empty, {"", "", ""});
  ASSERT_NO_THROW(parse(none));
  EXPECT_EQ(count(field_svg(empty, ""), "class=\"ring\""), 4U * 1U);
  EXPECT_NE(field_svg(empty, "").find(">0.5 m</text>"), std::string::npos);
}

TEST(FieldSvg, XmlEscape) { EXPECT_EQ(xml_escape("a&<>\"'b"), "a&amp;&lt;&gt;&quot;&apos;b"); }

}  // namespace
}  // namespace rs4sim::rs4::report
