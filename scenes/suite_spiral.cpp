// The spiral tube of the planner benchmark suite: a round tube bent along a helix (OpenCASCADE
// pipe along straight runs and circular bends), capped at its lower end, with a rod inside that
// must travel the whole spiral to leave. See swept/scenes/planning_suite.h.
#include "swept/scenes/modeling.h"
#include "swept/scenes/planning_suite.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace swept::scenes::suite {
namespace {

constexpr double kPi = std::numbers::pi;
// The helix: radius, rise per turn, turns, corners per turn of the polyline the tube follows.
constexpr double kHelixRadius = 12.0, kPitch = 10.0, kTurns = 2.0;
constexpr int kCornersPerTurn = 8;
constexpr double kBendRadius = 5.0;  // < the runs' half length (4.6) / tan(22.5°) keeps every run straight in part
constexpr double kOuter = 3.0, kInner = 2.4, kCap = 1.0;
// The rod: 4 long along its x axis, 1.4 × 1.4 across (half-diagonal across 0.99). Through a bend
// of radius 5 its ends swing 5 − √(5² − 2²) = 0.42 off the centre line: 1.41 < 2.4 from the axis.
constexpr double kRodHalf = 2.0, kRodSide = 1.4;
// BRepMesh: the inner wall's chords sit at most kDeflection inside the true surface.
constexpr double kDeflection = 0.02, kAngular = 0.35;
constexpr int kArcSamples = 6;  // witness waypoints per bend: chord error 5(1 − cos(45°/12)) ≈ 0.011

/// The rod's orientation with its x axis along `tangent` (the smallest rotation from x).
Mat3 along(const Vec3& tangent) { return Eigen::Quaterniond::FromTwoVectors(Vec3::UnitX(), tangent).toRotationMatrix(); }

}  // namespace

SuiteProblem spiral_tube() {
  SuiteProblem s;
  s.problem.name = "spiral-tube";
  Problem& p = s.problem.problem;
  p.unit = "mm";
  p.clearance = 0.05;
  p.bounds = Aabb{Vec3(-20, -20, -10), Vec3(20, 20, 32)};
  p.rotation = RotationMode::free;
  p.time_limit = 60.0;
  p.threads = 2;

  const int n = static_cast<int>(kTurns * kCornersPerTurn) + 1;
  std::vector<Vec3> points;
  for (int k = 0; k < n; ++k) {
    const double a = 2 * kPi * k / kCornersPerTurn;
    points.emplace_back(kHelixRadius * std::cos(a), kHelixRadius * std::sin(a), kPitch * k / kCornersPerTurn);
  }
  const Vec3 first = (points[1] - points[0]).normalized();
  const Vec3 last = (points[n - 1] - points[n - 2]).normalized();
  const TopoDS_Shape tube = detail::bent_tube(points, kBendRadius, kOuter, kInner);
  const TopoDS_Shape cap = detail::cylinder(points[0] - kCap * first, first, kOuter, kCap);
  const TopoDS_Shape all = detail::compound({tube, cap});
  detail::mesh(all, kDeflection, kAngular);
  s.problem.obstacles = detail::triangles_of(all, "obstacles");
  s.problem.body.name = "body";
  add_box(s.problem.body.triangles, Vec3(-kRodHalf, -kRodSide / 2, -kRodSide / 2), Vec3(kRodHalf, kRodSide / 2, kRodSide / 2));

  // The witness follows the tube's centre line as bent_tube builds it: straight runs between
  // the bends' tangent points, each bend sampled along its arc, the rod along the tangent.
  auto pose = [](const Vec3& c, const Vec3& tangent) {
    const Mat3 r = along(tangent);
    return Pose{r, c};  // the rod's origin is its centre
  };
  s.witness.push_back(pose(points[0] + (kRodHalf + 1.0) * first, first));  // 1 from the cap
  for (int i = 1; i + 1 < n; ++i) {
    const Vec3 u = (points[i] - points[i - 1]).normalized(), v = (points[i + 1] - points[i]).normalized();
    const double turn = std::acos(std::clamp(u.dot(v), -1.0, 1.0));
    const double t = kBendRadius * std::tan(0.5 * turn);
    const Vec3 w = (v - u).normalized();
    const Vec3 centre = points[i] + w * (kBendRadius / std::cos(0.5 * turn));
    const Vec3 a = points[i] - u * t - centre, b = points[i] + v * t - centre;
    for (int k = 0; k <= kArcSamples; ++k) {
      const double f = static_cast<double>(k) / kArcSamples;
      const double sa = std::sin((1 - f) * turn) / std::sin(turn), sb = std::sin(f * turn) / std::sin(turn);
      s.witness.push_back(pose(centre + sa * a + sb * b, (sa * u + sb * v).normalized()));
    }
  }
  s.witness.push_back(pose(points[n - 1] + (kRodHalf + 3.0) * last, last));  // 3 beyond the open end
  s.passage_width = 2 * kInner;
  s.body_width = 2 * std::hypot(kRodSide / 2, kRodSide / 2);
  s.passage = "the tube's bore, 4.8 across, 2 turns of radius 12 with 16 bends of radius 5";
  p.start = s.witness.front();
  p.goal = s.witness.back();
  return s;
}

}  // namespace swept::scenes::suite
