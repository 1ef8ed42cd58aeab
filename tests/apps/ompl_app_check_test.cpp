// OMPL.app's conventions end to end, on a problem whose answer is derived by hand: a wall with a
// square hole, written as a Z-up COLLADA file, and a cube robot (also Z-up, off-centre in its
// file). OMPL.app reads meshes with assimp's defaults, which turn a Z-up file's (x, y, z) into
// (x, z, −y), and moves the robot so that the mean of its (joined) vertices is its frame origin;
// the .cfg poses and .path states are in that frame, and OMPL interpolates states about the
// frame origin. In that frame the wall is the horizontal slab z ∈ [−1, 1] with the hole
// |x| < 3, |y| < 3, and the cube (half width 1) rises through the hole 2 from its walls. Read
// with the up axis ignored, the wall would stand vertical (|y| < 1) across that same motion.
#include "support/cli_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <array>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>
#include <vector>

namespace swept {
namespace {

namespace fs = std::filesystem;
using Box = std::array<double, 6>;  // x0 y0 z0 x1 y1 z1, in the file's own (Z-up) frame

// A COLLADA document with the 12 triangles of each box, up axis Z, unit metre.
std::string collada(const std::vector<Box>& boxes) {
  std::ostringstream pos, idx;
  int base = 0;
  for (const Box& b : boxes) {
    for (int i = 0; i < 8; ++i)
      pos << (i & 1 ? b[3] : b[0]) << ' ' << (i & 2 ? b[4] : b[1]) << ' ' << (i & 4 ? b[5] : b[2]) << ' ';
    const int f[12][3] = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                          {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
    for (const auto& t : f) idx << base + t[0] << ' ' << base + t[1] << ' ' << base + t[2] << ' ';
    base += 8;
  }
  const std::size_t n = 8 * boxes.size(), m = 12 * boxes.size();
  std::ostringstream os;
  os << R"(<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset><unit name="meter" meter="1"/><up_axis>Z_UP</up_axis></asset>
  <library_geometries><geometry id="g"><mesh>
    <source id="p"><float_array id="a" count=")"
     << 3 * n << "\">" << pos.str() << R"(</float_array>
      <technique_common><accessor source="#a" count=")"
     << n << R"(" stride="3">
        <param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
      </accessor></technique_common></source>
    <vertices id="v"><input semantic="POSITION" source="#p"/></vertices>
    <triangles count=")"
     << m << R"("><input semantic="VERTEX" source="#v" offset="0"/><p>)" << idx.str() << R"(</p></triangles>
  </mesh></geometry></library_geometries>
  <library_visual_scenes><visual_scene id="s"><node id="n"><instance_geometry url="#g"/></node></visual_scene>
  </library_visual_scenes>
  <scene><instance_visual_scene url="#s"/></scene>
</COLLADA>
)";
  return os.str();
}

class OmplAppConventions : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = fs::temp_directory_path() / ("swept_ompl_app_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    // The wall y ∈ [−1, 1] (file frame) with the hole |x| < 3, |z| < 3.
    std::ofstream(dir / "wall.dae") << collada({{-20, -1, -20, -3, 1, 20},
                                                 {3, -1, -20, 20, 1, 20},
                                                 {-3, -1, -20, 3, 1, -3},
                                                 {-3, -1, 3, 3, 1, 20}});
    // A cube of half width 1 centred at (5, 5, 5) in its file.
    std::ofstream(dir / "cube.dae") << collada({{4, 4, 4, 6, 6, 6}});
    std::ofstream(dir / "hole.cfg") << R"([problem]
name = hole
robot = cube.dae
world = wall.dae
start.x = 0
start.y = 0
start.z = -10
start.theta = 0
start.axis.x = 0
start.axis.y = 0
start.axis.z = 1
goal.x = 0
goal.y = 0
goal.z = 10
goal.theta = 0
goal.axis.x = 0
goal.axis.y = 0
goal.axis.z = 1
volume.min.x = -25
volume.min.y = -25
volume.min.z = -25
volume.max.x = 25
volume.max.y = 25
volume.max.z = 25
)";
    // OMPL .path states: x y z qx qy qz qw.
    std::ofstream(dir / "through.path") << "0 0 -10 0 0 0 1\n0 0 10 0 0 0 1\n";
    std::ofstream(dir / "beside.path") << "10 0 -10 0 0 0 1\n10 0 10 0 0 0 1\n";
    // Turning a quarter about z while rising: the cube's corners reach √2 from its axis, still
    // 3 − √2 from the hole's walls.
    std::ofstream(dir / "turning.path") << "0 0 -10 0 0 0 1\n0 0 10 0 0 0.7071067811865476 0.7071067811865476\n";
  }
  void TearDown() override { fs::remove_all(dir); }
  test::CliRun check(const std::string& path, const std::string& extra = "") {
    return test::run_cli("check " + (dir / "hole.cfg").string() + " " + (dir / path).string() + " --json " + extra,
                         /*with_stderr=*/false);
  }
  fs::path dir;
};

TEST_F(OmplAppConventions, ThroughTheHoleIsValidTwoFromItsWalls) {
  const test::CliRun r = check("through.path");
  ASSERT_EQ(r.code, 0) << r.out;
  const auto doc = nlohmann::json::parse(r.out);
  EXPECT_NEAR(doc["min_clearance"].get<double>(), 2.0, 1e-6);
  EXPECT_EQ(check("through.path", "--clearance 1.99").code, 0);
  EXPECT_EQ(check("through.path", "--clearance 2.01").code, 2);
}

TEST_F(OmplAppConventions, BesideTheHoleCollides) {
  const test::CliRun r = check("beside.path");
  ASSERT_EQ(r.code, 2) << r.out;
  const auto doc = nlohmann::json::parse(r.out);
  EXPECT_TRUE(doc["first_invalid"]["colliding"].get<bool>());
}

TEST_F(OmplAppConventions, TurningWhileRisingKeepsTheCornersClear) {
  const test::CliRun r = check("turning.path");
  ASSERT_EQ(r.code, 0) << r.out;
  const auto doc = nlohmann::json::parse(r.out);
  // At least 3 − √2 from the hole's walls (corners), at most the 2 of the faces.
  EXPECT_GE(doc["min_clearance"].get<double>(), 3.0 - std::sqrt(2.0) - 1e-6);
  EXPECT_LE(doc["min_clearance"].get<double>(), 2.0 + 1e-6);
}

TEST_F(OmplAppConventions, PlannedPathWrittenAsDotPathChecksValid) {
  const std::string out = (dir / "planned.path").string();
  const test::CliRun p = test::run_cli("plan " + (dir / "hole.cfg").string() + " -q -o " + out);
  ASSERT_EQ(p.code, 0) << p.out;
  EXPECT_EQ(test::run_cli("check " + (dir / "hole.cfg").string() + " " + out).code, 0);
}

}  // namespace
}  // namespace swept
