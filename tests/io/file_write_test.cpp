// write_file_atomically(): whole files or nothing, devices written in place, errors named.
#include "import_test_util.h"

#include "swept/io/file_write.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>
#include <sys/stat.h>

namespace swept::test {
namespace {

namespace fs = std::filesystem;

// Every entry of `dir`, to see that no temporary file is left behind.
std::vector<std::string> entries(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

TEST(WriteFile, WritesAndReplacesWholeFilesKeepingPermissions) {
  const auto dir = scratch_dir();
  const fs::path file = dir / "out.json";
  ASSERT_TRUE(write_file_atomically(file, "first\n").ok());
  EXPECT_EQ(read_bytes(file), "first\n");
  ::chmod(file.c_str(), 0640);
  ASSERT_TRUE(write_file_atomically(file, "second, longer\n").ok());
  EXPECT_EQ(read_bytes(file), "second, longer\n");
  struct stat st {};
  ASSERT_EQ(::stat(file.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0640u);
  ASSERT_TRUE(write_file_atomically(file, "").ok());
  EXPECT_EQ(read_bytes(file), "");
  EXPECT_EQ(entries(dir), std::vector<std::string>{"out.json"});
}

TEST(WriteFile, FollowsASymbolicLinkAndKeepsIt) {
  const auto dir = scratch_dir();
  write_file(dir / "real.txt", "old");
  fs::create_symlink("real.txt", dir / "link.txt");
  ASSERT_TRUE(write_file_atomically(dir / "link.txt", "new").ok());
  EXPECT_TRUE(fs::is_symlink(dir / "link.txt"));
  EXPECT_EQ(read_bytes(dir / "real.txt"), "new");
  EXPECT_EQ(entries(dir), (std::vector<std::string>{"link.txt", "real.txt"}));
}

TEST(WriteFile, ErrorsNameTheFileAndLeaveNothing) {
  const auto dir = scratch_dir();
  const auto missing = write_file_atomically(dir / "no_such_folder" / "out.json", "x");
  expect_error(missing, {(dir / "no_such_folder" / "out.json").string(), "temporary file", "No such file"});
  expect_error(write_file_atomically(dir, "x"), {dir.string(), "is a directory"});
  expect_error(write_file_atomically("", "x"), {"empty name"});
  EXPECT_TRUE(entries(dir).empty());
}

// A device cannot be replaced by a rename: it is written in place and its errors are reported.
TEST(WriteFile, DevicesAreWrittenInPlaceAndTheirErrorsReported) {
  if (!fs::exists("/dev/full") || !fs::exists("/dev/null")) GTEST_SKIP() << "no /dev/full or /dev/null";
  expect_error(write_file_atomically("/dev/full", std::string(100000, 'x')), {"/dev/full", "write failed", "No space"});
  EXPECT_TRUE(write_file_atomically("/dev/null", "discarded").ok());
  EXPECT_TRUE(fs::is_character_file("/dev/full"));
}

}  // namespace
}  // namespace swept::test
