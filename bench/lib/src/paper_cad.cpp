// `swept bench paper`, the real CAD: Tables II and IV on meshes of ../shared/data.
#include "swept/bench/paper.h"

#include "swept/io/mesh_io.h"

#include <iostream>
#include <stdexcept>

namespace swept::bench {

namespace fs = std::filesystem;

namespace {

struct CadInput {
  const char* path;       ///< relative to the data directory
  double deflection;      ///< BRepMesh linear deflection (mm) for CAD formats; 0: the importer's default
  bool paper_only;
  const char* file_unit;  ///< unit of a mesh file's coordinates; "": the importer's default (mm)
};

constexpr CadInput kCad[] = {
    {"ros_industrial/kuka_kr10r1420_visual_base_link.stl", 0.0, false, "m"},  // the vendor's meshes are in metres
    {"tessellated/engine_d0.05/engine_p01_CylinderHead_rle_brep.stl", 0.0, false, ""},
    {"occt/motor.stl", 0.0, true, ""},
    {"nist/nist_ctc_04_asme1_rd.stp", 0.05, true, ""},
    {"occt/hammer.brep", 0.05, true, ""},
};

}  // namespace

void run_cad(const PaperOptions& o, bool paper, Results& res) {
  const fs::path data(o.data_dir);
  if (!fs::is_directory(data)) {
    res.notes.push_back("real CAD skipped: the data directory " + data.string() + " is absent");
    std::cerr << "bench paper: " << res.notes.back() << "\n";
    return;
  }
  for (const CadInput& c : kCad) {
    if (c.paper_only && !paper) continue;
    const fs::path file = data / c.path;
    if (!fs::exists(file)) {
      res.notes.push_back("real CAD " + file.string() + " skipped: absent");
      std::cerr << "bench paper: " << res.notes.back() << "\n";
      continue;
    }
    ImportOptions io;
    if (c.deflection > 0) io.linear_deflection = c.deflection;
    io.file_unit = c.file_unit;
    auto model = import_mesh(file, io);
    if (!model) throw std::runtime_error(model.error().message);
    const std::vector<Triangle> tris = model->merged().triangles;
    if (tris.empty()) throw std::runtime_error(file.string() + ": no triangles");
    std::string name = fs::path(c.path).filename().string();
    if (c.deflection > 0) name += " @" + fmt_g(c.deflection) + " mm";
    std::cerr << "bench paper: " << name << ": " << tris.size() << " triangles\n";
    res.meshes.push_back(measure_mesh(name, c.path, tris, o.runs));
  }
}

}  // namespace swept::bench
