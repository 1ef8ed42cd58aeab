// `swept bench paper`, the real CAD: Tables II and IV on meshes of ../shared/data.
#include "swept/bench/paper.h"

#include "swept/io/mesh_io.h"

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

std::size_t cad_steps(bool paper) {
  std::size_t n = 0;
  for (const CadInput& c : kCad) n += (!c.paper_only || paper) ? 1 : 0;
  return n;
}

void run_cad(const PaperOptions& o, bool paper, Results& res, PaperSteps& steps) {
  const fs::path data(o.data_dir);
  if (!fs::is_directory(data)) {
    res.notes.push_back("real CAD skipped: the data directory " + data.string() + " is absent");
    log_line(o, std::string("bench paper: ") + res.notes.back());
    for (std::size_t i = cad_steps(paper); i > 0; --i) steps.step("real CAD skipped");
    return;
  }
  for (const CadInput& c : kCad) {
    if (c.paper_only && !paper) continue;
    const fs::path file = data / c.path;
    if (!fs::exists(file)) {
      res.notes.push_back("real CAD " + file.string() + " skipped: absent");
      log_line(o, std::string("bench paper: ") + res.notes.back());
      steps.step(fs::path(c.path).filename().string());
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
    log_line(o, std::string("bench paper: ") + name + ": " + std::to_string(tris.size()) + " triangles");
    res.meshes.push_back(measure_mesh(name, c.path, tris, o.runs));
    steps.step(name);
  }
}

}  // namespace swept::bench
