#include "polaris/model.h"

#include <gtest/gtest.h>

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
      {80, 8},      {100, 10},    {120, 12},    {140, 14},    {160, 16},    {180, 18},
      {200, 20},    {220, 22},    {240, 24},    {260, 26},    {280, 28},    {300, 30},
      {320, 32},    {400, 40},    {480, 48},    {500, 50},    {560, 56},    {640, 64},
      {720, 72},    {800, 80},    {880, 88},    {960, 96},    {1040, 104},  {1120, 112},
      {1200, 120},  {1280, 128},  {1360, 136},  {1440, 144},  {1520, 152},  {1600, 160},
      {1680, 168},  {1760, 176},  {1840, 184},  {1920, 192},  {2000, 200},  {2080, 208},
      {2160, 216},  {2240, 224},  {2320, 232},  {2400, 240},  {2480, 248},  {2560, 256},
      {2640, 264},  {2720, 272},  {2800, 280},  {2880, 288},  {2960, 296},  {3040, 304},
      {3120, 312},  {3200, 320},  {3280, 328},  {3360, 336},  {3440, 344}};
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

TEST(Model, Names) {
  EXPECT_EQ(to_string(Family::kPli05), "PLi05");
  EXPECT_EQ(parse_family("PL48"), Family::kPl48);
  EXPECT_FALSE(parse_family("PL 48"));
}

}  // namespace
}  // namespace rs4sim::polaris
