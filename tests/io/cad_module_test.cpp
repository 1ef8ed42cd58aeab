// The STEP / IGES / OCCT .brep reader is a module loaded on first use (swept/io/cad_reader.h):
// `swept --version` names the one in use; a missing, broken or foreign module is a one-line error
// naming the file (exit code 1) while every other format still reads; and the swept binary does
// not load OpenCASCADE's data-exchange libraries at start-up.
#include "import_test_util.h"
#include "support/cli_support.h"
#include "swept/io/cad_reader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

namespace swept::test {
namespace {

namespace fs = std::filesystem;

TEST(CadModule, VersionNamesTheModuleInUse) {
  const CliRun r = run_cli("--version", /*with_stderr=*/false);
  ASSERT_EQ(r.code, 0) << r.out;
  const std::string key = "CAD reader (STEP, IGES, OCCT .brep): ";
  const std::size_t at = r.out.find(key);
  ASSERT_NE(at, std::string::npos) << r.out;
  const std::size_t end = r.out.find('\n', at);  // its line (the tools' line follows)
  const std::string path = r.out.substr(at + key.size(), end == std::string::npos ? std::string::npos : end - at - key.size());
  EXPECT_EQ(fs::path(path).filename(), "libswept_cad.so") << r.out;
  EXPECT_TRUE(fs::is_regular_file(path)) << path;
  // This test program and the command line are in the same build tree: the same module.
  const CadReaderStatus here = cad_reader_status();
  EXPECT_TRUE(here.error.empty()) << here.error;
  EXPECT_EQ(fs::canonical(here.path), fs::canonical(path));
  EXPECT_FALSE(here.candidates.empty());
}

TEST(CadModule, MissingBrokenOrForeignModuleIsAClearErrorAndOtherFormatsStillRead) {
  const auto dir = scratch_dir();
  const fs::path stl = write_file(dir / "tri.stl",
                                  "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
                                  "endloop\nendfacet\nendsolid t\n");
  const fs::path step = fixture("box_mm.step");
  struct Case {
    std::string module;
    std::string says;
  };
  const Case cases[] = {
      {(dir / "no-such-dir" / "libswept_cad.so").string(), "not there"},
      {stl.string(), "invalid ELF header"},  // not a shared object at all
      {SWEPT_FAKE_CAD_MODULE, "built for another version of swept"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.module);
    ASSERT_EQ(::setenv("SWEPT_CAD_MODULE", c.module.c_str(), 1), 0);
    const CliRun cad = run_cli("mesh-stats " + step.string());
    EXPECT_EQ(cad.code, 1) << cad.out;
    EXPECT_NE(cad.out.find("box_mm.step"), std::string::npos) << cad.out;
    EXPECT_NE(cad.out.find("libswept_cad.so"), std::string::npos) << cad.out;
    EXPECT_NE(cad.out.find(c.says), std::string::npos) << cad.out;
    EXPECT_NE(cad.out.find(c.module), std::string::npos) << cad.out;
    EXPECT_EQ(lines(cad.out), 1u) << cad.out;
    const CliRun version = run_cli("--version", /*with_stderr=*/false);
    EXPECT_EQ(version.code, 0);
    EXPECT_NE(version.out.find("CAD reader (STEP, IGES, OCCT .brep): none"), std::string::npos) << version.out;
    const CliRun mesh = run_cli("mesh-stats " + stl.string());
    EXPECT_EQ(mesh.code, 0) << mesh.out;
  }
  ASSERT_EQ(::unsetenv("SWEPT_CAD_MODULE"), 0);
  EXPECT_EQ(run_cli("mesh-stats " + step.string()).code, 0);
}

TEST(CadModule, TheCommandLineDoesNotLoadOpenCascadeDataExchangeAtStartUp) {
  FILE* pipe = ::popen((std::string("ldd ") + SWEPT_CLI + " 2>&1").c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  std::string out;
  char buf[4096];
  std::size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, pipe)) > 0) out.append(buf, n);
  ::pclose(pipe);
  ASSERT_NE(out.find("libc.so"), std::string::npos) << out;  // ldd worked
  for (const char* lib : {"libTKXDESTEP", "libTKXCAF", "libTKSTEP.", "libTKIGES", "libTKV3d"})
    EXPECT_EQ(out.find(lib), std::string::npos) << lib << " is loaded at start-up:\n" << out;
}

}  // namespace
}  // namespace swept::test
