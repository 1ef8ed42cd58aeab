// Long work draws one redrawn line on a terminal, and nothing when stderr is not one or with -q.
// `script` (util-linux) runs the command on a pseudo-terminal; a pipe is the other case. The line
// is "\r  <phase>  <done>/<total> ..." followed by the erase-to-end-of-line sequence, and it is
// erased before the command's own output.
#include "assembly/assembly_support.h"
#include "support/cli_support.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace swept {
namespace {

namespace fs = std::filesystem;
using namespace swept::test;

constexpr const char* kErase = "\033[K";

std::string quoted(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

// stdout and stderr of `swept ARGS` on a pseudo-terminal.
CliRun on_terminal(const std::string& args) {
  return run_shell("script -qefc " + quoted(std::string(SWEPT_CLI) + " " + args) + " /dev/null");
}

fs::path bolted_ring_files() {
  const fs::path dir = fs::path(SWEPT_BINARY_DIR) / "tests_apps_scratch" / "progress_bolted";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const Assembly a = bolted_ring();
  std::string toml;
  for (std::size_t i = 0; i < a.parts.size(); ++i) {
    EXPECT_TRUE(write_stl_binary(dir / (a.parts[i].name + ".stl"), a.parts[i].mesh).ok());
    toml += "[[part]]\nfile = \"" + a.parts[i].name + ".stl\"\n" + (i == 0 ? "fixed = true\n" : "");
  }
  std::ofstream(dir / "assembly.toml") << toml;
  return dir / "assembly.toml";
}

bool has_script() { return run_shell("script --version >/dev/null 2>&1").code == 0; }

TEST(ProgressLine, DisassembleDrawsOnATerminalOnly) {
  if (!has_script()) GTEST_SKIP() << "script (util-linux) is missing";
  const fs::path toml = bolted_ring_files();
  const CliRun tty = on_terminal("disassemble " + toml.string());
  ASSERT_EQ(tty.code, 0) << tty.out;
  for (const char* phase : {"\r  trees  ", "\r  interferences  ", "\r  removals  "})
    EXPECT_NE(tty.out.find(phase), std::string::npos) << phase << " in\n" << tty.out;
  EXPECT_NE(tty.out.find("\r  trees  3/3 parts"), std::string::npos) << tty.out;  // a phase's end is always drawn
  // Erased before the report: the last line drawn is followed by "\r" + erase, then the table.
  const std::size_t table = tty.out.find("assembly     ");
  ASSERT_NE(table, std::string::npos) << tty.out;
  EXPECT_EQ(tty.out.rfind(std::string("\r") + kErase, table), table - 4) << tty.out;

  const CliRun quiet = on_terminal("disassemble -q " + toml.string());
  ASSERT_EQ(quiet.code, 0) << quiet.out;
  EXPECT_EQ(quiet.out.find(kErase), std::string::npos) << quiet.out;
  const CliRun piped = run_cli("disassemble " + toml.string());  // stdout and stderr into a pipe
  ASSERT_EQ(piped.code, 0) << piped.out;
  EXPECT_EQ(piped.out.find('\r'), std::string::npos) << piped.out;
}

// A CAD read shows how far OpenCASCADE's meshing is; `swept bvh` and `mesh-stats` read CAD.
TEST(ProgressLine, CadMeshingDrawsPerCent) {
  if (!has_script()) GTEST_SKIP() << "script (util-linux) is missing";
  const auto step = occt_sample("screw.step");
  if (!step) GTEST_SKIP() << "OpenCASCADE's screw.step is missing (occt-misc)";
  const CliRun tty = on_terminal("mesh-stats " + step->string());
  ASSERT_EQ(tty.code, 0) << tty.out;
  EXPECT_NE(tty.out.find("\r  reading screw.step  shapes"), std::string::npos) << tty.out;
  EXPECT_NE(tty.out.find("\r  reading screw.step  meshing  100 %"), std::string::npos) << tty.out;
  const CliRun piped = run_cli("mesh-stats " + step->string());
  ASSERT_EQ(piped.code, 0) << piped.out;
  EXPECT_EQ(piped.out.find('\r'), std::string::npos) << piped.out;
  const CliRun quiet = on_terminal("mesh-stats -q " + step->string());
  EXPECT_EQ(quiet.out.find(kErase), std::string::npos) << quiet.out;
}

}  // namespace
}  // namespace swept
