#pragma once
// Helpers for the import tests: a scratch folder per test and file writers.
#include "swept/io/mesh_io.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

namespace swept::test {

/// A fresh, empty folder for the running test under the build tree.
inline std::filesystem::path scratch_dir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::filesystem::path dir = std::filesystem::path(SWEPT_BINARY_DIR) / "tests_io_scratch" /
                                    (std::string(info->test_suite_name()) + "." + info->name());
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

/// Writes `bytes` to `file` and returns the path.
inline std::filesystem::path write_file(const std::filesystem::path& file, const std::string& bytes) {
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  return file;
}

inline std::string read_bytes(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

/// The committed CAD fixtures (tests/data/io).
inline std::filesystem::path fixture(const std::string& name) {
  return std::filesystem::path(SWEPT_SOURCE_DIR) / "tests" / "data" / "io" / name;
}

/// Asserts that `result` is an error whose message contains every one of `parts`.
template <class T>
void expect_error(const Result<T>& result, std::initializer_list<std::string> parts) {
  ASSERT_FALSE(result.ok()) << "expected an error";
  for (const std::string& p : parts)
    EXPECT_NE(result.error().message.find(p), std::string::npos)
        << "message '" << result.error().message << "' lacks '" << p << "'";
}

/// Asserts that importing `file` fails with a message that names the file and contains every one
/// of `parts`.
inline void expect_import_error(const std::filesystem::path& file, std::initializer_list<std::string> parts) {
  const Result<ImportedModel> result = import_mesh(file);
  ASSERT_FALSE(result.ok()) << file << ": expected an error";
  EXPECT_NE(result.error().message.find(file.string()), std::string::npos) << result.error().message;
  for (const std::string& p : parts)
    EXPECT_NE(result.error().message.find(p), std::string::npos)
        << "message '" << result.error().message << "' lacks '" << p << "'";
}

/// Skips the running test when `dir`, a Debian package's sample files, is missing.
#define SKIP_WITHOUT_PACKAGE(dir, package)                                                       \
  if (!std::filesystem::is_directory(dir))                                                       \
  GTEST_SKIP() << (dir) << " is missing: install Debian's " package " (scripts/setup.sh does)"

/// Every file under `dir` (recursively) whose extension, in lower case, is one of `formats`,
/// sorted (so that failures read the same on every run).
inline std::vector<std::filesystem::path> files_under(const std::filesystem::path& dir,
                                                      const std::set<std::string>& formats) {
  std::vector<std::filesystem::path> out;
  for (const auto& e : std::filesystem::recursive_directory_iterator(dir)) {
    std::string ext = e.path().extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (e.is_regular_file() && formats.count(ext)) out.push_back(e.path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

/// The readers' memory limit is not applied under AddressSanitizer (src/io/isolate.h).
#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kAddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr bool kAddressSanitizer = true;
#else
inline constexpr bool kAddressSanitizer = false;
#endif
#else
inline constexpr bool kAddressSanitizer = false;
#endif

/// Reads `file` as a user would: it must give finite triangles, with warnings that start with the
/// file, or fail with one line that starts with the file. Returns whether it read.
inline bool reads_or_fails_naming_the_file(const std::filesystem::path& file, const ImportOptions& options = {}) {
  SCOPED_TRACE(file.string());
  const auto model = import_mesh(file, options);
  if (!model.ok()) {
    const std::string& m = model.error().message;
    EXPECT_EQ(m.rfind(file.string() + ": ", 0), 0u) << m;
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
    return false;
  }
  EXPECT_GT(model->triangle_count(), 0u);
  for (const TriangleSoup& part : model->parts)
    for (const Triangle& t : part.triangles)
      for (int v = 0; v < 3; ++v) EXPECT_TRUE(t[v].allFinite()) << "part " << part.name;
  for (const std::string& w : model->warnings) EXPECT_EQ(w.rfind(file.string() + ": ", 0), 0u) << w;
  return true;
}

}  // namespace swept::test
