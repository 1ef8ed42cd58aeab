// `swept bench paper` replaces results.json and report.md whole (a temporary file renamed into
// place), never by rewriting the old file in place: a reader holding the old file keeps it whole.
#include "support/cli_support.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace swept::test {
namespace {

namespace fs = std::filesystem;

#ifdef SWEPT_CLI

std::string read_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream os;
  os << in.rdbuf();
  return os.str();
}

TEST(BenchPaperWrite, ResultsAndReportAreReplacedByRenameNotRewrittenInPlace) {
  const fs::path dir = fs::path(SWEPT_BINARY_DIR) / "test_output" / "bench_paper_write";
  fs::remove_all(dir);
  fs::create_directories(dir);
  // A second hard link sees an in-place rewrite, but not a rename over the name.
  for (const char* name : {"results.json", "report.md"}) {
    std::ofstream(dir / name) << "old " << name << "\n";
    fs::create_hard_link(dir / name, dir / (std::string("held_") + name));
  }
  const CliRun r = run_cli("bench paper --no-scenes --no-cad --no-ompl --out '" + dir.string() + "'");
  ASSERT_EQ(r.code, 0) << r.out;
  for (const char* name : {"results.json", "report.md"}) {
    EXPECT_EQ(read_text(dir / (std::string("held_") + name)), std::string("old ") + name + "\n") << name;
    EXPECT_NE(read_text(dir / name).find("INERTIA_FIT"), std::string::npos) << name;
  }
  for (const auto& entry : fs::directory_iterator(dir))
    EXPECT_NE(entry.path().filename().string().rfind(".", 0), 0u) << "temporary file left: " << entry.path();
}

#endif

}  // namespace
}  // namespace swept::test
