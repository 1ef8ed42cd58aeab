// check_path: the oracle's motion, dense exact distances and segment certificates.
#include "oracle/path_oracle.h"

#include "oracle/box_tree.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

namespace oracle {

using detail::BoxTree;
using detail::Closest;
using detail::PairKey;

double rotation_angle(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) {
  const Eigen::Quaterniond q(a.transpose() * b);
  // atan2 keeps small angles accurate (acos of w loses half the digits near 1).
  return 2.0 * std::atan2(q.vec().norm(), std::abs(q.w()));
}

RigidPose interpolate_pose(const RigidPose& a, const RigidPose& b, double s, const Eigen::Vector3d& reference) {
  if (s == 0.0) return a;
  if (s == 1.0) return b;
  const Eigen::Quaterniond qa = Eigen::Quaterniond(a.R).normalized();
  const Eigen::Quaterniond qb = Eigen::Quaterniond(b.R).normalized();
  const Eigen::Matrix3d R = qa.slerp(s, qb).toRotationMatrix();  // Eigen's slerp takes the short arc
  const Eigen::Vector3d ca = a.R * reference + a.t;
  const Eigen::Vector3d cb = b.R * reference + b.t;
  const Eigen::Vector3d c = (1.0 - s) * ca + s * cb;
  return {R, c - R * reference};
}

double exact_distance(const std::vector<Tri>& obstacles_world, const std::vector<Tri>& body_world) {
  const BoxTree ta = detail::build_tree(obstacles_world);
  const BoxTree tb = detail::build_tree(body_world);
  return detail::closest_pair(ta, obstacles_world, tb, body_world).distance;
}

namespace {

// The obstacles' tree, and the body's tree refitted at each pose in per-thread scratch.
class Scene {
 public:
  Scene(const std::vector<Tri>& obstacles, const std::vector<Tri>& body)
      : obstacles_(obstacles),
        body_(body),
        obstacle_tree_(detail::build_tree(obstacles)),
        body_tree_(detail::build_tree(body)),
        scratch_([this] { return Placed{std::vector<Tri>(body_.size()), body_tree_}; }) {}

  // Exact distance at the pose over every pair not in `exclude` (sorted; may be null).
  Closest at(const RigidPose& pose, const std::vector<PairKey>* exclude = nullptr) const {
    Placed& p = scratch_.local();
    place(pose, p);
    return detail::closest_pair(obstacle_tree_, obstacles_, p.tree, p.world, exclude);
  }

  // Every pair closer than `threshold` at the pose.
  std::vector<PairKey> close_pairs(const RigidPose& pose, double threshold) const {
    Placed& p = scratch_.local();
    place(pose, p);
    return detail::close_pairs(obstacle_tree_, obstacles_, p.tree, p.world, threshold);
  }

