#pragma once
// Shared by the binding sources: the swept.Error exception, pose arrays, the thread arena and the
// Python-side objects that own meshes and trees.
#include "swept/bvh/bvh.h"
#include "swept/geometry/pose.h"
#include "swept/geometry/result.h"
#include "swept/geometry/types.h"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstddef>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace swept::py {

namespace pyb = pybind11;

/// Bad input: raised in Python as swept.Error (a ValueError) carrying the message as it is.
/// The messages are the ones the command line prints after "swept: error: ".
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// The value, or InputError with the library's message (optionally prefixed, as the CLI does).
template <class T>
T value_or_raise(Result<T> r, const std::string& prefix = {}) {
  if (!r) throw InputError(prefix + r.error().message);
  return std::move(r).value();
}

/// A triangle soup shared between a Mesh, its trees and the NumPy views onto it.
struct MeshData {
  TriangleSoup soup;
  std::string file;  ///< the path as given to Mesh.load ("" for meshes from arrays)
  std::string unit;
  std::size_t degenerate_triangles = 0;
  std::vector<std::string> warnings;
};

/// swept.Mesh: the soup plus the arrays the user gave (returned as they are) or views onto it.
struct PyMesh {
  std::shared_ptr<const MeshData> data;
  pyb::object vertices;  ///< (N, 3) float64
  pyb::object faces;     ///< (M, 3) int64
};

/// swept.BVH: an immutable tree (safe for concurrent queries), and the mesh it was built from.
struct PyBvh {
  std::shared_ptr<const Bvh> bvh;
  std::shared_ptr<const MeshData> mesh;  ///< null for the trees of a plan scene's parts
  double build_ms = 0.0;
};

/// A swept.Mesh over `data`: `.vertices` a read-only view onto the soup (three vertices per
/// triangle), `.faces` arange(3 M).reshape(M, 3).
PyMesh mesh_from_data(std::shared_ptr<const MeshData> data);

/// Poses given as None (identity), one pose ((7,) or (4, 4)) or K poses ((K, 7) or (K, 4, 4)).
/// (x, y, z, qx, qy, qz, qw): translation then quaternion, scalar last (OMPL's .path order);
/// the quaternion need not be normalised. 4×4: homogeneous matrices, rotation orthonormal.
struct PoseArray {
  std::vector<Pose> poses;
  bool single = true;  ///< given as None or one pose: broadcast against the other arguments
  std::size_t size() const { return poses.size(); }
  const Pose& operator[](std::size_t k) const { return single ? poses[0] : poses[k]; }
};
PoseArray to_poses(const pyb::handle& obj, const char* name);

/// K for poses given together: all single → 1; otherwise every non-single one has the same count.
std::size_t broadcast_count(std::initializer_list<std::pair<const PoseArray*, const char*>> args);

/// A (3,) point from Python (raises swept.Error on a wrong shape or a non-finite value).
Vec3 to_vec3(const pyb::handle& obj, const char* name);

/// A pose as (x, y, z, qx, qy, qz, qw) written at out[0..6].
void write_pose7(const Pose& p, double* out);
/// A (3,) array of the vector's coordinates.
pyb::array_t<double> vec3_array(const Vec3& v);
/// A (P, 7) array of the poses, one write_pose7() row each.
pyb::array_t<double> poses_array(const std::vector<Pose>& poses);

/// Runs body(k) for k in [0, count) on `threads` threads (0: all cores), the GIL released.
/// Each k is independent; the results do not depend on the thread count. Raises
/// KeyboardInterrupt (after the current chunk of 8192) when Ctrl-C was pressed.
void parallel_for(std::size_t count, int threads, const std::function<void(std::size_t)>& body);

/// A new C-contiguous array of the given shape.
template <class T>
pyb::array_t<T> new_array(std::vector<pyb::ssize_t> shape) {
  return pyb::array_t<T>(shape);
}

void bind_mesh(pyb::module_& m);
void bind_query(pyb::module_& m);
void bind_plan(pyb::module_& m);
void bind_assembly(pyb::module_& m);

}  // namespace swept::py
