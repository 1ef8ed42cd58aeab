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

  // The deepest triangle_penetration of the pairs that touch at the pose.
  double penetration(const RigidPose& pose) const {
    Placed& p = scratch_.local();
    place(pose, p);
    double deepest = 0;
    for (PairKey k : detail::close_pairs(obstacle_tree_, obstacles_, p.tree, p.world, 1e-150)) {
      const auto a = static_cast<std::size_t>(k >> 32), b = static_cast<std::size_t>(k & 0xffffffffu);
      deepest = std::max(deepest, triangle_penetration(obstacles_[a], p.world[b]));
    }
    return deepest;
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
  const char* what = "";
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

double triangle_penetration(const Tri& a, const Tri& b) {
  if (triangle_distance(a, b) > 0) return 0;
  std::vector<Eigen::Vector3d> axes;
  const Eigen::Vector3d na = (a.v[1] - a.v[0]).cross(a.v[2] - a.v[0]);
  const Eigen::Vector3d nb = (b.v[1] - b.v[0]).cross(b.v[2] - b.v[0]);
  axes.push_back(na);
  axes.push_back(nb);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) axes.push_back((a.v[(i + 1) % 3] - a.v[i]).cross(b.v[(j + 1) % 3] - b.v[j]));
  for (int i = 0; i < 3; ++i) {
    axes.push_back(na.cross(a.v[(i + 1) % 3] - a.v[i]));
    axes.push_back(nb.cross(b.v[(i + 1) % 3] - b.v[i]));
  }
  double best = std::numeric_limits<double>::infinity();
  for (const Eigen::Vector3d& axis : axes) {
    const double n = axis.norm();
    if (!(n > 1e-12 * (1.0 + na.norm() + nb.norm()))) continue;
    const Eigen::Vector3d u = axis / n;
    double lo_a = u.dot(a.v[0]), hi_a = lo_a, lo_b = u.dot(b.v[0]), hi_b = lo_b;
    for (int k = 1; k < 3; ++k) {
      lo_a = std::min(lo_a, u.dot(a.v[k])), hi_a = std::max(hi_a, u.dot(a.v[k]));
      lo_b = std::min(lo_b, u.dot(b.v[k])), hi_b = std::max(hi_b, u.dot(b.v[k]));
    }
    best = std::min(best, std::max(0.0, std::min(hi_a - lo_b, hi_b - lo_a)));
  }
  return std::isfinite(best) ? best : 0.0;
}

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

  // Where each waypoint is in contact decides which segments are motions in contact.
  std::vector<double> at_waypoint(in.poses.size());
  tbb::parallel_for(std::size_t{0}, in.poses.size(), [&](std::size_t w) { at_waypoint[w] = scene.at(in.poses[w]).distance; });
  const Closest start = scene.at(in.poses.front());
  std::vector<bool> in_contact(segs.size(), false);
  for (std::size_t i = 0; i < segs.size(); ++i) {
    in_contact[i] = in.contact_tolerance > 0 && (!(at_waypoint[i] > delta) || !(at_waypoint[i + 1] > delta));
    if (in_contact[i]) ++rep.contact_segments;
  }

  // Dense samples: n_i intervals on segment i, n_i ∝ length, at least 16; on a motion in contact
  // no farther apart than a quarter of the tolerance (at most 2^16).
  struct Sample {
    std::size_t seg;
    double t;
  };
  std::vector<Sample> samples;
  for (std::size_t i = 0; i < segs.size(); ++i) {
    const double share = total > 0 ? static_cast<double>(in.dense_samples) * segs[i].length / total : 0.0;
    int n = std::max(16, static_cast<int>(std::ceil(share)));
    if (in_contact[i]) n = std::max(n, static_cast<int>(std::min(65536.0, std::ceil(4.0 * segs[i].length / in.contact_tolerance))));
    rep.dense_spacing = std::max(rep.dense_spacing, segs[i].length / n);
    for (int k = i == 0 ? 0 : 1; k <= n; ++k) samples.push_back({i, static_cast<double>(k) / n});
  }
  std::vector<double> dense(samples.size()), depth(samples.size(), 0.0);
  tbb::parallel_for(std::size_t{0}, samples.size(), [&](std::size_t k) {
    const Sample& s = samples[k];
    const RigidPose p = interpolate_pose(segs[s.seg].a, segs[s.seg].b, s.t, in.reference);
    dense[k] = scene.at(p).distance;
    if (in_contact[s.seg] && !(dense[k] > 0)) depth[k] = scene.penetration(p);
  });
  rep.dense_min = segs.empty() ? start.distance : std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < samples.size(); ++k) {
    rep.dense_min = std::min(rep.dense_min, dense[k]);
    rep.max_penetration = std::max(rep.max_penetration, depth[k]);
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
    if (in_contact[i]) {
      char buf[240];
      if (segs[i].angle > 1e-12) {
        std::snprintf(buf, sizeof buf, "segment %zu has an end in contact but rotates by %.3g rad (must be a pure translation)", i,
                      segs[i].angle);
        failure[i] = Failure{0.0, buf};
        return;
      }
      const double limit = in.contact_tolerance * (1 + 1e-9) + 1e-12;
      for (std::size_t k = 0; k < samples.size(); ++k)
        if (samples[k].seg == i && depth[k] > limit) {
          std::snprintf(buf, sizeof buf, "segment %zu at t=%.9g: two triangles reach %.9g into each other (tolerance %.9g)", i,
                        samples[k].t, depth[k], in.contact_tolerance);
          failure[i] = Failure{samples[k].t, buf};
          return;
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
