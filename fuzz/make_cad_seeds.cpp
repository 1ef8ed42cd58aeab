// Writes the CAD seeds of the fuzz corpora with OpenCASCADE: a 10 mm box with a cylindrical
// boss (and the plain box) as OCCT BREP (fuzz/data/box.brep, corpus/fuzz_brep/), STEP AP214 (corpus/fuzz_step/) and
// IGES 5.3 with B-rep solids (corpus/fuzz_iges/). Built on demand only:
//   cmake --build build/fuzz --target fuzz_make_cad_seeds && build/fuzz/fuzz/fuzz_make_cad_seeds fuzz
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepTools.hxx>
#include <IGESControl_Controller.hxx>
#include <IGESControl_Writer.hxx>
#include <Interface_Static.hxx>
#include <STEPControl_Writer.hxx>
#include <gp_Ax2.hxx>

#include <cstdio>
#include <string>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s FUZZ_DIR\n", argv[0]);
    return 1;
  }
  const std::string dir = argv[1];
  const TopoDS_Shape box = BRepPrimAPI_MakeBox(10.0, 10.0, 10.0).Shape();
  const TopoDS_Shape boss = BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(5, 5, 10), gp_Dir(0, 0, 1)), 2.0, 3.0).Shape();
  const TopoDS_Shape part = BRepAlgoAPI_Fuse(box, boss).Shape();

  bool ok = BRepTools::Write(part, (dir + "/corpus/fuzz_brep/box_boss.brep").c_str()) &&
            BRepTools::Write(box, (dir + "/data/box.brep").c_str());

  STEPControl_Writer step;
  Interface_Static::SetCVal("write.step.schema", "AP214IS");
  Interface_Static::SetCVal("write.step.unit", "MM");
  ok = ok && step.Transfer(part, STEPControl_AsIs) == IFSelect_RetDone &&
       step.Write((dir + "/corpus/fuzz_step/box_boss.step").c_str()) == IFSelect_RetDone;
  STEPControl_Writer step_box;  // the plain box: fewer entities, faster mutations
  ok = ok && step_box.Transfer(box, STEPControl_AsIs) == IFSelect_RetDone &&
       step_box.Write((dir + "/corpus/fuzz_step/box.step").c_str()) == IFSelect_RetDone;

  IGESControl_Controller::Init();
  IGESControl_Writer iges("MM", 1);  // mode 1: B-rep solids (type 186), not trimmed surfaces
  ok = ok && iges.AddShape(part);
  iges.ComputeModel();
  ok = ok && iges.Write((dir + "/corpus/fuzz_iges/box_boss.iges").c_str());
  IGESControl_Writer faces("MM", 0);  // mode 0: faces (trimmed surfaces, type 144)
  ok = ok && faces.AddShape(box);
  faces.ComputeModel();
  ok = ok && faces.Write((dir + "/corpus/fuzz_iges/box_faces.iges").c_str());
  if (!ok) std::fprintf(stderr, "fuzz_make_cad_seeds: a writer failed\n");
  return ok ? 0 : 1;
}
