// swept's OFF reader: polygons of any size covered exactly (assimp's dropped faces of more than
// nine corners, and faces after a comment line), double precision, Geomview's header variants,
// comments anywhere. Expected triangles and areas come from the shapes' own formulas and from a
// point-in-polygon test written here, not from the reader.
#include "import_test_util.h"
#include "support/test_support.h"

#include "swept/io/mesh_io.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace swept::test {
namespace {

struct Point2 {
  double x, y;
};

std::string off_text(const std::vector<Vec3>& vertices, const std::vector<std::vector<int>>& faces) {
  std::ostringstream s;
  s.precision(17);
  s << "OFF\n" << vertices.size() << ' ' << faces.size() << " 0\n";
  for (const Vec3& v : vertices) s << v.x() << ' ' << v.y() << ' ' << v.z() << '\n';
  for (const auto& f : faces) {
    s << f.size();
    for (int i : f) s << ' ' << i;
    s << '\n';
  }
  return s.str();
}

double total_area(const ImportedModel& m) {
  double sum = 0.0;
  for (const Triangle& t : m.merged().triangles) sum += area(t);
  return sum;
}

// Crossing-number test, independent of the reader's ear clipping.
bool inside(const std::vector<Point2>& poly, Point2 p) {
  bool in = false;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const Point2 a = poly[i], b = poly[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) in = !in;
  }
  return in;
}

double shoelace(const std::vector<Point2>& poly) {
  double twice = 0.0;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) twice += poly[j].x * poly[i].y - poly[i].x * poly[j].y;
  return twice / 2.0;
}

// A prism over a regular n-gon (radius 1, height 1): two n-cornered caps and n quads, wound
// outward. assimp's OFF reader dropped both caps for n > 9 and left an open tube.
TEST(OffReader, PolygonsOfAnySizeAreTriangulatedWhole) {
  const auto dir = scratch_dir();
  for (int n : {3, 9, 10, 12, 64, 1000}) {
    std::vector<Vec3> v;
    for (int z = 0; z < 2; ++z)
      for (int i = 0; i < n; ++i)
        v.emplace_back(std::cos(2 * std::numbers::pi * i / n), std::sin(2 * std::numbers::pi * i / n), z);
    std::vector<std::vector<int>> f(2);
    for (int i = n - 1; i >= 0; --i) f[0].push_back(i);  // bottom, seen from below
    for (int i = 0; i < n; ++i) f[1].push_back(n + i);
    for (int i = 0; i < n; ++i) f.push_back({i, (i + 1) % n, n + (i + 1) % n, n + i});
    const auto file = write_file(dir / ("prism" + std::to_string(n) + ".off"), off_text(v, f));
    const auto model = import_mesh(file);
    ASSERT_TRUE(model.ok()) << model.error().message;
    EXPECT_EQ(model->triangle_count(), static_cast<std::size_t>(2 * (n - 2) + 2 * n)) << n;
    const double cap = n / 2.0 * std::sin(2 * std::numbers::pi / n), side = 2 * std::sin(std::numbers::pi / n);
    EXPECT_NEAR(total_area(*model), 2 * cap + n * side, 1e-9 * n) << n;
    // Every triangle keeps its face's outward winding.
    for (const Triangle& t : model->merged().triangles) {
      const Vec3 normal = (t.q - t.p).cross(t.r - t.p);
      const Vec3 out = centroid(t) - Vec3(0, 0, 0.5);
      EXPECT_GT(normal.dot(out), 0.0) << n;
    }
  }
}

