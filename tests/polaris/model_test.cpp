#include "polaris/model.h"

#include <gtest/gtest.h>

#include <chrono>
#include <utility>
#include <vector>

namespace rs4sim::polaris {
namespace {

TEST(Model, FamilyEndpointsMatchTheManualTables) {
  // [Polaris manual §1.2]: beams of the smallest and the largest body of each family.
  EXPECT_EQ(beams_for_height(Family::kPli02, 100), 31);
  EXPECT_EQ(beams_for_height(Family::kPli02, 3460), 1375);
  EXPECT_EQ(beams_for_height(Family::kPli05, 100), 15);
  EXPECT_EQ(beams_for_height(Family::kPli05, 3460), 687);
  EXPECT_EQ(beams_for_height(Family::kPli12, 116), 7);
  EXPECT_EQ(beams_for_height(Family::kPli12, 3476), 287);
  EXPECT_EQ(beams_for_height(Family::kPl10, 100), 8);
  EXPECT_EQ(beams_for_height(Family::kPl10, 3460), 344);
  EXPECT_EQ(beams_for_height(Family::kPl24, 116), 4);
  EXPECT_EQ(beams_for_height(Family::kPl24, 3476), 144);
  EXPECT_EQ(beams_for_height(Family::kPl48, 212), 4);
  EXPECT_EQ(beams_for_height(Family::kPl48, 2900), 60);
}

TEST(Model, StepsOfTheBodyHeights) {
  EXPECT_EQ(beams_for_height(Family::kPli05, 120), 19);  // 20 mm steps up to 340
  EXPECT_EQ(beams_for_height(Family::kPli05, 340), 63);
  EXPECT_EQ(beams_for_height(Family::kPli05, 420), 79);  // then 80 mm
  EXPECT_FALSE(beams_for_height(Family::kPli05, 360));
  EXPECT_EQ(beams_for_height(Family::kPl10, 180), 16);  // PL 10-160
  EXPECT_FALSE(beams_for_height(Family::kPl10, 110));
  EXPECT_FALSE(beams_for_height(Family::kPl10, 360));  // after PL 10-320: 80 mm steps
  EXPECT_FALSE(beams_for_height(Family::kPl10, 540));
  EXPECT_FALSE(beams_for_height(Family::kPl48, 3000));
}

// Every model of the PL 10 table [Polaris manual §2.2] (model name = h - 20 mm; beams in its
// last column), and no other beam count.
TEST(Model, EveryPl10ModelOfTheManualsTable) {
  const std::vector<std::pair<int, int>> table{
      {80, 8},     {100, 10},   {120, 12},   {140, 14},   {160, 16},   {180, 18},   {200, 20},
      {220, 22},   {240, 24},   {260, 26},   {280, 28},   {300, 30},   {320, 32},   {400, 40},
      {480, 48},   {500, 50},   {560, 56},   {640, 64},   {720, 72},   {800, 80},   {880, 88},
      {960, 96},   {1040, 104}, {1120, 112}, {1200, 120}, {1280, 128}, {1360, 136}, {1440, 144},
      {1520, 152}, {1600, 160}, {1680, 168}, {1760, 176}, {1840, 184}, {1920, 192}, {2000, 200},
      {2080, 208}, {2160, 216}, {2240, 224}, {2320, 232}, {2400, 240}, {2480, 248}, {2560, 256},
      {2640, 264}, {2720, 272}, {2800, 280}, {2880, 288}, {2960, 296}, {3040, 304}, {3120, 312},
      {3200, 320}, {3280, 328}, {3360, 336}, {3440, 344}};
  std::vector<bool> is_model(345, false);
  for (const auto& [model, beams] : table) {
    const auto h = static_cast<std::uint16_t>(model + 20);
    EXPECT_EQ(beams_for_height(Family::kPl10, h), beams) << "PL 10-" << model;
    EXPECT_EQ(height_for_beams(Family::kPl10, static_cast<std::uint16_t>(beams)), h);
    is_model[static_cast<std::size_t>(beams)] = true;
  }
  for (std::uint16_t b = 1; b <= 344; ++b) {
    EXPECT_EQ(height_for_beams(Family::kPl10, b).has_value(), is_model[b]) << b << " beams";
  }
}

TEST(Model, HeightForBeams) {
  EXPECT_EQ(height_for_beams(Family::kPli02, 127), 340);   // 127 beams [Polaris manual §7.4]
  EXPECT_EQ(height_for_beams(Family::kPli12, 127), 1556);  // 2(1556-20)/24-1
  EXPECT_FALSE(height_for_beams(Family::kPl10, 17));
  EXPECT_EQ(beam_range(Family::kPl24).max, 144);
}

// The first maximum response time, read off the manual's tables [Polaris manual §2.1, §2.2]
// (model, beams, ms): both ends of each family and rows in between, some of them rows the
// OCR damaged (PLi 02-2320, PLi 12-1440, PL 48 with 48 beams).
TEST(Model, ResponseTimesOfTheManualsTables) {
  struct Row {
    const char* model;
    Family family;
    std::uint16_t beams;
    std::chrono::microseconds first;
    std::chrono::microseconds second;
  };
  using std::chrono::microseconds;
  // Rows the OCR printed whole (the repaired ones are checked by TheTablesAreConsistent only:
  // their values are the project's reading, not the manual's print).
  const std::vector<Row> rows{
      {"PLi 02-80", Family::kPli02, 31, microseconds(700), microseconds(1100)},
      {"PLi 02-3440", Family::kPli02, 1375, microseconds(19600), microseconds(34700)},
      {"PLi 05-80", Family::kPli05, 15, microseconds(600), microseconds(1000)},
      {"PLi 05-2080", Family::kPli05, 415, microseconds(11800), microseconds(21000)},
      {"PLi 05-3440", Family::kPli05, 687, microseconds(19400), microseconds(34600)},
      {"PLi 12-095", Family::kPli12, 7, microseconds(400), microseconds(600)},
      {"PLi 12-3500", Family::kPli12, 287, microseconds(8200), microseconds(14600)},
      {"PL 10-80", Family::kPl10, 8, microseconds(400), microseconds(600)},
      {"PL 10-500", Family::kPl10, 50, microseconds(1600), microseconds(2700)},
      {"PL 10-3040", Family::kPl10, 304, microseconds(8700), microseconds(15400)},
      {"PL 10-3440", Family::kPl10, 344, microseconds(9800), microseconds(17400)},
      {"PL 24, h 116", Family::kPl24, 4, microseconds(300), microseconds(400)},
      {"PL 24, h 3476", Family::kPl24, 144, microseconds(4200), microseconds(7400)},
      {"PL 48, h 212", Family::kPl48, 4, microseconds(300), microseconds(400)},
      {"PL 48, h 2900", Family::kPl48, 60, microseconds(1900), microseconds(3200)},
  };
  for (const Row& r : rows) {
    const Model* m = find_model(r.family, r.beams);
    ASSERT_NE(m, nullptr) << r.model;
    EXPECT_EQ(m->response_time(), r.first) << r.model;
    EXPECT_EQ(m->response_time_2nd(), r.second) << r.model;
  }
  EXPECT_EQ(find_model(Family::kPl10, 17), nullptr);
}

// The transcription of the tables (read from an OCR, docs in polaris/model.cpp): every beam
// count fits its family's formula, the times rise with the beams, and the second column is
// exactly linear in the beams (0.05 ms a beam; PLi 02: 0.025 ms).
TEST(Model, TheTablesAreConsistent) {
  const auto formula = [](Family f, int h) {
    const int l = h - 20;
    switch (f) {
      case Family::kPli02: return l * 2 / 5 - 1;
      case Family::kPli05: return l / 5 - 1;
      case Family::kPli12: return 2 * l / 24 - 1;
      case Family::kPl10: return l / 10;
      case Family::kPl24: return l / 24;
      case Family::kPl48: return l / 48;
    }
    return 0;
  };
  for (const Family f : {Family::kPli02, Family::kPli05, Family::kPli12, Family::kPl10,
                         Family::kPl24, Family::kPl48}) {
    const auto table = models(f);
    ASSERT_FALSE(table.empty());
    const Model& first = table.front();
    const int per_beam_x4 = f == Family::kPli02 ? 1 : 2;  // 0.1 ms per 4 beams
    for (std::size_t i = 0; i < table.size(); ++i) {
      const Model& m = table[i];
      EXPECT_EQ(m.beams, formula(f, m.h_mm)) << to_string(f) << " h " << m.h_mm;
      EXPECT_EQ(4 * (m.response_2nd_01ms - first.response_2nd_01ms),
                per_beam_x4 * (m.beams - first.beams))
          << to_string(f) << " h " << m.h_mm;
      if (i == 0) continue;
      EXPECT_GT(m.h_mm, table[i - 1].h_mm) << to_string(f) << " h " << m.h_mm;
      EXPECT_GE(m.response_01ms, table[i - 1].response_01ms) << to_string(f) << " h " << m.h_mm;
      EXPECT_LE(m.response_01ms - table[i - 1].response_01ms, 6) << to_string(f) << " h " << m.h_mm;
    }
  }
}

TEST(Model, Names) {
  EXPECT_EQ(to_string(Family::kPli05), "PLi05");
  EXPECT_EQ(parse_family("PL48"), Family::kPl48);
  EXPECT_FALSE(parse_family("PL 48"));
}

}  // namespace
}  // namespace rs4sim::polaris
