// Files nobody here wrote: assimp's own test models, as Debian ships them (assimp-testmodels,
// installed by scripts/setup.sh), in every format swept reads through assimp or itself. Among
// them are Khronos' glTF samples, files written by Blender, 3ds Max and SketchUp, and the broken
// files assimp's tests feed its importers (truncated, wrong types, indices out of range, UTF-16).
#include "import_test_util.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <set>
#include <string>
#include <vector>

namespace swept::test {
namespace {

namespace fs = std::filesystem;

const fs::path kModels = "/usr/share/assimp/models";

std::vector<fs::path> models() {
  return files_under(kModels, {".stl", ".obj", ".ply", ".off", ".gltf", ".glb", ".dae"});
}

#define SKIP_WITHOUT_MODELS() SKIP_WITHOUT_PACKAGE(kModels, "assimp-testmodels")

// The glTF JSON of a .gltf or .glb file (the GLB's first chunk).
nlohmann::json gltf_json(const fs::path& file) {
  const std::string bytes = read_bytes(file);
  if (bytes.compare(0, 4, "glTF") == 0) {
    std::uint32_t length = 0;
    for (int b = 0; b < 4; ++b) length |= static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[12 + b])) << (8 * b);
    return nlohmann::json::parse(bytes.substr(20, length));
  }
  return nlohmann::json::parse(bytes);
}

// The triangles a glTF 2 scene holds, counted from its JSON alone (no assimp, nothing of swept):
// every node of the default scene, depth first, adds the whole triangles of its mesh's
// primitives: count / 3 for TRIANGLES, count − 2 for strips and fans, none for points and lines
// (count: the indices', or the positions' without indices). A mesh used by two nodes counts twice.
std::size_t scene_triangles(const nlohmann::json& doc) {
  const auto& accessors = doc.at("accessors");
  std::size_t total = 0;
  std::vector<std::size_t> stack;
  for (const auto& n : doc.at("scenes").at(doc.value("scene", 0)).at("nodes")) stack.push_back(n.get<std::size_t>());
  while (!stack.empty()) {
    const auto& node = doc.at("nodes").at(stack.back());
    stack.pop_back();
    for (const auto& c : node.value("children", nlohmann::json::array())) stack.push_back(c.get<std::size_t>());
    if (!node.contains("mesh")) continue;
    for (const auto& prim : doc.at("meshes").at(node.at("mesh").get<std::size_t>()).at("primitives")) {
      const auto& counted = prim.contains("indices") ? prim.at("indices") : prim.at("attributes").at("POSITION");
      const std::size_t n = accessors.at(counted.get<std::size_t>()).at("count").get<std::size_t>();
      const int mode = prim.value("mode", 4);
      total += mode == 4 ? n / 3 : (mode == 5 || mode == 6) && n > 2 ? n - 2 : 0;
    }
  }
  return total;
}

// Each file reads, into finite triangles, or fails with one line that starts with the file: no
// crash, no hang, no NaN, whatever assimp's tests throw at it.
TEST(AssimpTestModels, EveryModelReadsOrFailsWithOneLineNamingTheFile) {
  SKIP_WITHOUT_MODELS();
  const std::vector<fs::path> files = models();
  ASSERT_GT(files.size(), 100u);
  std::size_t read = 0;
  for (const fs::path& file : files) read += reads_or_fails_naming_the_file(file);
  EXPECT_GT(read, files.size() / 2);
}

// The centre OMPL.app gives a `.cfg` robot (ompl_app_center: assimp with OMPL.app's own
// post-processing, a second way through every file) is finite, or one line naming the file: it
// was NaN for BoxWithInfinites.glb.
TEST(AssimpTestModels, OmplAppCentresAreFiniteOrOneLineNamingTheFile) {
  SKIP_WITHOUT_MODELS();
  for (const fs::path& file : models()) {
    SCOPED_TRACE(file.string());
    const auto centre = ompl_app_center(file);
    if (centre.ok()) {
      EXPECT_TRUE(centre->allFinite()) << centre->transpose();
      continue;
    }
    const std::string& m = centre.error().message;
    EXPECT_EQ(m.rfind(file.string() + ": ", 0), 0u) << m;
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
  }
  const fs::path infinites = kModels / "glTF2/BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb";
  expect_error(ompl_app_center(infinites), {infinites.string() + ": a vertex has a non-finite coordinate"});
}

