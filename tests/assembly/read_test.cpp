// Reading assemblies (assembly.h): TOML files, folders of placed meshes, multi-solid STEP with
// its XCAF names, and the bad inputs that must be clear errors.
#include "assembly/assembly_support.h"
#include "io/import_test_util.h"
#include "support/test_support.h"

namespace swept {
namespace {

using namespace swept::test;

Aabb box_of(const TriangleSoup& s) {
  Aabb b;
  for (const Triangle& t : s.triangles)
    for (int v = 0; v < 3; ++v) b.extend(t[v]);
  return b;
}

void write_box_stl(const std::filesystem::path& file, const Vec3& lo, const Vec3& hi) {
  TriangleSoup s;
  s.triangles = box_triangles(lo, hi);
  ASSERT_TRUE(write_stl_binary(file, s).ok());
}

TEST(ReadAssembly, TomlPartsPosesAndFixed) {
  const auto dir = scratch_dir();
  write_box_stl(dir / "plate.stl", Vec3(0, 0, 0), Vec3(10, 10, 1));
  write_box_stl(dir / "cube.stl", Vec3(0, 0, 0), Vec3(1, 1, 1));
  write_file(dir / "a.toml",
             "unit = \"mm\"\n"
             "[[part]]\nfile = \"plate.stl\"\nname = \"base\"\nfixed = true\n"
             "[[part]]\nfile = \"cube.stl\"\npose = { translation = [2, 3, 1] }\n"
             "[[part]]\nfile = \"cube.stl\"\nname = \"turned\"\n"
             "pose = { translation = [5, 5, 1], axis = [0, 0, 1], angle_deg = 90 }\n");
  const auto a = read_assembly(dir / "a.toml");
  ASSERT_TRUE(a.ok()) << a.error().message;
  ASSERT_EQ(a->parts.size(), 3u);
  EXPECT_EQ(a->parts[0].name, "base");
  EXPECT_TRUE(a->parts[0].fixed);
  EXPECT_EQ(a->parts[1].name, "cube");  // the file's stem
  EXPECT_FALSE(a->parts[1].fixed);
  EXPECT_EQ(a->parts[2].name, "turned");
  const Aabb b1 = box_of(a->parts[1].mesh);
  EXPECT_TRUE(b1.min.isApprox(Vec3(2, 3, 1), 1e-9)) << b1.min.transpose();
  // Rotated 90° about z: (x, y) → (−y, x), then moved.
  const Aabb b2 = box_of(a->parts[2].mesh);
  EXPECT_TRUE(b2.min.isApprox(Vec3(4, 5, 1), 1e-9)) << b2.min.transpose();
  EXPECT_TRUE(b2.max.isApprox(Vec3(5, 6, 2), 1e-9)) << b2.max.transpose();
  EXPECT_EQ(a->triangle_count(), 36u);
}

TEST(ReadAssembly, FolderOfPlacedMeshesInNameOrder) {
  const auto dir = scratch_dir();
  write_box_stl(dir / "b_top.stl", Vec3(0, 0, 1), Vec3(1, 1, 2));
  write_box_stl(dir / "a_bottom.stl", Vec3(0, 0, 0), Vec3(1, 1, 1));
  write_file(dir / "notes.txt", "not a mesh\n");
  const auto a = read_assembly(dir);
  ASSERT_TRUE(a.ok()) << a.error().message;
  ASSERT_EQ(a->parts.size(), 2u);
  EXPECT_EQ(a->parts[0].name, "a_bottom");
  EXPECT_EQ(a->parts[1].name, "b_top");
}

TEST(ReadAssembly, StepSolidsWithTheirProductNames) {
  const auto a = read_assembly(fixture("assembly.step"));
  ASSERT_TRUE(a.ok()) << a.error().message;
  ASSERT_EQ(a->parts.size(), 2u);
  EXPECT_EQ(a->parts[0].name, "block");
  EXPECT_EQ(a->parts[1].name, "block#2");
}

TEST(ReadAssembly, BadInputIsAClearError) {
  const auto dir = scratch_dir();
  write_box_stl(dir / "cube.stl", Vec3(0, 0, 0), Vec3(1, 1, 1));
  // Two parts with one name.
  write_file(dir / "dup.toml", "[[part]]\nfile = \"cube.stl\"\n[[part]]\nfile = \"cube.stl\"\n");
  expect_error(read_assembly(dir / "dup.toml"), {"dup.toml", "two parts are named 'cube'"});
  // A missing mesh, named with its part.
  write_file(dir / "missing.toml", "[[part]]\nfile = \"nowhere.stl\"\nname = \"lid\"\n");
  expect_error(read_assembly(dir / "missing.toml"), {"missing.toml", "part[0] (lid)", "nowhere.stl"});
  // An unknown key, with its line.
  write_file(dir / "typo.toml", "[[part]]\nfile = \"cube.stl\"\nfixd = true\n");
  expect_error(read_assembly(dir / "typo.toml"), {"typo.toml:3", "part[0].fixd", "unknown key"});
  // No parts.
  write_file(dir / "empty.toml", "unit = \"mm\"\n");
  expect_error(read_assembly(dir / "empty.toml"), {"empty.toml", "no parts"});
  // An empty folder, a missing path.
  std::filesystem::create_directories(dir / "nothing");
  expect_error(read_assembly(dir / "nothing"), {"nothing", "empty"});
  expect_error(read_assembly(dir / "absent"), {"absent", "no such file"});
  // A mesh without triangles.
  std::filesystem::create_directories(dir / "hollow");
  write_file(dir / "hollow" / "void.stl", "solid void\nendsolid void\n");
  expect_error(read_assembly(dir / "hollow"), {"void.stl", "no triangles"});
  // Wrong types.
  write_file(dir / "types.toml", "[[part]]\nfile = \"cube.stl\"\nfixed = 1\n");
  expect_error(read_assembly(dir / "types.toml"), {"types.toml:3", "part[0].fixed", "true or false"});
}

}  // namespace
}  // namespace swept
