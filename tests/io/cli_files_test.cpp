// The command line and users' files: a missing or bad input file is exit code 1 with one line
// naming it (never CLI11's own codes).
#include "import_test_util.h"
#include "support/cli_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>

namespace swept::test {
namespace {

namespace fs = std::filesystem;

std::size_t lines(const std::string& text) { return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')); }

TEST(CliFiles, MissingInputIsExitCodeOneWithOneLineNamingIt) {
  const auto dir = scratch_dir();
  const std::string none = (dir / "none.stl").string();
  const std::string toml = (dir / "none.toml").string();
  for (const std::string& args : {"bvh " + none, "mesh-stats " + none, "bench queries " + none + " " + none,
                                  "plan " + toml, "view " + toml + " " + (dir / "none.json").string() + " -o " +
                                                      (dir / "v.html").string()}) {
    const CliRun r = run_cli(args);
    EXPECT_EQ(r.code, 1) << args << "\n" << r.out;
    EXPECT_NE(r.out.find("none."), std::string::npos) << args << "\n" << r.out;
    EXPECT_EQ(lines(r.out), 1u) << args << "\n" << r.out;
  }
  // Other command-line mistakes are bad input too.
  for (const std::string& args : {std::string("bvh"), "bvh " + none + " --no-such-option", std::string(""),
                                  "bvh " + none + " --threads 4294967297", std::string("no-such-command")}) {
    const CliRun r = run_cli(args);
    EXPECT_EQ(r.code, 1) << args << "\n" << r.out;
    EXPECT_EQ(lines(r.out), 1u) << args << "\n" << r.out;
  }
  EXPECT_EQ(run_cli("--help").code, 0);
  EXPECT_EQ(run_cli("bvh --help").code, 0);
  EXPECT_EQ(run_cli("--version").code, 0);
  EXPECT_TRUE(fs::is_empty(dir));
}

TEST(CliFiles, ABadMeshIsExitCodeOneNamingTheFileAndLine) {
  const auto dir = scratch_dir();
  const auto ply = write_file(dir / "bad.ply",
                              "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                              "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
                              "0 0 0\n1 0 0\n0 1 0\n3 0 1 2000000000\n");
  for (const char* cmd : {"bvh ", "mesh-stats "}) {
    const CliRun r = run_cli(cmd + ply.string());
    EXPECT_EQ(r.code, 1) << r.out;
    EXPECT_NE(r.out.find(ply.string() + ": line 13"), std::string::npos) << r.out;
    EXPECT_EQ(lines(r.out), 1u) << r.out;
  }
}

}  // namespace
}  // namespace swept::test
