// The data storage [Polaris manual §7.4.2]: "Data storage: None: No storage. Object: Store
// the position and maximum length of objects. Hole: Store the position and maximum diameter
// of holes." "Storage mode: Temporary: reset the storage memory after each data
// transmission. Permanent: permanent storage of the last interrupted beam." The model
// (DECISION, docs/decisions.md#polaris-data-storage): the scan with the longest object
// (widest hole) is transmitted; Temporary forgets it after each transmission. Expected
// frames worked out by hand; CRCs computed independently (CRC-16/MODBUS, low byte first).
#include "polaris/storage.h"
#include "tests/polaris/polaris_line.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace rs4sim::polaris {
namespace {

using namespace testing;  // Answers, answers, Bytes, Rig

std::vector<std::uint16_t> beams(std::initializer_list<std::pair<int, int>> runs) {
  std::vector<std::uint16_t> out;
  for (const auto& [first, last] : runs) {
    for (int b = first; b <= last; ++b) out.push_back(static_cast<std::uint16_t>(b));
  }
  return out;
}

// 40 beams: 9..13 and 25..34 interrupted.
std::vector<std::uint8_t> two_objects() {
  std::vector<std::uint8_t> f(40, 0);
  for (const auto b : beams({{9, 13}, {25, 34}})) f[b - 1U] = 1;
  return f;
}

Options storage_options(DataStorage storage, StorageMode mode) {
  Options o;  // PL 10, 40 beams, FL1, slave 1
  o.beams = 40;
  o.mode = DataMode::kFl1;
  o.storage = storage;
  o.storage_mode = mode;
  return o;
}

const Bytes kReadFl1{0x01, 0x03, 0x20, 0x00, 0x00, 0x02, 0xCF, 0xCB};
const Bytes k9To34{0x01, 0x03, 0x04, 0x00, 0x09, 0x00, 0x22, 0xAA, 0x28};   // first 9, last 34
const Bytes k20To22{0x01, 0x03, 0x04, 0x00, 0x14, 0x00, 0x16, 0x3B, 0xF9};  // first 20, last 22
const Bytes k5To34{0x01, 0x03, 0x04, 0x00, 0x05, 0x00, 0x22, 0x6A, 0x2B};   // first 5, last 34
const Bytes kNone{0x01, 0x03, 0x04, 0x00, 0x00, 0x00, 0x00, 0xFA, 0x33};    // no object

TEST(PolarisStorage, SizeIsTheLongestObjectOrTheWidestHole) {
  const auto f = two_objects();
  EXPECT_EQ(stored_size(DataStorage::kObject, f), 10U);  // 25..34
  EXPECT_EQ(stored_size(DataStorage::kHole, f), 11U);    // 14..24, between the objects
  EXPECT_EQ(stored_size(DataStorage::kNone, f), 0U);
  // Free beams at either end are no hole: 1..8 and 35..40 are not between two objects.
  std::vector<std::uint8_t> one(40, 0);
  one[19] = 1;
  EXPECT_EQ(stored_size(DataStorage::kHole, one), 0U);
  EXPECT_EQ(stored_size(DataStorage::kObject, one), 1U);
}

TEST(PolarisStorage, NoneTransmitsTheScanInView) {
  Rig r(storage_options(DataStorage::kNone, StorageMode::kTemporary));
  ASSERT_FALSE(r.device().set_interrupted(beams({{9, 13}, {25, 34}}), r.now()));
  ASSERT_FALSE(r.device().set_interrupted(beams({{20, 22}}), r.now()));
  EXPECT_EQ(answers(r, kReadFl1), (Answers{k20To22}));
}

TEST(PolarisStorage, TemporaryObjectSendsTheLongestSinceTheLastTransmission) {
  Rig r(storage_options(DataStorage::kObject, StorageMode::kTemporary));
  ASSERT_FALSE(r.device().set_interrupted(beams({{9, 13}, {25, 34}}), r.now()));  // longest 10
  ASSERT_FALSE(r.device().set_interrupted(beams({{20, 22}}), r.now()));           // 3
  EXPECT_EQ(answers(r, kReadFl1), (Answers{k9To34}));  // the stored scan
  // Reset by that transmission: now the scan in view.
  EXPECT_EQ(answers(r, kReadFl1), (Answers{k20To22}));
  ASSERT_FALSE(r.device().set_interrupted({}, r.now()));
  EXPECT_EQ(answers(r, kReadFl1), (Answers{k20To22}));  // stored until this transmission
  EXPECT_EQ(answers(r, kReadFl1), (Answers{kNone}));
}

TEST(PolarisStorage, PermanentKeepsItAfterTheObjectLeft) {
  Rig r(storage_options(DataStorage::kObject, StorageMode::kPermanent));
  ASSERT_FALSE(r.device().set_interrupted(beams({{9, 13}, {25, 34}}), r.now()));
  ASSERT_FALSE(r.device().set_interrupted({}, r.now()));
  EXPECT_EQ(answers(r, kReadFl1), (Answers{k9To34}));
  EXPECT_EQ(answers(r, kReadFl1), (Answers{k9To34}));
  // A smaller object does not replace it; a longer one does.
  ASSERT_FALSE(r.device().set_interrupted(beams({{20, 22}}), r.now()));
  EXPECT_EQ(answers(r, kReadFl1), (Answers{k9To34}));
  ASSERT_FALSE(r.device().set_interrupted(beams({{5, 34}}), r.now()));  // 30 beams
  EXPECT_EQ(answers(r, kReadFl1), (Answers{k5To34}));
  EXPECT_EQ(r.device().storage().size(), 30U);
}

TEST(PolarisStorage, HoleKeepsTheScanWithTheWidestHole) {
  Rig r(storage_options(DataStorage::kHole, StorageMode::kTemporary));
  ASSERT_FALSE(r.device().set_interrupted(beams({{9, 13}, {25, 34}}), r.now()));  // hole 11
  ASSERT_FALSE(r.device().set_interrupted(beams({{5, 34}}), r.now()));           // no hole
  EXPECT_EQ(answers(r, kReadFl1), (Answers{k9To34}));
  EXPECT_EQ(answers(r, kReadFl1), (Answers{k5To34}));  // reset: the scan in view
}

}  // namespace
}  // namespace rs4sim::polaris