// Non-convex polygons (an L, a ten-pointed star, a comb) in a tilted plane: the triangles cover
// each exactly — their areas add up to the shoelace area, every centroid is inside the polygon,
// every triangle is wound as the polygon.
TEST(OffReader, NonConvexPolygonsAreCoveredExactly) {
  std::vector<std::vector<Point2>> shapes;
  shapes.push_back({{0, 0}, {3, 0}, {3, 1}, {1, 1}, {1, 3}, {0, 3}});
  std::vector<Point2> star;
  for (int i = 0; i < 20; ++i) {
    const double r = i % 2 == 0 ? 2.0 : 0.7, a = std::numbers::pi * i / 10;
    star.push_back({r * std::cos(a), r * std::sin(a)});
  }
  shapes.push_back(star);
  std::vector<Point2> comb{{0, 0}};  // 500 teeth: 2,004 corners, half of them concave
  for (int tooth = 0; tooth < 500; ++tooth) {
    comb.push_back({2.0 * tooth + 1.0, 0});
    comb.push_back({2.0 * tooth + 1.0, -5});
    comb.push_back({2.0 * tooth + 2.0, -5});
    comb.push_back({2.0 * tooth + 2.0, 0});
  }
  comb.push_back({1001, 0});
  comb.push_back({1001, 1});
  comb.push_back({0, 1});
  shapes.push_back(comb);

  const Vec3 origin(5, -2, 7);
  const Vec3 e1 = Vec3(1, 2, 2).normalized(), e2 = Vec3(2, 1, -2).normalized();  // orthonormal
  const auto dir = scratch_dir();
  for (std::size_t s = 0; s < shapes.size(); ++s) {
    const auto& poly = shapes[s];
    std::vector<Vec3> v;
    std::vector<int> face;
    for (const Point2& p : poly) {
      face.push_back(static_cast<int>(v.size()));
      v.push_back(origin + p.x * e1 + p.y * e2);
    }
    const auto model = import_mesh(write_file(dir / ("shape" + std::to_string(s) + ".off"), off_text(v, {face})));
    ASSERT_TRUE(model.ok()) << model.error().message;
    EXPECT_TRUE(model->warnings.empty()) << s;
    ASSERT_EQ(model->triangle_count(), poly.size() - 2) << s;
    EXPECT_NEAR(total_area(*model), shoelace(poly), 1e-12 * poly.size() * shoelace(poly)) << s;
    std::size_t slivers = 0;
    for (const Triangle& t : model->merged().triangles) {
      // The comb's corners on one line (y = 0) are on it only to rounding once the plane is
      // tilted: an ear there may be a sliver of no area, on the outline, either way round.
      if (area(t) < 1e-9 && ++slivers) continue;
      const Vec3 c = centroid(t) - origin;
      EXPECT_TRUE(inside(poly, {c.dot(e1), c.dot(e2)})) << s;
      EXPECT_GT((t.q - t.p).cross(t.r - t.p).dot(e1.cross(e2)), 0.0) << s;
    }
    EXPECT_LT(slivers, poly.size() / 4) << s;
  }
}

// Random polygons (many self-crossing) never lose or add a triangle: k corners, k − 2 triangles,
// each made of the face's own corners.
TEST(OffReader, AnyPolygonGivesItsCornerCountLessTwoTriangles) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const auto dir = scratch_dir();
  for (int trial = 0; trial < 40; ++trial) {
    const int k = 3 + trial * 3;
    std::vector<Vec3> v;
    std::vector<int> face;
    for (int i = 0; i < k; ++i) {
      face.push_back(i);
      v.emplace_back(u(rng), u(rng), trial % 4 == 0 ? 0.0 : 0.01 * u(rng));  // some not quite planar
    }
    const auto model = import_mesh(write_file(dir / "random.off", off_text(v, {face})));
    ASSERT_TRUE(model.ok()) << model.error().message;
    ASSERT_EQ(model->triangle_count(), static_cast<std::size_t>(k - 2)) << k;
    for (const Triangle& t : model->merged().triangles)
      for (int c = 0; c < 3; ++c) EXPECT_NE(std::find(v.begin(), v.end(), t[c]), v.end());
  }
}

// A polygon whose edges cross so that no corner is an ear (found by a search over random
// hexagons): its corners are fanned, and a warning names the face and its line.
TEST(OffReader, SelfCrossingPolygonIsFannedWithAWarning) {
  const auto dir = scratch_dir();
  const std::string text = "OFF\n7 2 0\n5 2 0\n1 3 0\n5 1 0\n0 0 0\n3 3 0\n6 0 0\n9 9 9\n3 0 1 6\n6 0 1 2 3 4 5\n";
  const auto file = write_file(dir / "crossing.off", text);
  const auto model = import_mesh(file);
  ASSERT_TRUE(model.ok()) << model.error().message;
  EXPECT_EQ(model->triangle_count(), 1u + 4u);
  ASSERT_EQ(model->warnings.size(), 1u);
  EXPECT_NE(model->warnings[0].find("face 1 on line 11"), std::string::npos) << model->warnings[0];
  EXPECT_NE(model->warnings[0].find(file.string()), std::string::npos) << model->warnings[0];
}

TEST(OffReader, CoordinatesKeepDoublePrecision) {
  const auto dir = scratch_dir();
  const char* x = "1001.123456789012";
  const auto model = import_mesh(
      write_file(dir / "precise.off", std::string("OFF\n3 1 0\n") + x + " 0 0\n0 1 0\n0 0 -0.1\n3 0 1 2\n"));
  ASSERT_TRUE(model.ok()) << model.error().message;
  const Triangle t = model->merged().triangles.at(0);
  EXPECT_EQ(t.p.x(), std::strtod(x, nullptr));  // assimp gave 1001.1234741210938 (single precision)
  EXPECT_EQ(t.r.z(), -0.1);
}

