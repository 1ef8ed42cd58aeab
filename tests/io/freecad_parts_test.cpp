// Files nobody here wrote: FreeCAD's IDF library of electronic parts (Debian's freecad-common,
// installed by scripts/setup.sh), 28 STEP and 4 IGES files written by several exporters (OCCT's
// STEP translator 6.3, others), and the --json of each.
#include "import_test_util.h"

#include "support/cli_support.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <set>
#include <string>
#include <vector>

namespace swept::test {
namespace {

namespace fs = std::filesystem;

const fs::path kParts = "/usr/share/freecad/Mod/Idf/Idflibs";

#define SKIP_WITHOUT_PARTS() SKIP_WITHOUT_PACKAGE(kParts, "freecad-common")

std::vector<fs::path> parts() { return files_under(kParts, {".stp", ".step", ".igs", ".iges"}); }

TEST(FreecadParts, EveryPartReads) {
  SKIP_WITHOUT_PARTS();
  const std::vector<fs::path> files = parts();
  ASSERT_GT(files.size(), 25u);
  for (const fs::path& file : files) EXPECT_TRUE(reads_or_fails_naming_the_file(file)) << file;
}

// SOD_323.stp holds two faces of no area (their u range is one value): BRepMesh makes nothing of
// them, and the warning says nothing is lost (it said they "could not be tessellated").
TEST(FreecadParts, FacesOfNoAreaAreNamedAsSuch) {
  SKIP_WITHOUT_PARTS();
  const fs::path file = kParts / "SOD_323.stp";
  const auto model = import_mesh(file);
  ASSERT_TRUE(model.ok()) << model.error().message;
  ASSERT_FALSE(model->warnings.empty());
  EXPECT_EQ(model->warnings[0], file.string() + ": 2 face instance(s) of no area (degenerate in the file) have no "
                                                "triangles; nothing is lost");
  for (const std::string& w : model->warnings) EXPECT_EQ(w.find("could not be tessellated"), std::string::npos) << w;
}

#ifdef SWEPT_CLI
// Their IGES files made OpenCASCADE print "Total number of loaded entities" before the document.
TEST(FreecadParts, JsonOfEachIgesFileIsTheWholeOutput) {
  SKIP_WITHOUT_PARTS();
  for (const fs::path& file : parts()) {
    if (file.extension() != ".igs") continue;
    const CliRun r = run_cli("mesh-stats --json '" + file.string() + "'", /*with_stderr=*/false);
    ASSERT_EQ(r.code, 0) << file << "\n" << r.out;
    EXPECT_EQ(r.out.rfind("{", 0), 0u) << file << "\n" << r.out;
    EXPECT_FALSE(nlohmann::json::parse(r.out, nullptr, false).is_discarded()) << file;
  }
}
#endif

}  // namespace
}  // namespace swept::test