 private:
  struct Placed {
    std::vector<Tri> world;
    BoxTree tree;
  };
  void place(const RigidPose& pose, Placed& p) const {
    for (std::size_t i = 0; i < body_.size(); ++i)
      for (int k = 0; k < 3; ++k) p.world[i].v[k] = pose.R * body_[i].v[k] + pose.t;
    detail::refit(p.tree, p.world);
  }
  const std::vector<Tri>& obstacles_;
  const std::vector<Tri>& body_;
  BoxTree obstacle_tree_;
  BoxTree body_tree_;
  mutable tbb::enumerable_thread_specific<Placed> scratch_;
};

struct Segment {
  RigidPose a, b;
  double angle = 0;   // rotation angle, radians
  double length = 0;  // motion metric ‖Δc‖ + r·θ
};

struct Failure {
  double t = -1;
  std::string why;
};

std::string describe(std::size_t seg, double t, const Closest& c, double clearance, const char* what) {
  char buf[320];
  std::snprintf(buf, sizeof buf, "segment %zu at t=%.9g: %s distance %.9g <= clearance %.9g (obstacle triangle %d, body triangle %d)",
                seg, t, what, c.distance, clearance, c.a, c.b);
  return buf;
}

// Schwarzer, Saha, Latombe (2005): [t0, t1] is free when (t1 − t0)·L < (D(t0) − δ) + (D(t1) − δ),
// because no body point moves more than (t1 − t0)·L in between; otherwise bisect. Depth first,
// left half first, with an explicit stack and caps.
std::optional<Failure> certify(const Scene& scene, const Segment& seg, std::size_t index, const Eigen::Vector3d& ref,
                               const PathCheckInput& in, const std::vector<PairKey>* exclude, std::size_t& queries) {
  const double delta = in.clearance;
  const char* what = exclude ? "non-exempt" : "";
  auto D = [&](double t) {
    ++queries;
    return scene.at(interpolate_pose(seg.a, seg.b, t, ref), exclude);
  };
  const Closest d0 = D(0.0);
  if (!(d0.distance > delta)) return Failure{0.0, describe(index, 0.0, d0, delta, what)};
  const Closest d1 = D(1.0);
  if (!(d1.distance > delta)) return Failure{1.0, describe(index, 1.0, d1, delta, what)};
  struct Interval {
    double t0, d0, t1, d1;
    int depth;
  };
  std::vector<Interval> stack{{0.0, d0.distance, 1.0, d1.distance, 0}};
  std::size_t spent = 2;
  while (!stack.empty()) {
    const Interval iv = stack.back();
    stack.pop_back();
    if ((iv.t1 - iv.t0) * seg.length < (iv.d0 - delta) + (iv.d1 - delta)) continue;
    if (iv.depth >= in.max_certificate_depth || spent >= static_cast<std::size_t>(in.max_certificate_queries)) {
      char buf[200];
      std::snprintf(buf, sizeof buf, "segment %zu not certified: the certificate needs more than %s near t=%.9g", index,
                    iv.depth >= in.max_certificate_depth ? "the depth cap" : "the query cap", iv.t0);
      return Failure{iv.t0, buf};
    }
    const double tm = 0.5 * (iv.t0 + iv.t1);
    const Closest dm = D(tm);
    ++spent;
    if (!(dm.distance > delta)) return Failure{tm, describe(index, tm, dm, delta, what)};
    stack.push_back({tm, dm.distance, iv.t1, iv.d1, iv.depth + 1});
    stack.push_back({iv.t0, iv.d0, tm, dm.distance, iv.depth + 1});
  }
  return std::nullopt;
}

bool finite_pose(const RigidPose& p) { return p.R.allFinite() && p.t.allFinite(); }

}  // namespace

PathCheckReport check_path(const PathCheckInput& in) {
  PathCheckReport rep;
  const double delta = in.clearance;
  if (in.poses.empty()) {
    rep.why = "the path has no poses";
    return rep;
  }
  for (std::size_t i = 0; i < in.poses.size(); ++i)
    if (!finite_pose(in.poses[i])) {
      rep.why = "pose " + std::to_string(i) + " is not finite";
      rep.bad_segment = static_cast<int>(std::min(i, in.poses.size() > 1 ? in.poses.size() - 2 : 0));
      return rep;
    }
  const Scene scene(in.obstacles, in.body);

  double radius = 0;
  for (const Tri& t : in.body)
    for (const auto& v : t.v) radius = std::max(radius, (v - in.reference).norm());
  std::vector<Segment> segs;
  double total = 0;
  for (std::size_t i = 0; i + 1 < in.poses.size(); ++i) {
    Segment s{in.poses[i], in.poses[i + 1]};
    s.angle = rotation_angle(s.a.R, s.b.R);
    const Eigen::Vector3d ca = s.a.R * in.reference + s.a.t;
    const Eigen::Vector3d cb = s.b.R * in.reference + s.b.t;
    s.length = (cb - ca).norm() + radius * s.angle;
    total += s.length;
    rep.max_segment_length = std::max(rep.max_segment_length, s.length);
    segs.push_back(s);
  }

  // The start decides whether the first segment is an escape from contact.
  const Closest start = scene.at(in.poses.front());
  rep.escape = !segs.empty() && in.contact_tolerance > 0 && !(start.distance > delta);
  std::vector<PairKey> exempt;
  if (rep.escape) exempt = scene.close_pairs(in.poses.front(), delta + in.contact_tolerance);
  rep.exempt_pairs = exempt.size();

  // Dense samples: n_i intervals on segment i, n_i ∝ length, at least 16.
  struct Sample {
    std::size_t seg;
    double t;
    bool relaxed;  // the escape's distance over the non-exempt pairs
  };
  std::vector<Sample> samples;
  for (std::size_t i = 0; i < segs.size(); ++i) {
    const double share = total > 0 ? static_cast<double>(in.dense_samples) * segs[i].length / total : 0.0;
    const int n = std::max(16, static_cast<int>(std::ceil(share)));
    rep.dense_spacing = std::max(rep.dense_spacing, segs[i].length / n);
    for (int k = i == 0 ? 0 : 1; k <= n; ++k) samples.push_back({i, static_cast<double>(k) / n, false});
    if (i == 0 && rep.escape)
      for (int k = 0; k <= n; ++k) samples.push_back({i, static_cast<double>(k) / n, true});
  }
  std::vector<double> dense(samples.size());
  tbb::parallel_for(std::size_t{0}, samples.size(), [&](std::size_t k) {
    const Sample& s = samples[k];
    const RigidPose p = interpolate_pose(segs[s.seg].a, segs[s.seg].b, s.t, in.reference);
    dense[k] = scene.at(p, s.relaxed ? &exempt : nullptr).distance;
  });
  rep.dense_min = segs.empty() ? start.distance : std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < samples.size(); ++k) {
    if (samples[k].relaxed)
      rep.escape_dense_min = std::min(rep.escape_dense_min, dense[k]);
    else
      rep.dense_min = std::min(rep.dense_min, dense[k]);
  }

