// `swept scene` and `swept bench` run swept-tools (apps/swept/tools_path.h): the arguments and
// the exit code pass through, a missing swept-tools is a clear error, and `swept` itself does
// not link OpenCASCADE's modelling libraries or the peers (what made every command start slowly).
#include "support/cli_support.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace swept {
namespace {

namespace fs = std::filesystem;

/// Runs `command` in a shell; stdout and stderr together.
test::CliRun shell(const std::string& command) { return test::run_shell(command + " 2>&1"); }

TEST(ToolsCli, SceneAndBenchRunThroughSweptWithTheirExitCodes) {
  const test::CliRun list = test::run_cli("scene --list");
  ASSERT_EQ(list.code, 0) << list.out;
  EXPECT_NE(list.out.find("house"), std::string::npos) << list.out;
  EXPECT_NE(list.out.find("tunnel-console"), std::string::npos) << list.out;
  const fs::path out = fs::temp_directory_path() / ("swept_tools_cli_" + std::to_string(::getpid()));
  const test::CliRun unknown = test::run_cli("scene no-such-scene -o " + out.string());
  EXPECT_EQ(unknown.code, 1) << unknown.out;
  EXPECT_NE(unknown.out.find("swept: error:"), std::string::npos) << unknown.out;
  const test::CliRun bench = test::run_cli("bench queries");  // A and B missing
  EXPECT_EQ(bench.code, 1) << bench.out;
  EXPECT_NE(bench.out.find("(see --help)"), std::string::npos) << bench.out;
  const test::CliRun help = test::run_cli("bench --help");
  EXPECT_EQ(help.code, 0) << help.out;
  EXPECT_NE(help.out.find("queries"), std::string::npos) << help.out;
  EXPECT_NE(help.out.find("paper"), std::string::npos) << help.out;
  fs::remove_all(out);
}

TEST(ToolsCli, VersionNamesTheBuildTreesTools) {
  const test::CliRun v = test::run_cli("--version");
  ASSERT_EQ(v.code, 0) << v.out;
  const std::string line = "scenes and benchmarks (swept scene, swept bench): ";
  const std::size_t at = v.out.find(line);
  ASSERT_NE(at, std::string::npos) << v.out;
  const std::string path = v.out.substr(at + line.size(), v.out.find('\n', at) - at - line.size());
  EXPECT_EQ(fs::path(path).filename(), "swept-tools");
  EXPECT_EQ(path.rfind(fs::weakly_canonical(SWEPT_BINARY_DIR).string(), 0), 0u) << path;
}

TEST(ToolsCli, AMissingOrUnrunnableSweptToolsIsAClearError) {
  const std::string cli = SWEPT_CLI;
  const test::CliRun missing = shell("SWEPT_TOOLS=/nonexistent/swept-tools " + cli + " scene --list");
  EXPECT_EQ(missing.code, 1) << missing.out;
  EXPECT_NE(missing.out.find("`swept scene` runs swept-tools"), std::string::npos) << missing.out;
  EXPECT_NE(missing.out.find("/nonexistent/swept-tools (not there)"), std::string::npos) << missing.out;
  EXPECT_NE(missing.out.find("set SWEPT_TOOLS"), std::string::npos) << missing.out;

  const fs::path text = fs::temp_directory_path() / ("swept_tools_text_" + std::to_string(::getpid()));
  std::ofstream(text) << "not a program\n";
  fs::permissions(text, fs::perms::owner_read | fs::perms::owner_write);
  const test::CliRun plain = shell("SWEPT_TOOLS=" + text.string() + " " + cli + " bench queries a b");
  EXPECT_EQ(plain.code, 1) << plain.out;
  EXPECT_NE(plain.out.find(text.string() + " (not executable)"), std::string::npos) << plain.out;
  // An executable file that is no program: the exec fails and says why.
  fs::permissions(text, fs::perms::owner_all);
  const test::CliRun bad = shell("SWEPT_TOOLS=" + text.string() + " " + cli + " bench queries a b");
  EXPECT_EQ(bad.code, 1) << bad.out;
  EXPECT_NE(bad.out.find(text.string() + " ("), std::string::npos) << bad.out;
  fs::remove(text);
  // The other commands do not need swept-tools.
  const test::CliRun v = shell("SWEPT_TOOLS=/nonexistent/swept-tools " + cli + " --help");
  EXPECT_EQ(v.code, 0) << v.out;
}

TEST(ToolsCli, SweptLinksNeitherOpenCascadeNorThePeers) {
  const test::CliRun needed = shell("readelf -d " + std::string(SWEPT_CLI));
  ASSERT_EQ(needed.code, 0) << needed.out;
  ASSERT_NE(needed.out.find("(NEEDED)"), std::string::npos) << needed.out;
  for (const char* lib : {"libTK", "libfcl", "libompl", "liboctomap"})
    EXPECT_EQ(needed.out.find(lib), std::string::npos) << lib << " is linked into swept:\n" << needed.out;
}

}  // namespace
}  // namespace swept