// Every glTF that reads holds the triangles its scene declares (scene_triangles); those refused
// are refused for what the Khronos validator or assimp itself finds wrong in them.
TEST(AssimpTestModels, GltfScenesReadWithTheTrianglesTheyDeclare) {
  SKIP_WITHOUT_MODELS();
  std::size_t compared = 0;
  for (const fs::path& file : models()) {
    std::string ext = file.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (ext != ".gltf" && ext != ".glb") continue;
    SCOPED_TRACE(file.string());
    const auto model = import_mesh(file);
    if (!model.ok()) continue;
    const nlohmann::json doc = gltf_json(file);
    const nlohmann::json version = doc.value("asset", nlohmann::json::object()).value("version", nlohmann::json());
    if (!version.is_string() || version.get<std::string>().rfind("2", 0) != 0) continue;  // glTF 1
    EXPECT_EQ(model->triangle_count(), scene_triangles(doc));
    ++compared;
  }
  EXPECT_GT(compared, 20u);

  // Khronos' 2CylinderEngine (59 primitives, its nodes using the meshes out of file order), plain
  // and Draco-compressed: refused until the face check matched assimp's meshes by position.
  for (const char* name : {"glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb", "glTF2/draco/2CylinderEngine.gltf"}) {
    const fs::path file = kModels / name;
    const auto model = import_mesh(file);
    ASSERT_TRUE(model.ok()) << model.error().message;
    EXPECT_EQ(model->triangle_count(), scene_triangles(gltf_json(file))) << name;
  }
  // One index past the 24 vertices of the mesh 'Mesh': refused, never dropped in silence.
  const fs::path out_of_range = kModels / "glTF2/IndexOutOfRange/IndexOutOfRange.gltf";
  expect_error(import_mesh(out_of_range),
               {out_of_range.string(), "mesh 'Mesh' (primitive 0): 1 of its 12 faces refer to vertices past its 24 vertices"});
  // TRIANGLES over 35 vertices and over 35 indices (TruncatedCube, TruncatedIndexedCube): the
  // 11 whole triangles of each are read, and each leftover is a warning.
  const fs::path truncated = kModels / "glTF2/IncorrectVertexArrays/Cube.gltf";
  const auto cube = import_mesh(truncated);
  ASSERT_TRUE(cube.ok()) << cube.error().message;
  // (Its four LINES meshes are parts without triangles, each a warning of its own.)
  std::vector<std::string> leftovers;
  for (const std::string& w : cube->warnings)
    if (w.find("TRIANGLES with") != std::string::npos) leftovers.push_back(w);
  ASSERT_EQ(leftovers.size(), 2u);
  EXPECT_NE(leftovers[0].find("mesh 'TruncatedCube' (primitive 0): TRIANGLES with 35"), std::string::npos) << leftovers[0];
  EXPECT_NE(leftovers[1].find("mesh 'TruncatedIndexedCube' (primitive 0): TRIANGLES with 35"), std::string::npos)
      << leftovers[1];
  EXPECT_EQ(cube->triangle_count(), 12u + 11u + 12u + 11u);
}

// Blender 2.47 wrote a free-text line into this PLY header without the `comment` keyword; assimp
// skips it, a strict reader (rply, ours) refuses the file, and the message says how to mend it.
TEST(AssimpTestModels, PlyHeaderLineWithoutAKeywordSaysWhatAHeaderHolds) {
  SKIP_WITHOUT_MODELS();
  const fs::path file = kModels / "PLY/Wuson.ply";
  expect_error(import_mesh(file), {file.string(), "line 3: unexpected header keyword 'Created'", "'comment'"});
}

}  // namespace
}  // namespace swept::test
