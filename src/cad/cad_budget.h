#pragma once
// Internal to the CAD reader module (src/cad/): how many triangles BRepMesh will make of a face,
// estimated before it runs (the CAD reader refuses a tessellation over
// ImportOptions::max_triangles), and the words of that refusal.
#include "swept/io/mesh_io.h"

#include <TopoDS_Face.hxx>

#include <string>

namespace swept::io_detail {

/// About how many triangles BRepMesh makes of `face` at chord `deflection` and angular
/// deflections `angle` (boundary) and `angle_interior`: of the right size, not a bound.
double face_triangles(const TopoDS_Face& face, double deflection, double angle, double angle_interior);

/// "12345", or "1.2e+07" from a million on.
std::string count_text(double n);
/// "deflection 0.1 mm".
std::string deflection_text(const ImportOptions& opt);
/// "the limit of N (max_triangles; on the command line --max-triangles): ...".
std::string budget_advice(const ImportOptions& opt);

}  // namespace swept::io_detail
