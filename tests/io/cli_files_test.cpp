// The command line and users' files: a missing or bad input file is exit code 1 with one line
// naming it (never CLI11's own codes), and an output file is written whole or not at all.
#include "import_test_util.h"
#include "support/cli_support.h"

#include "swept/scenes/box_problems.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>

namespace swept::test {
namespace {

namespace fs = std::filesystem;

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

// Runs `swept ARGS` in a shell that first runs `setup` (e.g. a file size limit).
CliRun run_cli_after(const std::string& setup, const std::string& args) {
  const std::string cmd = setup + "; exec " + std::string(SWEPT_CLI) + " " + args + " 2>&1";
  CliRun r;
  FILE* pipe = ::popen(cmd.c_str(), "r");
  if (!pipe) return r;
  char buf[4096];
  std::size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, pipe)) > 0) r.out.append(buf, n);
  const int status = ::pclose(pipe);
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

TEST(CliFiles, OutputsAreWrittenWholeOrNotAtAll) {
  const auto dir = scratch_dir();
  ASSERT_TRUE(scenes::write_problem_files(scenes::peg_in_hole(), dir.string()).ok());
  const std::string problem = (dir / "problem.toml").string();

  // A device that refuses the bytes: exit 1 naming it (no rename onto /dev/full).
  if (fs::exists("/dev/full")) {
    const CliRun r = run_cli("plan " + problem + " -q -o /dev/full");
    EXPECT_EQ(r.code, 1) << r.out;
    EXPECT_NE(r.out.find("/dev/full: write failed"), std::string::npos) << r.out;
    EXPECT_TRUE(fs::is_character_file("/dev/full"));
  }

  // A write that fails part-way (a file size limit of 1 KiB, SIGXFSZ ignored so write() fails
  // with EFBIG): the earlier file stays as it was and no temporary file is left.
  const fs::path view = dir / "view.html";
  write_file(view, "earlier view\n");
  const CliRun r = run_cli_after("trap '' XFSZ; ulimit -f 1", "plan " + problem + " -q --view " + view.string());
  EXPECT_EQ(r.code, 1) << r.out;
  EXPECT_NE(r.out.find(view.string() + ": write failed"), std::string::npos) << r.out;
  EXPECT_EQ(read_bytes(view), "earlier view\n");
  for (const auto& e : fs::directory_iterator(dir))
    EXPECT_EQ(e.path().filename().string().find(".tmp-"), std::string::npos) << e.path();

  // The same with room to write: the whole file replaces the earlier one.
  const CliRun ok = run_cli("plan " + problem + " -q --view " + view.string() + " -o " + (dir / "p.path").string());
  ASSERT_EQ(ok.code, 0) << ok.out;
  const std::string html = read_bytes(view);
  EXPECT_EQ(html.rfind("</html>\n"), html.size() - 8);
  EXPECT_FALSE(read_bytes(dir / "p.path").empty());
}

}  // namespace
}  // namespace swept::test
