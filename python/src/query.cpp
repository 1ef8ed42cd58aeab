// The queries of swept/query/query.h, vectorised over poses: one small function per query.
// The arrays are allocated with the GIL held, then filled by oneTBB threads with the GIL released.
#include "convert.h"

#include "swept/query/query.h"

#include <chrono>
#include <cmath>

namespace swept::py {

namespace {

const Bvh& tree(const PyBvh& b) { return *b.bvh; }

void check_number(double v, const char* name, bool positive_or_zero = true) {
  if (!std::isfinite(v) && !(std::isinf(v) && v > 0))
    throw InputError(std::string(name) + " must be a number, not " + std::to_string(v));
  if (positive_or_zero && v < 0) throw InputError(std::string(name) + " must be >= 0, not " + std::to_string(v));
}

pyb::dict distance_py(const PyBvh& a, const PyBvh& b, const pyb::handle& poses_a_in, const pyb::handle& poses_b_in,
                      double rel_err, double abs_err, int threads) {
  check_number(rel_err, "rel_err");
  check_number(abs_err, "abs_err");
  const PoseArray pa = to_poses(poses_a_in, "poses_a"), pb = to_poses(poses_b_in, "poses_b");
  const std::size_t k = broadcast_count({{&pa, "poses_a"}, {&pb, "poses_b"}});
  const auto n = static_cast<pyb::ssize_t>(k);
  auto dist = new_array<double>({n});
  auto point_a = new_array<double>({n, 3}), point_b = new_array<double>({n, 3});
  auto tri_a = new_array<std::int64_t>({n}), tri_b = new_array<std::int64_t>({n});
  auto exact = new_array<bool>({n});
  auto bv_tests = new_array<std::uint64_t>({n}), tri_tests = new_array<std::uint64_t>({n});
  double* d = dist.mutable_data();
  double *xa = point_a.mutable_data(), *xb = point_b.mutable_data();
  std::int64_t *ta = tri_a.mutable_data(), *tb = tri_b.mutable_data();
  bool* ex = exact.mutable_data();
  std::uint64_t *bv = bv_tests.mutable_data(), *tt = tri_tests.mutable_data();
  const DistanceRequest request{.rel_err = rel_err, .abs_err = abs_err};
  parallel_for(k, threads, [&](std::size_t i) {
    const DistanceResult r = swept::distance(tree(a), pa[i], tree(b), pb[i], request);
    d[i] = r.distance;
    for (int c = 0; c < 3; ++c) xa[3 * i + c] = r.point_a[c], xb[3 * i + c] = r.point_b[c];
    ta[i] = r.triangle_a, tb[i] = r.triangle_b, ex[i] = r.exact;
    bv[i] = r.stats.bv_tests, tt[i] = r.stats.triangle_tests;
  });
  pyb::dict out;
  out["distance"] = dist, out["point_a"] = point_a, out["point_b"] = point_b;
  out["triangle_a"] = tri_a, out["triangle_b"] = tri_b, out["exact"] = exact;
  out["bv_tests"] = bv_tests, out["triangle_tests"] = tri_tests;
  return out;
}

pyb::dict collide_py(const PyBvh& a, const PyBvh& b, const pyb::handle& poses_a_in, const pyb::handle& poses_b_in,
                     bool all_contacts, int threads) {
  const PoseArray pa = to_poses(poses_a_in, "poses_a"), pb = to_poses(poses_b_in, "poses_b");
  const std::size_t k = broadcast_count({{&pa, "poses_a"}, {&pb, "poses_b"}});
  const auto n = static_cast<pyb::ssize_t>(k);
  auto colliding = new_array<bool>({n});
  auto tri_a = new_array<std::int64_t>({n}), tri_b = new_array<std::int64_t>({n});
  auto bv_tests = new_array<std::uint64_t>({n}), tri_tests = new_array<std::uint64_t>({n});
  bool* c = colliding.mutable_data();
  std::int64_t *ta = tri_a.mutable_data(), *tb = tri_b.mutable_data();
  std::uint64_t *bv = bv_tests.mutable_data(), *tt = tri_tests.mutable_data();
  std::vector<std::vector<ContactPair>> contacts(all_contacts ? k : 0);
  const CollideRequest request{.all_contacts = all_contacts};
  parallel_for(k, threads, [&](std::size_t i) {
    CollideResult r = swept::collide(tree(a), pa[i], tree(b), pb[i], request);
    c[i] = r.colliding;
    ta[i] = r.contacts.empty() ? std::int64_t{-1} : static_cast<std::int64_t>(r.contacts.front().triangle_a);
    tb[i] = r.contacts.empty() ? std::int64_t{-1} : static_cast<std::int64_t>(r.contacts.front().triangle_b);
    bv[i] = r.stats.bv_tests, tt[i] = r.stats.triangle_tests;
    if (all_contacts) contacts[i] = std::move(r.contacts);
  });
  pyb::dict out;
  out["colliding"] = colliding, out["triangle_a"] = tri_a, out["triangle_b"] = tri_b;
  out["bv_tests"] = bv_tests, out["triangle_tests"] = tri_tests;
  if (all_contacts) {
    pyb::list lists;
    for (const auto& pairs : contacts) {
      auto arr = new_array<std::int64_t>({static_cast<pyb::ssize_t>(pairs.size()), 2});
      std::int64_t* p = arr.mutable_data();
      for (std::size_t j = 0; j < pairs.size(); ++j) p[2 * j] = pairs[j].triangle_a, p[2 * j + 1] = pairs[j].triangle_b;
      lists.append(arr);
    }
    out["contacts"] = lists;
  } else {
    out["contacts"] = pyb::none();
  }
  return out;
}

pyb::dict tolerance_py(const PyBvh& a, const PyBvh& b, const pyb::handle& poses_a_in, const pyb::handle& poses_b_in,
                       double tol, int threads) {
  check_number(tol, "tolerance");
  const PoseArray pa = to_poses(poses_a_in, "poses_a"), pb = to_poses(poses_b_in, "poses_b");
  const std::size_t k = broadcast_count({{&pa, "poses_a"}, {&pb, "poses_b"}});
  const auto n = static_cast<pyb::ssize_t>(k);
  auto within = new_array<bool>({n});
  auto dist = new_array<double>({n});
  auto point_a = new_array<double>({n, 3}), point_b = new_array<double>({n, 3});
  auto tri_a = new_array<std::int64_t>({n}), tri_b = new_array<std::int64_t>({n});
  auto bv_tests = new_array<std::uint64_t>({n}), tri_tests = new_array<std::uint64_t>({n});
  bool* w = within.mutable_data();
  double* d = dist.mutable_data();
  double *xa = point_a.mutable_data(), *xb = point_b.mutable_data();
  std::int64_t *ta = tri_a.mutable_data(), *tb = tri_b.mutable_data();
  std::uint64_t *bv = bv_tests.mutable_data(), *tt = tri_tests.mutable_data();
  const ToleranceRequest request{.tolerance = tol};
  parallel_for(k, threads, [&](std::size_t i) {
    const ToleranceResult r = swept::tolerance(tree(a), pa[i], tree(b), pb[i], request);
    w[i] = r.within, d[i] = r.distance;
    for (int c = 0; c < 3; ++c) xa[3 * i + c] = r.point_a[c], xb[3 * i + c] = r.point_b[c];
    ta[i] = r.within ? static_cast<std::int64_t>(r.triangle_a) : -1;
    tb[i] = r.within ? static_cast<std::int64_t>(r.triangle_b) : -1;
    bv[i] = r.stats.bv_tests, tt[i] = r.stats.triangle_tests;
  });
  pyb::dict out;
  out["within"] = within, out["distance"] = dist, out["point_a"] = point_a, out["point_b"] = point_b;
  out["triangle_a"] = tri_a, out["triangle_b"] = tri_b, out["bv_tests"] = bv_tests, out["triangle_tests"] = tri_tests;
  return out;
}

/// Centre of the bounding box of a tree's triangles (model frame): the planner's default
/// reference point of a body.
Vec3 box_centre(const Bvh& b) { return bounds(b.triangles).center(); }

pyb::dict motion_py(const PyBvh& a, const PyBvh& b, const pyb::handle& poses_a_in, const pyb::handle& from_in,
                    const pyb::handle& to_in, double margin, const pyb::handle& reference_in,
                    const pyb::handle& radius_in, int max_queries, int threads) {
  check_number(margin, "margin");
  if (!std::isfinite(margin)) throw InputError("margin must be finite");
  if (max_queries < 1) throw InputError("max_queries must be >= 1, not " + std::to_string(max_queries));
  const PoseArray pa = to_poses(poses_a_in, "poses_a"), from = to_poses(from_in, "poses_from"),
                  to = to_poses(to_in, "poses_to");
  const std::size_t k = broadcast_count({{&pa, "poses_a"}, {&from, "poses_from"}, {&to, "poses_to"}});
  MotionRequest request;
  request.margin = margin;
  request.max_queries = max_queries;
  const Vec3 reference = reference_in.is_none() ? box_centre(tree(b)) : to_vec3(reference_in, "reference");
  double radius = 0.0;
  if (radius_in.is_none()) {
    radius = motion_radius(tree(b), reference);
  } else {
    radius = radius_in.cast<double>();
    if (!std::isfinite(radius) || radius < 0)
      throw InputError("radius must be a finite number >= 0, not " + std::to_string(radius));
    const double needed = motion_radius(tree(b), reference);
    if (radius < needed)
      throw InputError("radius " + std::to_string(radius) + " is smaller than the body's radius about the reference (" +
                       std::to_string(needed) + "): the certificate would not hold");
  }
  const auto n = static_cast<pyb::ssize_t>(k);
  auto free = new_array<bool>({n});
  auto t_blocked = new_array<double>({n}), at_block = new_array<double>({n}), min_d = new_array<double>({n});
  auto queries = new_array<std::int64_t>({n}), sweeps = new_array<std::int64_t>({n});
  bool* f = free.mutable_data();
  double *tb = t_blocked.mutable_data(), *ab = at_block.mutable_data(), *md = min_d.mutable_data();
  std::int64_t *q = queries.mutable_data(), *sw = sweeps.mutable_data();
  parallel_for(k, threads, [&](std::size_t i) {
    const MotionResult r = swept::motion_clearance(tree(a), pa[i], tree(b), {from[i], to[i], reference, radius}, request);
    f[i] = r.clear(), tb[i] = r.t_blocked, ab[i] = r.distance_at_block, md[i] = r.min_distance, q[i] = r.distance_queries;
    sw[i] = r.sweeps;
  });
  pyb::dict out;
  out["free"] = free, out["t_blocked"] = t_blocked, out["distance_at_block"] = at_block, out["min_distance"] = min_d;
  out["distance_queries"] = queries, out["sweeps"] = sweeps;
  auto ref = new_array<double>({3});
  for (int c = 0; c < 3; ++c) ref.mutable_data()[c] = reference[c];
  out["reference"] = ref;
  out["radius"] = radius;
  return out;
}

/// For bench/bench_python.py: milliseconds of swept::distance_batch alone (C++ poses built
/// beforehand, untimed), the reference the Python call's overhead is measured against.
double distance_batch_cpp_ms(const PyBvh& a, const PyBvh& b, const pyb::handle& poses_b_in) {
  const PoseArray pb = to_poses(poses_b_in, "poses_b");
  pyb::gil_scoped_release release;
  const auto t0 = std::chrono::steady_clock::now();
  const auto r = distance_batch(tree(a), Pose{}, tree(b), pb.poses);
  const auto t1 = std::chrono::steady_clock::now();
  volatile double sink = r.empty() ? 0.0 : r.back().distance;
  (void)sink;
  return std::chrono::duration<double, std::milli>(t1 - t0).count();
}

}  // namespace

void bind_query(pyb::module_& m) {
  using pyb::arg;
  m.def("_distance", &distance_py, arg("a"), arg("b"), arg("poses_a"), arg("poses_b"), arg("rel_err"), arg("abs_err"),
        arg("threads"));
  m.def("_collide", &collide_py, arg("a"), arg("b"), arg("poses_a"), arg("poses_b"), arg("all_contacts"), arg("threads"));
  m.def("_tolerance", &tolerance_py, arg("a"), arg("b"), arg("poses_a"), arg("poses_b"), arg("tolerance"), arg("threads"));
  m.def("_motion_clearance", &motion_py, arg("a"), arg("b"), arg("poses_a"), arg("poses_from"), arg("poses_to"),
        arg("margin"), arg("reference"), arg("radius"), arg("max_queries"), arg("threads"));
  m.def("_distance_batch_cpp_ms", &distance_batch_cpp_ms, arg("a"), arg("b"), arg("poses_b"));
}

}  // namespace swept::py