  if (segs.empty()) {
    rep.valid = start.distance > delta;
    if (!rep.valid) {
      rep.bad_segment = 0;
      rep.bad_t = 0;
      rep.why = "single pose: " + describe(0, 0.0, start, delta, "");
    }
    return rep;
  }

  // Certificates, segments in parallel; the first failing segment (in path order) is reported.
  std::vector<std::optional<Failure>> failure(segs.size());
  std::vector<std::size_t> queries(segs.size(), 0);
  tbb::parallel_for(std::size_t{0}, segs.size(), [&](std::size_t i) {
    if (i == 0 && rep.escape) {
      if (segs[0].angle > 1e-12) {
        char buf[200];
        std::snprintf(buf, sizeof buf, "segment 0 is an escape from contact but rotates by %.3g rad (must be a pure translation)",
                      segs[0].angle);
        failure[0] = Failure{0.0, buf};
        return;
      }
      failure[0] = certify(scene, segs[0], 0, in.reference, in, &exempt, queries[0]);
      if (!failure[0]) {
        ++queries[0];
        const Closest end = scene.at(segs[0].b);
        if (!(end.distance > delta))
          failure[0] = Failure{1.0, describe(0, 1.0, end, delta, "escape end (all pairs):")};
      }
      return;
    }
    failure[i] = certify(scene, segs[i], i, in.reference, in, nullptr, queries[i]);
  });
  for (std::size_t q : queries) rep.certificate_queries += q;
  for (std::size_t i = 0; i < segs.size(); ++i) {
    if (failure[i]) {
      rep.bad_segment = static_cast<int>(i);
      rep.bad_t = failure[i]->t;
      rep.why = failure[i]->why;
      return rep;
    }
  }
  rep.valid = true;
  return rep;
}

}  // namespace oracle
