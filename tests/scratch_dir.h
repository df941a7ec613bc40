// A fresh folder for the files one test writes.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <utility>

namespace rs4sim::testing {

// An empty folder below the system's temporary folder, named `prefix` + the run's random seed +
// the running test's name: tests of parallel runs (ctest -j) never share one.
inline std::filesystem::path fresh_test_dir(const std::string& prefix) {
  const auto* unit = ::testing::UnitTest::GetInstance();
  const auto dir = std::filesystem::temp_directory_path() /
                   (prefix + std::to_string(unit->random_seed()) + "_" +
                    unit->current_test_info()->name());
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

// A test that writes files into its fresh folder `dir_`, removed after the test.
class ScratchDirTest : public ::testing::Test {
 protected:
  explicit ScratchDirTest(std::string prefix) : prefix_(std::move(prefix)) {}
  void SetUp() override { dir_ = fresh_test_dir(prefix_); }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  // Writes `bytes` to the file `name` in the folder; its path.
  std::string write_file(const std::string& name, const std::string& bytes) {
    const auto path = (dir_ / name).string();
    std::ofstream(path, std::ios::binary) << bytes;
    return path;
  }

  std::string prefix_;
  std::filesystem::path dir_;
};

}  // namespace rs4sim::testing
