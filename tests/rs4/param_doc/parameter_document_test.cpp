// The parameter document (docs/param.md) against hand-written documents in data/: the
// factory default as `get` must print it, and a workshop set written with every contour
// form, whose encoded bytes are written by hand from docs/rs4-scanner.md "Encoding".
#include "rs4/param_doc/parameter_document.h"

#include "rs4/scanner/parameter_codec.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <vector>

namespace rs4sim::rs4::param_doc {
namespace {

using scanner::ParameterSet;

std::string read_data(const char* name) {
  std::ifstream in(std::string(RS4SIM_PARAM_DOC_DATA) + "/" + name);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::uint16_t u16_at(const std::vector<std::uint8_t>& b, std::size_t offset) {
  return static_cast<std::uint16_t>((b[offset] << 8) | b[offset + 1]);
}

constexpr std::size_t kPair = scanner::kParameterPairSize;    // 2116 bytes a pair
constexpr std::size_t kWarning = 2 * scanner::kSegmentCount;  // warning after protective

std::size_t contour_offset(std::size_t pair, bool warning, std::size_t segment) {
  return scanner::kParameterHeaderSize + (pair - 1) * kPair + (warning ? kWarning : 0) +
         2 * segment;
}

TEST(ParameterDocument, FactoryDefaultPrintsTheHandWrittenDocument) {
  EXPECT_EQ(to_document(scanner::factory_default()), read_data("factory_default.json"));
}

TEST(ParameterDocument, HandWrittenFactoryDocumentReadsBackToTheFactorySet) {
  ParameterSet base = scanner::factory_default();
  base.response_steps = 9;  // every key of the document overrides the base
  base.pairs[2].warning_mm.fill(7);
  const auto result = from_document(read_data("factory_default.json"), base);
  ASSERT_TRUE(result) << result.issue.message();
  EXPECT_EQ(*result.set, scanner::factory_default());
}

TEST(ParameterDocument, RoundTripIsIdentityAndKeepsPasswordsAndIdentity) {
  ParameterSet set = scanner::factory_default();
  set.identity = {0x0A0B0C0D, 4, 2, 7};
  set.passwords[0] = {'R', 'O', 'D', '4', 'L', 'E', 0xFF, 0xFF};
  set.pairs[1].protective_mm[100] = 0;
  set.pairs[3].warning_mm[528] = 15000;
  const std::string doc = to_document(set);
  EXPECT_EQ(doc.find("ROD4"), std::string::npos);  // passwords never printed
  EXPECT_EQ(doc.find("password"), std::string::npos);
  const auto back = from_document(doc, set);
  ASSERT_TRUE(back) << back.issue.message();
  EXPECT_EQ(scanner::encode(*back.set), scanner::encode(set));
  // The base's passwords and identity, whatever the document's "device" says.
  const auto onto_factory = from_document(doc, scanner::factory_default());
  ASSERT_TRUE(onto_factory);
  EXPECT_EQ(onto_factory.set->passwords, scanner::factory_default().passwords);
  EXPECT_EQ(onto_factory.set->identity, scanner::factory_default().identity);
}

TEST(ParameterDocument, WorkshopDocumentEncodesToTheHandWrittenBytes) {
  const auto result = from_document(read_data("workshop.json"), scanner::factory_default());
  ASSERT_TRUE(result) << result.issue.message();
  const auto bytes = scanner::encode(*result.set);
  const std::vector<std::uint8_t> header(bytes.begin(), bytes.begin() + 27);
  const std::vector<std::uint8_t> expected = {
      0x52, 0x53, 0x34, 0x50,  // 0..3   magic "RS4P"
      0x01, 0x00,              // 4, 5   version 1, reserved
      0x00, 0x00, 0x00, 0x00,  // 6..9   serial number: the base's (factory 0)
      0x00, 0x04, 0x01, 0x00,  // 10..13 device type 4, firmware 1.0: the base's
      0x03,                    // 14     response 200 ms = 80 + 3·40
      0x01,                    // 15     start_interlock
      0x02,                    // 16     start pair 2
      0x03,                    // 17     from 1: to 1, 2
      0x07,                    // 18     from 2: to 1, 2, 3
      0x0F, 0x0F,              // 19, 20 from 3, 4: not in the document, the base's
      0x03,                    // 21     contamination | warning_field
      0x02,                    // 22     measurement resolution 2
      0x00, 0x0E,              // 23, 24 start segment 14
      0x01, 0x08,              // 25, 26 stop segment 264
  };
  EXPECT_EQ(header, expected);
  for (std::size_t i = 27; i < 43; ++i) EXPECT_EQ(bytes[i], 0xFF) << i;  // passwords: base's
  // Pair 1 protective, sector 0°..90° of 3000 mm: segments 14 (0°) to 264 (90°).
  EXPECT_EQ(u16_at(bytes, contour_offset(1, false, 13)), 0);
  EXPECT_EQ(u16_at(bytes, contour_offset(1, false, 14)), 0x0BB8);
  EXPECT_EQ(u16_at(bytes, contour_offset(1, false, 264)), 0x0BB8);
  EXPECT_EQ(u16_at(bytes, contour_offset(1, false, 265)), 0);
  EXPECT_EQ(u16_at(bytes, contour_offset(1, true, 0)), 2000);  // not in the document
  // Pair 2 protective, rectangle x −1000..1000, y −500..2000 (the scanner inside):
  EXPECT_EQ(u16_at(bytes, contour_offset(2, false, 0)), 1004);    // −5.04°: 1000/cos 5.04°
  EXPECT_EQ(u16_at(bytes, contour_offset(2, false, 14)), 1000);   // 0°: the right edge
  EXPECT_EQ(u16_at(bytes, contour_offset(2, false, 139)), 1414);  // 45°: corner side, √2·1000
  EXPECT_EQ(u16_at(bytes, contour_offset(2, false, 264)), 2000);  // 90°: the far edge
  EXPECT_EQ(u16_at(bytes, contour_offset(2, false, 528)), 1004);  // 185.04°
  // Pair 2 warning, runs: 0..99 4000 mm, 100..528 15000 mm.
  EXPECT_EQ(u16_at(bytes, contour_offset(2, true, 99)), 0x0FA0);
  EXPECT_EQ(u16_at(bytes, contour_offset(2, true, 100)), 0x3A98);
  // Pair 3 warning, triangle (500,500) (1500,500) (1000,1500), the scanner outside it: at 45°
  // the beam leaves it on the edge (1500,500)-(1000,1500) at (1166.7, 1166.7), 1650 mm.
  EXPECT_EQ(u16_at(bytes, contour_offset(3, true, 139)), 1650);
  EXPECT_EQ(u16_at(bytes, contour_offset(3, true, 264)), 0);      // 90° misses it
  EXPECT_EQ(u16_at(bytes, contour_offset(3, false, 264)), 2000);  // protective: the base's
}

TEST(ParameterDocument, PartialDocumentKeepsTheBase) {
  const auto result =
      from_document(R"({"format": 1, "response_time_ms": 640})", scanner::factory_default());
  ASSERT_TRUE(result) << result.issue.message();
  ParameterSet expected = scanner::factory_default();
  expected.response_steps = 14;
  EXPECT_EQ(*result.set, expected);
}

TEST(ParameterDocument, SegmentsFormTakesAll529Values) {
  std::string values;
  for (int n = 0; n < 529; ++n) values += (n == 0 ? "" : ",") + std::to_string(n);
  const auto result =
      from_document(R"({"format":1,"pairs":{"4":{"warning":{"segments":[)" + values + "]}}}}",
                    scanner::factory_default());
  ASSERT_TRUE(result) << result.issue.message();
  for (std::size_t n = 0; n < 529; ++n) EXPECT_EQ(result.set->pairs[3].warning_mm[n], n);
}

}  // namespace
}  // namespace rs4sim::rs4::param_doc
