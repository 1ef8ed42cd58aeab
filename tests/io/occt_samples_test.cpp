// Files nobody here wrote: OpenCASCADE's own sample data, as Debian ships it (occt-misc, installed
// by scripts/setup.sh): STEP, IGES, 37 .brep shapes (solids, shells, loose faces, wireframes, a
// B-spline terrain) and STL meshes.
#include "import_test_util.h"

#include <algorithm>
#include <set>
#include <string>
#include <vector>

namespace swept::test {
namespace {

namespace fs = std::filesystem;

const fs::path kData = "/usr/share/opencascade/data";

#define SKIP_WITHOUT_SAMPLES() SKIP_WITHOUT_PACKAGE(kData, "occt-misc")

std::vector<fs::path> samples() { return files_under(kData, {".brep", ".step", ".stp", ".iges", ".igs", ".stl"}); }

// Each sample reads into finite triangles or fails with one line that starts with the file. At a
// 1 mm deflection and a 1 GB reader, so that the terrain (12 GB at 0.1 mm) stays quick.
TEST(OcctSamples, EverySampleReadsOrFailsWithOneLineNamingTheFile) {
  SKIP_WITHOUT_SAMPLES();
  const std::vector<fs::path> files = samples();
  ASSERT_GT(files.size(), 40u);
  ImportOptions options;
  options.linear_deflection = 1.0;
  options.reader_memory = std::size_t{1} << 30;
  std::size_t read = 0;
  for (const fs::path& file : files) {
    // Unbounded under AddressSanitizer, the terrain alone would take minutes and gigabytes.
    if (kAddressSanitizer && file.filename() == "terrain.brep") continue;
    read += reads_or_fails_naming_the_file(file, options);
  }
  EXPECT_GT(read, files.size() - 5);
}

// asahi.brep is a wireframe of 2,828 edges: there is nothing to mesh, and the message says what
// the file holds (it said "contains no shapes").
TEST(OcctSamples, AWireframeSaysItHoldsNoFaces) {
  SKIP_WITHOUT_SAMPLES();
  const fs::path asahi = kData / "occ" / "asahi.brep";
  expect_error(import_mesh(asahi), {asahi.string() + ": holds no faces to mesh, only 2828 edges and 8989 vertices (a wireframe)"});
  const fs::path edge = kData / "occ" / "edge.brep";
  expect_error(import_mesh(edge), {edge.string() + ": holds no faces to mesh, only 1 edge and 2 vertices (a wireframe)"});
}

// The terrain at the default deflection outgrows any reader's memory: with 512 MB it is an error
// that says so, in seconds.
TEST(OcctSamples, TheTerrainAtTheDefaultDeflectionRunsOutOfTheReadersMemory) {
  SKIP_WITHOUT_SAMPLES();
  if (kAddressSanitizer) GTEST_SKIP() << "no memory limit under AddressSanitizer";
  ImportOptions options;
  options.reader_memory = std::size_t{512} << 20;
  const fs::path terrain = kData / "occ" / "terrain.brep";
  expect_error(import_mesh(terrain, options),
               {terrain.string() + ": the OpenCASCADE reader ran out of memory on this file: it used ",
                " of its 512 MB limit", "a larger deflection makes fewer triangles"});
}

}  // namespace
}  // namespace swept::test
