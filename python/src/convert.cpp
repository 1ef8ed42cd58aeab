// Pose arrays in, threads for the batches.
#include "convert.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <sstream>

namespace swept::py {

namespace {

std::string shape_text(const pyb::array& a) {
  std::ostringstream os;
  os << "(";
  for (pyb::ssize_t i = 0; i < a.ndim(); ++i) os << (i ? ", " : "") << a.shape(i);
  os << (a.ndim() == 1 ? ",)" : ")");
  return os.str();
}

pyb::array_t<double, pyb::array::c_style | pyb::array::forcecast> as_doubles(const pyb::handle& obj, const char* name) {
  auto a = pyb::array_t<double, pyb::array::c_style | pyb::array::forcecast>::ensure(obj);
  if (!a) throw InputError(std::string(name) + ": not an array of numbers");
  return a;
}

}  // namespace

PoseArray to_poses(const pyb::handle& obj, const char* name) {
  PoseArray out;
  if (obj.is_none()) {
    out.poses.push_back(Pose{});
    return out;
  }
  auto a = as_doubles(obj, name);
  const pyb::ssize_t nd = a.ndim();
  bool matrix = false;
  if (nd == 1 && a.shape(0) == 7) {
    out.single = true;
  } else if (nd == 2 && a.shape(0) == 4 && a.shape(1) == 4) {
    out.single = true, matrix = true;
  } else if (nd == 2 && a.shape(1) == 7) {
    out.single = false;
  } else if (nd == 3 && a.shape(1) == 4 && a.shape(2) == 4) {
    out.single = false, matrix = true;
  } else {
    throw InputError(std::string(name) + ": poses must have shape (7,), (4, 4), (K, 7) or (K, 4, 4), not " +
                     shape_text(a));
  }
  const std::size_t count = out.single ? 1 : static_cast<std::size_t>(a.shape(0));
  const double* v = a.data();
  out.poses.resize(count);
  auto where = [&](std::size_t k) {
    return out.single ? std::string(name) : std::string(name) + "[" + std::to_string(k) + "]";
  };
  for (std::size_t k = 0; k < count; ++k) {
    const double* p = v + k * (matrix ? 16 : 7);
    for (int i = 0; i < (matrix ? 16 : 7); ++i)
      if (!std::isfinite(p[i])) throw InputError(where(k) + ": non-finite value " + std::to_string(p[i]));
    if (!matrix) {
      const Quat q(p[6], p[3], p[4], p[5]);  // Eigen: (w, x, y, z)
      if (q.coeffs().cwiseAbs().maxCoeff() == 0.0) throw InputError(where(k) + ": zero quaternion");
      out.poses[k] = Pose::from_quaternion(q, Vec3(p[0], p[1], p[2]));
    } else {
      Mat3 r;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) r(i, j) = p[4 * i + j];
      if (p[12] != 0.0 || p[13] != 0.0 || p[14] != 0.0 || p[15] != 1.0)
        throw InputError(where(k) + ": the last row of a 4x4 pose must be (0, 0, 0, 1)");
      const double err = (r.transpose() * r - Mat3::Identity()).cwiseAbs().maxCoeff();
      if (err > 1e-9 || r.determinant() <= 0.0) {
        std::ostringstream os;
        os << where(k) << ": the rotation is not orthonormal with determinant +1 (max |R^T R - I| = " << err
           << ", det = " << r.determinant() << ")";
        throw InputError(os.str());
      }
      out.poses[k] = Pose{r, Vec3(p[3], p[7], p[11])};
    }
  }
  return out;
}

std::size_t broadcast_count(std::initializer_list<std::pair<const PoseArray*, const char*>> args) {
  std::size_t count = 1;
  const char* first = nullptr;
  for (const auto& [p, name] : args) {
    if (p->single) continue;
    if (!first) {
      count = p->size(), first = name;
    } else if (p->size() != count) {
      throw InputError(std::string(first) + " has " + std::to_string(count) + " poses, " + name + " has " +
                       std::to_string(p->size()) + " (give as many, or one pose for all)");
    }
  }
  return count;
}

Vec3 to_vec3(const pyb::handle& obj, const char* name) {
  auto a = as_doubles(obj, name);
  if (a.ndim() != 1 || a.shape(0) != 3)
    throw InputError(std::string(name) + ": a point must have shape (3,), not " + shape_text(a));
  const Vec3 v(a.data()[0], a.data()[1], a.data()[2]);
  if (!v.allFinite()) throw InputError(std::string(name) + ": non-finite coordinate");
  return v;
}

void write_pose7(const Pose& p, double* out) {
  const Quat q = p.quaternion();
  out[0] = p.translation.x(), out[1] = p.translation.y(), out[2] = p.translation.z();
  out[3] = q.x(), out[4] = q.y(), out[5] = q.z(), out[6] = q.w();
}

pyb::array_t<double> vec3_array(const Vec3& v) {
  pyb::array_t<double> a(3);
  for (int c = 0; c < 3; ++c) a.mutable_data()[c] = v[c];
  return a;
}

pyb::array_t<double> poses_array(const std::vector<Pose>& poses) {
  pyb::array_t<double> a({static_cast<pyb::ssize_t>(poses.size()), pyb::ssize_t{7}});
  for (std::size_t i = 0; i < poses.size(); ++i) write_pose7(poses[i], a.mutable_data() + 7 * i);
  return a;
}

void parallel_for(std::size_t count, int threads, const std::function<void(std::size_t)>& body) {
  if (threads < 0) throw InputError("threads must be >= 0 (0: all cores), not " + std::to_string(threads));
  // In chunks, so that Ctrl-C (a signal Python sees between chunks) stops a long batch: the GIL
  // is taken back for a moment after each chunk. The chunks do not change any result.
  constexpr std::size_t kChunk = 8192;
  std::unique_ptr<tbb::task_arena> arena;
  if (threads != 1 && count > 1) {
    int concurrency = threads;
    if (concurrency <= 0) concurrency = tbb::task_arena::automatic;  // read, not bound to a reference
    arena = std::make_unique<tbb::task_arena>(concurrency);
  }
  for (std::size_t begin = 0; begin < count; begin += kChunk) {
    const std::size_t end = std::min(count, begin + kChunk);
    {
      pyb::gil_scoped_release release;
      if (!arena) {
        for (std::size_t k = begin; k < end; ++k) body(k);
      } else {
        arena->execute([&] {
          tbb::parallel_for(tbb::blocked_range<std::size_t>(begin, end), [&](const tbb::blocked_range<std::size_t>& r) {
            for (std::size_t k = r.begin(); k != r.end(); ++k) body(k);
          });
        });
      }
    }
    if (end < count && PyErr_CheckSignals() != 0) throw pyb::error_already_set();
  }
}

}  // namespace swept::py
