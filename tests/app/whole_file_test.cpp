// read_whole_file on real files in a temporary directory: the bytes as they are (a NUL and a
// CR included), an empty file as empty text, and the operating system's reason for a missing
// file, a directory and a path through a regular file.
#include "app/runtime/whole_file.h"

#include "tests/scratch_dir.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace rs4sim::app {
namespace {

namespace fs = std::filesystem;

class WholeFileTest : public rs4sim::testing::ScratchDirTest {
 protected:
  WholeFileTest() : ScratchDirTest("rs4sim_whole_file_") {}
  std::string write(const std::string& name, const std::string& bytes) {
    return write_file(name, bytes);
  }
};

TEST_F(WholeFileTest, ReadsEveryByteAsItIs) {
  const std::string bytes("a\0b\r\n\xff", 6);
  const auto f = read_whole_file(write("bin", bytes));
  ASSERT_TRUE(f) << f.error;
  EXPECT_EQ(f.bytes, bytes);
}

TEST_F(WholeFileTest, AnEmptyFileIsEmptyTextNotAnError) {
  const auto f = read_whole_file(write("empty", ""));
  ASSERT_TRUE(f) << f.error;
  EXPECT_EQ(f.bytes, "");
}

TEST_F(WholeFileTest, ReasonsAreTheOperatingSystemsWords) {
  EXPECT_EQ(read_whole_file((dir_ / "none").string()).error, "No such file or directory");
  EXPECT_EQ(read_whole_file(dir_.string()).error, "Is a directory");
  const auto file = write("plain", "x");
  EXPECT_EQ(read_whole_file(file + "/below").error, "Not a directory");
  EXPECT_FALSE(read_whole_file(dir_.string()));
}

}  // namespace
}  // namespace rs4sim::app
