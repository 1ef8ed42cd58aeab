// File names need not be UTF-8 (POSIX allows any byte but '/' and NUL): every JSON document and
// page we write carries such a name with U+FFFD in place of the bad byte, instead of failing with
// a JSON library error and leaving a partial file.
#include "support/cli_support.h"
#include "support/test_support.h"

#include "swept/io/mesh_io.h"
#include "swept/plan/problem.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace swept::test {
namespace {

namespace fs = std::filesystem;

#ifdef SWEPT_CLI

const std::string kReplacement = "\xEF\xBF\xBD";  // U+FFFD in UTF-8

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::path(SWEPT_BINARY_DIR) / "test_output" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string read_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream os;
  os << in.rdbuf();
  return os.str();
}

std::string quoted(const fs::path& p) { return "'" + p.string() + "'"; }

TEST(JsonFileNames, MeshNamesWithAByteThatIsNotUtf8AreReplacedInJsonOutput) {
  const fs::path dir = fresh_dir("json_file_names_mesh");
  const fs::path mesh = dir / "part\xff.stl";
  ASSERT_TRUE(write_stl_binary(mesh, {"box", box_triangles({0, 0, 0}, {1, 2, 3})}));
  for (const std::string command : {"bvh --json ", "mesh-stats --json "}) {
    const CliRun r = run_cli(command + quoted(mesh), /*with_stderr=*/false);
    ASSERT_EQ(r.code, 0) << command;
    const nlohmann::json doc = nlohmann::json::parse(r.out, nullptr, false);
    ASSERT_FALSE(doc.is_discarded()) << command << " printed invalid JSON:\n" << r.out;
    EXPECT_NE(r.out.find("part" + kReplacement + ".stl"), std::string::npos) << command << "\n" << r.out;
  }
}

TEST(JsonFileNames, ViewOfAProblemWhoseNameIsNotUtf8IsWrittenWhole) {
  const fs::path dir = fresh_dir("json_file_names_view");
  // TOML text must be UTF-8, so the meshes it names are; the problem's own name need not be.
  ASSERT_TRUE(write_stl_binary(dir / "wall.stl", {"wall", box_triangles({-50, -50, -5}, {50, 50, 0})}));
  ASSERT_TRUE(write_stl_binary(dir / "cube.stl", {"cube", box_triangles({-5, -5, -5}, {5, 5, 5})}));
  const fs::path problem = dir / "lift\xff.toml";
  std::ofstream(problem) << "unit = \"mm\"\n"
                            "[[obstacle]]\nfile = \"wall.stl\"\n"
                            "[[body]]\nfile = \"cube.stl\"\n"
                            "[start]\ntranslation = [0, 0, 10]\n"
                            "[goal]\ntranslation = [0, 0, 40]\n";
  Path path;
  path.poses = {Pose::from_translation({0, 0, 10}), Pose::from_translation({0, 0, 40})};
  ASSERT_TRUE(write_path(dir / "path.json", path, "mm", Vec3::Zero()));
  const fs::path html = dir / "view\xff.html";
  const CliRun r = run_cli("view " + quoted(problem) + " " + quoted(dir / "path.json") + " -o " + quoted(html));
  ASSERT_EQ(r.code, 0) << r.out;
  const std::string page = read_text(html);
  EXPECT_NE(page.find("<title>swept view: lift" + kReplacement + ".toml</title>"), std::string::npos);
  EXPECT_NE(page.find("\"title\":\"lift" + kReplacement + ".toml\""), std::string::npos);
  // Nothing but the inputs and the page: no temporary file left behind.
  int files = 0;
  for (const auto& entry : fs::directory_iterator(dir)) {
    ++files;
    EXPECT_EQ(entry.path().filename().string().rfind(".", 0), std::string::npos) << entry.path();
  }
  EXPECT_EQ(files, 5);
}

// `swept plan --json` and `swept check --json` list the import warnings, which name their mesh
// file: in a folder whose name is not UTF-8 the documents are still whole, valid JSON.
TEST(JsonFileNames, PlanAndCheckWarningsNamingAFolderThatIsNotUtf8) {
  const fs::path dir = fresh_dir("json_file_names_plan") / "d\xff";
  fs::create_directories(dir);
  std::ofstream(dir / "marked.obj") << "o marks\nv 0 0 0\nv 1 0 0\np 1\nl 1 2\n"
                                       "o wall\nv 10 -50 -50\nv 10 50 -50\nv 10 50 50\nv 10 -50 50\nf 3 4 5 6\n";
  ASSERT_TRUE(write_stl_binary(dir / "cube.stl", {"cube", box_triangles({-1, -1, -1}, {1, 1, 1})}));
  std::ofstream(dir / "p.toml") << "unit = \"mm\"\n[[obstacle]]\nfile = \"marked.obj\"\n[[body]]\nfile = \"cube.stl\"\n"
                                   "[start]\ntranslation = [0, 0, 0]\n[goal]\ntranslation = [-20, 0, 0]\n"
                                   "[bounds]\nmin = [-50, -50, -50]\nmax = [50, 50, 50]\n";
  const CliRun plan = run_cli("plan --json -q " + quoted(dir / "p.toml") + " -o " + quoted(dir / "path.json"), false);
  ASSERT_EQ(plan.code, 0) << plan.out;
  const CliRun check = run_cli("check --json " + quoted(dir / "p.toml") + " " + quoted(dir / "path.json"), false);
  ASSERT_EQ(check.code, 0) << check.out;
  for (const CliRun* r : {&plan, &check}) {
    const nlohmann::json doc = nlohmann::json::parse(r->out, nullptr, false);
    ASSERT_FALSE(doc.is_discarded()) << "invalid JSON:\n" << r->out;
    ASSERT_EQ(doc.at("warnings").size(), 1u) << r->out;
    EXPECT_NE(doc["warnings"][0].get<std::string>().find("d" + kReplacement + "/marked.obj: part 'marks'"),
              std::string::npos) << r->out;
  }
}

#endif

}  // namespace
}  // namespace swept::test
