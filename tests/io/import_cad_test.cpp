// CAD formats through OpenCASCADE: .brep, STEP (mm and inch), IGES, STEP assemblies, errors,
// parallel tessellation determinism, and the shared CAD data when present.
#include "import_test_util.h"
#include "support/test_support.h"

#include "swept/io/mesh_io.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>

namespace swept::test {
namespace {

ImportOptions cad_options(const std::string& unit, double linear, double angular = 0.5) {
  ImportOptions o;
  o.unit = unit;
  o.linear_deflection = linear;
  o.angular_deflection = angular;
  return o;
}

void expect_box(const Aabb& box, const Vec3& lo, const Vec3& hi, double tol) {
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(box.min[k], lo[k], tol) << "axis " << k;
    EXPECT_NEAR(box.max[k], hi[k], tol) << "axis " << k;
  }
}

double total_area(const TriangleSoup& soup) {
  double a = 0.0;
  for (const Triangle& t : soup.triangles) a += area(t);
  return a;
}

// Box faces point outwards: the signed volume from the triangles' orientation is positive.
double signed_volume(const TriangleSoup& soup) {
  double v = 0.0;
  for (const Triangle& t : soup.triangles) v += t.p.dot(t.q.cross(t.r)) / 6.0;
  return v;
}

// FNV-1a over the coordinate bits, to compare two imports bit for bit.
std::uint64_t hash(const ImportedModel& model) {
  std::uint64_t h = 1469598103934665603ull;
  for (const TriangleSoup& part : model.parts)
    for (const Triangle& t : part.triangles)
      for (int v = 0; v < 3; ++v)
        for (int k = 0; k < 3; ++k) {
          std::uint64_t bits;
          const double x = t[v][k];
          std::memcpy(&bits, &x, 8);
          for (int b = 0; b < 8; ++b) h = (h ^ ((bits >> (8 * b)) & 0xFF)) * 1099511628211ull;
        }
  return h;
}

TEST(ImportCad, BrepBox) {
  const auto model = import_mesh(fixture("box.brep"));
  ASSERT_TRUE(model.ok()) << model.error().message;
  ASSERT_EQ(model->parts.size(), 1u);
  EXPECT_EQ(model->parts[0].name, "box");
  EXPECT_EQ(model->triangle_count(), 12u);
  EXPECT_EQ(model->degenerate_triangles, 0u);
  expect_box(bounds(model->parts[0].triangles), Vec3(0, 0, 0), Vec3(10, 20, 30), 1e-9);
  EXPECT_NEAR(total_area(model->parts[0]), 2 * (200 + 300 + 600), 1e-9);
  EXPECT_NEAR(signed_volume(model->parts[0]), 6000, 1e-6);

  const auto metres = import_mesh(fixture("box.brep"), cad_options("m", 1e-4));
  ASSERT_TRUE(metres.ok()) << metres.error().message;
  expect_box(bounds(metres->parts[0].triangles), Vec3(0, 0, 0), Vec3(0.01, 0.02, 0.03), 1e-12);
}

TEST(ImportCad, StepInMillimetresAndInches) {
  for (const char* name : {"box_mm.step", "box_inch.step"}) {
    const auto model = import_mesh(fixture(name));
    ASSERT_TRUE(model.ok()) << model.error().message;
    EXPECT_EQ(model->triangle_count(), 12u) << name;
    expect_box(bounds(model->merged().triangles), Vec3(0, 0, 0), Vec3(10, 20, 30), 1e-6);
    EXPECT_NEAR(signed_volume(model->merged()), 6000, 1e-3) << name;
  }
  const auto inches = import_mesh(fixture("box_inch.step"), cad_options("in", 0.01));
  ASSERT_TRUE(inches.ok()) << inches.error().message;
  expect_box(bounds(inches->merged().triangles), Vec3(0, 0, 0), Vec3(10, 20, 30) / 25.4, 1e-9);
}

TEST(ImportCad, Iges) {
  const auto model = import_mesh(fixture("box.igs"));
  ASSERT_TRUE(model.ok()) << model.error().message;
  EXPECT_EQ(model->triangle_count(), 12u);
  expect_box(bounds(model->merged().triangles), Vec3(0, 0, 0), Vec3(10, 20, 30), 1e-6);
}

TEST(ImportCad, StepAssemblyPlacementsAndNames) {
  const auto model = import_mesh(fixture("assembly.step"));
  ASSERT_TRUE(model.ok()) << model.error().message;
  ASSERT_EQ(model->parts.size(), 2u);
  EXPECT_EQ(model->parts[0].name, "block");
  EXPECT_EQ(model->parts[1].name, "block#2");
  for (const TriangleSoup& part : model->parts) EXPECT_EQ(part.triangles.size(), 12u);
  expect_box(bounds(model->parts[0].triangles), Vec3(100, 0, 0), Vec3(110, 20, 30), 1e-6);
  // Rotated 90 degrees about z, then moved by (0, 50, 0): (x, y) -> (-y, x + 50).
  expect_box(bounds(model->parts[1].triangles), Vec3(-20, 50, 0), Vec3(0, 60, 30), 1e-6);
  EXPECT_NEAR(signed_volume(model->parts[1]), 6000, 1e-3);
}

TEST(ImportCad, DeflectionControlsTheTessellation) {
  // A box has planar faces only, so use a curved OCCT sample when present, else skip.
  const auto sample = occt_sample("mal_tige.brep");
  if (!sample) GTEST_SKIP() << "OCCT's mal_tige.brep not found (shared data or occt-misc)";
  const auto file = *sample;
  const auto coarse = import_mesh(file, cad_options("mm", 0.5));
  const auto fine = import_mesh(file, cad_options("mm", 0.02, 0.2));
  ASSERT_TRUE(coarse.ok()) << coarse.error().message;
  ASSERT_TRUE(fine.ok()) << fine.error().message;
  EXPECT_GT(fine->triangle_count(), 2 * coarse->triangle_count());
}

TEST(ImportCad, MalformedFilesAreErrors) {
  const auto dir = scratch_dir();
  const auto brep = write_file(dir / "junk.brep", "this is not a brep file\n");
  expect_error(import_mesh(brep), {brep.string(), "not a readable OCCT .brep"});

  const auto step = write_file(dir / "junk.step", "ISO-10303-21;\nHEADER;\nFILE_DESCRIPTION(('x'),'2;1');\n#1=FOO(;\n");
  expect_error(import_mesh(step), {step.string(), "STEP", "Line 5"});

  std::string text = read_bytes(fixture("box_mm.step"));
  text.resize(text.size() / 2);
  const auto cut = write_file(dir / "cut.step", text);
  expect_error(import_mesh(cut), {cut.string()});

  const auto iges = write_file(dir / "junk.igs", "garbage\n");
  expect_error(import_mesh(iges), {iges.string(), "80 columns"});

  // Truncated IGES and .brep files crash or hang OCCT's readers unless caught first.
  const std::string igs = read_bytes(fixture("box.igs"));
  const auto igs_cut = write_file(dir / "cut.igs", igs.substr(0, igs.size() * 3 / 4));
  expect_error(import_mesh(igs_cut), {igs_cut.string(), "line"});
  const std::size_t t = igs.rfind("T0000001");
  ASSERT_NE(t, std::string::npos);
  // Whole records only: drop the parameter section, keep the terminate record.
  const std::size_t p_start = igs.rfind('\n', igs.find("P0000001")) + 1;
  const std::size_t t_start = igs.rfind('\n', t) + 1;
  const auto igs_lines = write_file(dir / "lines.igs", igs.substr(0, p_start) + igs.substr(t_start));
  expect_error(import_mesh(igs_lines), {igs_lines.string(), "truncated IGES file: terminate section says section P"});

  const std::string brep_text = read_bytes(fixture("box.brep"));
  for (const std::size_t keep : {brep_text.size() / 4, brep_text.size() * 3 / 4}) {
    const auto brep_cut = write_file(dir / "cut.brep", brep_text.substr(0, keep));
    expect_error(import_mesh(brep_cut), {brep_cut.string(), "not a readable OCCT .brep file"});
  }

  expect_error(import_mesh(fixture("box.brep"), cad_options("mm", 0.0)), {"box.brep", "linear deflection"});
  expect_error(import_mesh(fixture("box.brep"), cad_options("mm", 0.1, -1.0)), {"box.brep", "angular deflection"});
}

TEST(ImportCad, SharedAs1AssemblyHas18PlacedParts) {
  const auto data = shared_data();
  if (!data) GTEST_SKIP() << "shared CAD data not found";
  const auto file = *data / "as1" / "as1-oc-214.stp";
  if (!std::filesystem::exists(file)) GTEST_SKIP() << file << " not found";
  const auto model = import_mesh(file, cad_options("mm", 0.1));
  ASSERT_TRUE(model.ok()) << model.error().message;
  ASSERT_EQ(model->parts.size(), 18u);
  // Identical parts placed at different positions: same triangle counts, different bounds.
  std::map<std::string, std::vector<const TriangleSoup*>> by_base;
  for (const TriangleSoup& p : model->parts) {
    EXPECT_FALSE(p.triangles.empty()) << p.name;
    by_base[p.name.substr(0, p.name.find('#'))].push_back(&p);
  }
  std::size_t largest_family = 0;
  for (const auto& [base, family] : by_base) {
    largest_family = std::max(largest_family, family.size());
    for (std::size_t i = 1; i < family.size(); ++i) {
      EXPECT_EQ(family[i]->triangles.size(), family[0]->triangles.size()) << base;
      EXPECT_GT((bounds(family[i]->triangles).center() - bounds(family[0]->triangles).center()).norm(), 1.0) << base;
      EXPECT_NEAR(total_area(*family[i]), total_area(*family[0]), 1e-6 * total_area(*family[0])) << base;
    }
  }
  EXPECT_EQ(largest_family, 8u);  // the 8 nuts
}

TEST(ImportCad, SharedInchStepMatchesMillimetres) {
  const auto data = shared_data();
  if (!data) GTEST_SKIP() << "shared CAD data not found";
  const auto file = *data / "nist" / "nist_ctc_03_asme1_rc.stp";
  if (!std::filesystem::exists(file)) GTEST_SKIP() << file << " not found";
  const auto mm = import_mesh(file, cad_options("mm", 0.5));
  const auto in = import_mesh(file, cad_options("in", 0.5 / 25.4));
  ASSERT_TRUE(mm.ok()) << mm.error().message;
  ASSERT_TRUE(in.ok()) << in.error().message;
  EXPECT_EQ(mm->triangle_count(), in->triangle_count());
  const Aabb a = bounds(mm->merged().triangles), b = bounds(in->merged().triangles);
  EXPECT_NEAR(a.extent(), 25.4 * b.extent(), 1e-6 * a.extent());
  // The part is declared in inches: its size in mm is well above its number of inches.
  EXPECT_GT(a.extent(), 100.0);
}

TEST(ImportCad, ParallelTessellationIsDeterministic) {
  const auto sample = occt_sample("Motor-c.brep");
  if (!sample) GTEST_SKIP() << "OCCT's Motor-c.brep not found (shared data or occt-misc)";
  const auto file = *sample;
  const auto a = import_mesh(file, cad_options("mm", 0.1));
  const auto b = import_mesh(file, cad_options("mm", 0.1));
  ASSERT_TRUE(a.ok()) << a.error().message;
  ASSERT_TRUE(b.ok()) << b.error().message;
  EXPECT_EQ(a->parts.size(), 17u);
  ASSERT_EQ(a->triangle_count(), b->triangle_count());
  EXPECT_EQ(a->degenerate_triangles, b->degenerate_triangles);
  EXPECT_EQ(hash(*a), hash(*b));
}

}  // namespace
}  // namespace swept::test
