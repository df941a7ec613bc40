#include "polaris/model.h"

#include <gtest/gtest.h>

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
  EXPECT_FALSE(beams_for_height(Family::kPl10, 120));
  EXPECT_EQ(beams_for_height(Family::kPl10, 180), 16);  // PL 10-160
  EXPECT_FALSE(beams_for_height(Family::kPl48, 3000));
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