// Files as CGAL and Geomview write them: comment lines and blank lines anywhere (assimp's reader
// took a comment line among the faces for a face, and dropped a real one), a comment after a
// vertex's colour (assimp stopped there), counts on the header line, colours after the faces.
TEST(OffReader, CommentsColoursAndHeaderVariants) {
  const auto dir = scratch_dir();
  auto read = [&](const std::string& name, const std::string& text) { return import_mesh(write_file(dir / name, text)); };
  const std::string tail = "3 0 1 2\n3 0 2 3 255 0 0\n";  // a unit square in two triangles
  const std::string square = "0 0 0\n1 0 0\n1 1 0\n0 1 0\n";

  const auto commented = read("commented.off",
                              "# written by hand\nOFF\n\n# 4 vertices\n4 2 0\n\n# vertices\n" + square +
                                  "\n# 2 facets\n# ------\n" + tail + "\n# End of OFF #\n");
  ASSERT_TRUE(commented.ok()) << commented.error().message;
  EXPECT_EQ(commented->triangle_count(), 2u);
  EXPECT_NEAR(total_area(*commented), 1.0, 1e-15);

  const auto coloured = read("coloured.off", "COFF\n4 2 0\n0 0 0 0.9 0.0 0.0 #red\n1 0 0 0 0 0.9   #blue\n"
                                             "1 1 0 0.9 0 0#red\n0 1 0 0 0 0.9 1\n" + tail);
  ASSERT_TRUE(coloured.ok()) << coloured.error().message;
  EXPECT_EQ(coloured->triangle_count(), 2u);

  const auto one_line = read("one_line.off", "OFF 4 2 0\n" + square + tail);
  ASSERT_TRUE(one_line.ok()) << one_line.error().message;
  EXPECT_EQ(one_line->triangle_count(), 2u);

  // Normals, texture coordinates and colours after the coordinates are skipped.
  const auto all_fields = read("stcn.off", "STCNOFF\n4 2 0\n0 0 0 0 0 1 1 0 0 1 0 0\n1 0 0 0 0 1 1 0 0 1 1 0\n"
                                           "1 1 0 0 0 1 1 0 0 1 1 1\n0 1 0 0 0 1 1 0 0 1 0 1\n" + tail);
  ASSERT_TRUE(all_fields.ok()) << all_fields.error().message;
  EXPECT_NEAR(total_area(*all_fields), 1.0, 1e-15);

  // 4OFF: homogeneous coordinates, each point (x, y, z) / w.
  const auto homogeneous = read("4off.off", "4OFF\n4 2 0\n0 0 0 2\n2 0 0 2\n4 4 0 4\n0 3 0 3\n" + tail);
  ASSERT_TRUE(homogeneous.ok()) << homogeneous.error().message;
  EXPECT_NEAR(total_area(*homogeneous), 1.0, 1e-15);

  // nOFF: the dimension follows; 2 gives z = 0.
  const auto flat = read("noff.off", "nOFF 2\n4 2 0\n0 0\n1 0\n1 1\n0 1\n" + tail);
  ASSERT_TRUE(flat.ok()) << flat.error().message;
  EXPECT_NEAR(total_area(*flat), 1.0, 1e-15);

  // More data after the header's faces (one of CGAL's own test files): read up to the count, said.
  const auto more = read("more.off", "OFF\n4 1 0\n" + square + "3 0 1 2\n3 0 2 3\n");
  ASSERT_TRUE(more.ok()) << more.error().message;
  EXPECT_EQ(more->triangle_count(), 1u);
  ASSERT_EQ(more->warnings.size(), 1u);
  EXPECT_NE(more->warnings[0].find("line 8: more data after the 1 faces"), std::string::npos) << more->warnings[0];
}

TEST(OffReader, ErrorsNameTheFileAndLine) {
  const auto dir = scratch_dir();
  const std::string square = "0 0 0\n1 0 0\n1 1 0\n0 1 0\n";
  auto check = [&](const std::string& name, const std::string& text, std::initializer_list<std::string> parts) {
    expect_import_error(write_file(dir / name, text), parts);
  };
  check("binary.off", "OFF BINARY\n", {"line 1", "binary OFF"});
  check("unknown.off", "XOFF\n4 1 0\n" + square + "3 0 1 2\n", {"line 1", "unknown OFF header 'XOFF'"});
  check("nothing.off", "PLY\n", {"line 1", "expected the 'OFF' header"});
  check("cloud.off", "OFF\n4 0 0\n" + square, {"holds no faces, only 4 vertices (a point cloud)"});
  check("w0.off", "4OFF\n3 1 0\n0 0 0 1\n1 0 0 0\n0 1 0 1\n3 0 1 2\n", {"line 4", "vertex 1 has w = 0"});
  check("dim4.off", "nOFF 4\n3 1 0\n", {"line 1", "4 dimensions"});
  check("short.off", "OFF\n4 1 0\n" + square + "4 0 1 2\n", {"line 7", "face 0 lists fewer than its 4 vertices"});
  check("two.off", "OFF\n4 1 0\n" + square + "2 0 1\n", {"line 7", "at least 3"});
  check("nan.off", "OFF\n4 1 0\n0 0 0\nnan 0 0\n1 1 0\n0 1 0\n3 0 1 2\n", {"line 4", "vertex 1"});
  check("faces_cut.off", "OFF\n4 3 0\n" + square + "3 0 1 2\n", {"unexpected end of file", "file holds 4 and 1"});
  check("huge_w.off", "4OFF\n3 1 0\n1e300 0 0 1e-300\n1 0 0 1\n0 1 0 1\n3 0 1 2\n", {"line 3", "not finite"});
}

}  // namespace
}  // namespace swept::test
