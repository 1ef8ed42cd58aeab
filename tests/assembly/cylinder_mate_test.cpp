// The CAD's cylinders in the contact model (contact.h, case 4): a headed pin in a bore of its own
// radius, on a tilted axis, meshed so coarsely that the facets of pin and bore cross by twice the
// mating tolerance (`swept scene pin-in-bore`). Read from its OpenCASCADE files the pin
// leaves along its exact axis, away from its head, and the independent check below — the pin's
// true surface against the block's true solid, sampled along the pull, no code shared with the
// contact model — finds nothing through material. The same triangles without their cylinders
// (a mesh-only input) are an interference and stay put; a cap over the head blocks the one way
// out, and the pin is reported blocked both ways.
#include "assembly/assembly_support.h"
#include "support/test_support.h"
#include "swept/scenes/pin_in_bore.h"

#include <cmath>
#include <numbers>

namespace swept {
namespace {

using scenes::PinInBore;

Assembly read_pin_in_bore() {
  // A folder per test: ctest runs them in parallel.
  const auto dir = std::filesystem::path(SWEPT_BINARY_DIR) / "tests_assembly_scratch" /
                   ("pin_in_bore_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
  std::filesystem::remove_all(dir);
  const auto report = scenes::generate_pin_in_bore({.name = "pin-in-bore", .output_dir = dir});
  EXPECT_TRUE(report.ok()) << report.error().message;
  auto a = read_assembly(report->problem_file);
  EXPECT_TRUE(a.ok()) << a.error().message;
  return *a;
}

// How deep a point (world frame) lies inside the block's true solid: the box less the bore.
double depth_in_block(const Vec3& world) {
  const Vec3 x = PinInBore::pose().apply_inverse(world);
  const double rho = std::hypot(x.x(), x.y());
  const double inside_box = std::min({PinInBore::kBlockHalf - std::abs(x.x()), PinInBore::kBlockHalf - std::abs(x.y()),
                                      x.z(), PinInBore::kBlockHeight - x.z()});
  return std::min(inside_box, rho - PinInBore::kRadius);
}

// Points of the pin's true surface (local frame): the shaft's and the head's cylinders and the
// end discs, on a grid of angles and heights.
std::vector<Vec3> pin_surface_points() {
  std::vector<Vec3> out;
  const int turns = 90;
  for (int k = 0; k < turns; ++k) {
    const double a = 2.0 * std::numbers::pi * k / turns;
    const Vec3 dir(std::cos(a), std::sin(a), 0.0);
    for (int h = 0; h <= 60; ++h) {
      const double z = PinInBore::kShaftBottom + (PinInBore::kBlockHeight - PinInBore::kShaftBottom) * h / 60.0;
      out.push_back(PinInBore::kRadius * dir + Vec3(0, 0, z));
    }
    for (int h = 0; h <= 8; ++h)
      out.push_back(PinInBore::kHeadRadius * dir +
                    Vec3(0, 0, PinInBore::kBlockHeight + (PinInBore::kHeadTop - PinInBore::kBlockHeight) * h / 8.0));
    for (int s = 0; s <= 8; ++s) {
      out.push_back(PinInBore::kRadius * s / 8.0 * dir + Vec3(0, 0, PinInBore::kShaftBottom));
      out.push_back(PinInBore::kHeadRadius * s / 8.0 * dir + Vec3(0, 0, PinInBore::kBlockHeight));
      out.push_back(PinInBore::kHeadRadius * s / 8.0 * dir + Vec3(0, 0, PinInBore::kHeadTop));
    }
  }
  return out;
}

// The deepest a sampled point of the pin's true surface reaches into the block's true solid at
// 400 samples along the pull.
double deepest_along(const Vec3& direction, double distance) {
  double deepest = -1e300;
  const auto points = pin_surface_points();
  for (int s = 0; s <= 400; ++s) {
    const Vec3 shift = direction * (distance * s / 400.0);
    for (const Vec3& p : points) deepest = std::max(deepest, depth_in_block(PinInBore::pose().apply(p) + shift));
  }
  return deepest;
}

TEST(CylinderMate, ReaderKeepsTheCylindersInTheAssemblysFrame) {
  const Assembly a = read_pin_in_bore();
  ASSERT_EQ(a.parts.size(), 2u);
  const Vec3 axis = PinInBore::pose().rotation * Vec3::UnitZ();
  for (const AssemblyPart& p : a.parts) {
    ASSERT_EQ(p.mesh.cylinder_of.size(), p.mesh.triangles.size()) << p.name;
    ASSERT_FALSE(p.mesh.cylinders.empty()) << p.name;
    for (const CadCylinder& c : p.mesh.cylinders) {
      EXPECT_LT(c.axis.cross(axis).norm(), 1e-12) << p.name;
      // The axis passes through the pose's image of the local z axis.
      const Vec3 off = PinInBore::pose().apply_inverse(c.origin);
      EXPECT_LT(std::hypot(off.x(), off.y()), 1e-9) << p.name;
      EXPECT_TRUE(std::abs(c.radius - PinInBore::kRadius) < 1e-12 || std::abs(c.radius - PinInBore::kHeadRadius) < 1e-12)
          << p.name << " " << c.radius;
    }
    // Every triangle on a cylinder lies on it (vertices at its radius from its axis).
    for (std::size_t k = 0; k < p.mesh.triangles.size(); ++k) {
      if (p.mesh.cylinder_of[k] < 0) continue;
      const CadCylinder& c = p.mesh.cylinders[static_cast<std::size_t>(p.mesh.cylinder_of[k])];
      for (int v = 0; v < 3; ++v) {
        const Vec3 w = p.mesh.triangles[k][v] - c.origin;
        EXPECT_NEAR((w - c.axis * w.dot(c.axis)).norm(), c.radius, 1e-9);
      }
    }
  }
}

TEST(CylinderMate, TheCylindersCrossTheReadersIsolationUnchanged) {
  const Assembly a = read_pin_in_bore();
  const auto file = a.source.parent_path() / "pin.brep";
  ImportOptions isolated, in_process;
  in_process.isolate_readers = false;
  const auto x = import_mesh(file, isolated), y = import_mesh(file, in_process);
  ASSERT_TRUE(x.ok()) << x.error().message;
  ASSERT_TRUE(y.ok()) << y.error().message;
  ASSERT_EQ(x->parts.size(), 1u);
  ASSERT_EQ(y->parts.size(), 1u);
  EXPECT_EQ(x->parts[0].cylinder_of, y->parts[0].cylinder_of);
  ASSERT_EQ(x->parts[0].cylinders.size(), y->parts[0].cylinders.size());
  ASSERT_FALSE(x->parts[0].cylinders.empty());
  for (std::size_t k = 0; k < x->parts[0].cylinders.size(); ++k) {
    const CadCylinder &c = x->parts[0].cylinders[k], &d = y->parts[0].cylinders[k];
    EXPECT_EQ(c.origin, d.origin);
    EXPECT_EQ(c.axis, d.axis);
    EXPECT_EQ(c.radius, d.radius);
    EXPECT_EQ(c.deviation, d.deviation);
  }
}

TEST(CylinderMate, ThePinSlidesOutAlongItsAxisByTheCylinders) {
  const Assembly a = read_pin_in_bore();
  ASSERT_EQ(a.parts.size(), 2u);
  ASSERT_EQ(a.parts[1].name, "pin");
  const double clearance = 0.01, tolerance = 0.01;
  // The facets cross by far more than the tolerance: what the triangles alone would refuse.
  const auto facets = find_interferences(test::without_cylinders(a), tolerance);
  ASSERT_EQ(facets.size(), 1u);
  EXPECT_GT(facets[0].depth, 1.5 * tolerance);

  const DisassemblyResult r =
      disassemble(a, {.clearance = clearance, .tolerance = tolerance, .jobs = 2, .plan_time_limit = 0});
  EXPECT_TRUE(r.interferences.empty());
  ASSERT_TRUE(r.complete);
  ASSERT_EQ(r.sequence.size(), 1u);
  const SequenceStep& s = r.sequence[0];
  EXPECT_EQ(s.method, RemovalMethod::pull);
  // Away from the head, along the axis: the pose's image of +z, to rounding (the CAD's axis).
  const Vec3 up = PinInBore::pose().rotation * Vec3::UnitZ();
  EXPECT_LT((s.direction - up).norm(), 1e-12) << s.direction.transpose();
  // Far enough that the shaft's bottom (10 below the block) has left the block's box.
  EXPECT_GT(s.distance, PinInBore::kBlockHeight - PinInBore::kShaftBottom - 1.0);
  // The independent check: the pin's true surface never enters the block's true solid.
  EXPECT_LT(deepest_along(s.direction, s.distance), 1e-9);
  // ... which it does along any other direction the sequence could have taken.
  EXPECT_GT(deepest_along(-up, 5.0), 1.0);
  EXPECT_GT(deepest_along(PinInBore::pose().rotation * Vec3::UnitX(), 5.0), 1.0);
}

TEST(CylinderMate, ThePlannerTakesThePinOutAlongItsAxisByTheCylinders) {
  // The same problem through the planner (swept plan ASSEMBLY --part pin): its escape is a pull
  // under the same contact model, the CAD's cylinders included.
  const Assembly a = read_pin_in_bore();
  const DisassemblyOptions options{.clearance = 0.01, .tolerance = 0.01};
  auto pp = part_problem(a, {1}, {0, 1}, options);
  ASSERT_TRUE(pp.ok()) << pp.error().message;
  EXPECT_FALSE(pp->scene.body.cylinders.empty());
  const PlanResult r = plan(pp->problem, pp->scene);
  ASSERT_TRUE(r.solved()) << r.message;
  ASSERT_GE(r.escape_segments, 1u);
  const Vec3 pull = r.path.poses[1].translation - r.path.poses[0].translation;
  const Vec3 up = PinInBore::pose().rotation * Vec3::UnitZ();
  EXPECT_LT((pull.normalized() - up).norm(), 1e-12) << pull.transpose();
  EXPECT_EQ(r.path.poses[1].rotation, Mat3::Identity());
  // The independent check: the pin's true surface never enters the block's true solid.
  EXPECT_LT(deepest_along(up, pull.norm()), 1e-9);
  // Without the cylinders the same triangles cross by more than the tolerance: no way out.
  auto facets = part_problem(test::without_cylinders(a), {1}, {0, 1}, options);
  ASSERT_TRUE(facets.ok());
  facets->problem.time_limit = 5;
  EXPECT_FALSE(plan(facets->problem, facets->scene, {.max_queries = 20000}).solved());
}

TEST(CylinderMate, WithoutTheCylindersTheSameTrianglesStayPut) {
  const Assembly a = test::without_cylinders(read_pin_in_bore());
  const DisassemblyResult r = disassemble(a, {.clearance = 0.01, .tolerance = 0.01, .jobs = 2, .plan_time_limit = 0});
  EXPECT_EQ(r.interferences.size(), 1u);
  EXPECT_FALSE(r.complete);
}

TEST(CylinderMate, ACapOverTheHeadBlocksTheOnlyWayOut) {
  Assembly a = read_pin_in_bore();
  // A fixed plate resting on the head (a mesh: no cylinders), 30 × 30 × 2 in the local frame.
  AssemblyPart cap;
  cap.name = "cap";
  cap.source = "test";
  cap.fixed = true;
  const Vec3 lo(-15, -15, PinInBore::kHeadTop), hi(15, 15, PinInBore::kHeadTop + 2);
  for (const Triangle& t : test::box_triangles(lo, hi)) {
    Triangle w;
    for (int v = 0; v < 3; ++v) w[v] = PinInBore::pose().apply(t[v]);
    cap.mesh.triangles.push_back(w);
  }
  cap.mesh.name = "cap";
  a.parts.push_back(cap);
  a.parts[0].fixed = true;
  const DisassemblyResult r = disassemble(a, {.clearance = 0.01, .tolerance = 0.01, .jobs = 2, .plan_time_limit = 0});
  EXPECT_TRUE(r.interferences.empty());
  EXPECT_FALSE(r.complete);
  ASSERT_EQ(r.sequence.size(), 1u);
  const SequenceStep& s = r.sequence[0];
  EXPECT_FALSE(s.removed);
  const Vec3 up = PinInBore::pose().rotation * Vec3::UnitZ();
  bool saw_up = false, saw_down = false;
  for (const SequenceStep::Blocking& b : s.blocking) {
    if ((b.direction - up).norm() < 1e-12) {
      saw_up = true;
      EXPECT_EQ(b.blockers, std::vector<std::size_t>{2});
    }
    if ((b.direction + up).norm() < 1e-12) {
      saw_down = true;
      EXPECT_EQ(b.blockers, std::vector<std::size_t>{0});
    }
  }
  EXPECT_TRUE(saw_up);
  EXPECT_TRUE(saw_down);
}

}  // namespace
}  // namespace swept
