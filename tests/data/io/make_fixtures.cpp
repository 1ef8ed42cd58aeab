// Generates the CAD fixtures in this folder with OpenCASCADE (run once; the outputs are committed
// because the test executable links swept only and sees no OCCT headers):
//   g++ -std=c++20 make_fixtures.cpp -I/usr/include/opencascade -lTKernel -lTKMath -lTKBRep \
//     -lTKTopAlgo -lTKPrim -lTKXSBase -lTKSTEP -lTKIGES -lTKXCAF -lTKLCAF -lTKXDESTEP -lTKCAF \
//     -lTKG3d -lTKGeomBase -o make_fixtures && ./make_fixtures
// box.brep, box_mm.step, box_inch.step, box.igs: a 10 x 20 x 30 mm box with a corner at the
// origin. assembly.step: assembly "pair" holding two instances of part "block" (the same box),
// one translated by (100, 0, 0) mm, one rotated 90 degrees about z and translated by (0, 50, 0) mm.
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepTools.hxx>
#include <IGESControl_Controller.hxx>
#include <IGESControl_Writer.hxx>
#include <Interface_Static.hxx>
#include <STEPCAFControl_Writer.hxx>
#include <STEPControl_Writer.hxx>
#include <TDataStd_Name.hxx>
#include <TDocStd_Document.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>
#include <gp_Ax1.hxx>
#include <gp_Trsf.hxx>

#include <cmath>
#include <cstdio>

int main() {
  const TopoDS_Shape box = BRepPrimAPI_MakeBox(10.0, 20.0, 30.0).Shape();
  if (!BRepTools::Write(box, "box.brep")) return 1;

  for (const char* unit : {"MM", "INCH"}) {
    Interface_Static::SetCVal("write.step.unit", unit);
    STEPControl_Writer writer;
    if (writer.Transfer(box, STEPControl_AsIs) != IFSelect_RetDone) return 2;
    if (writer.Write(std::string(unit) == "MM" ? "box_mm.step" : "box_inch.step") != IFSelect_RetDone) return 3;
  }
  Interface_Static::SetCVal("write.step.unit", "MM");

  IGESControl_Controller::Init();
  IGESControl_Writer iges("MM", 1);
  iges.AddShape(box);
  iges.ComputeModel();
  if (!iges.Write("box.igs")) return 4;

  Handle(TDocStd_Document) doc = new TDocStd_Document("XmlXCAF");
  Handle(XCAFDoc_ShapeTool) tool = XCAFDoc_DocumentTool::ShapeTool(doc->Main());
  const TDF_Label part = tool->AddShape(box, false);
  TDataStd_Name::Set(part, "block");
  const TDF_Label assembly = tool->NewShape();
  TDataStd_Name::Set(assembly, "pair");
  gp_Trsf a;
  a.SetTranslation(gp_Vec(100.0, 0.0, 0.0));
  gp_Trsf rot;
  rot.SetRotation(gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), M_PI / 2);
  gp_Trsf shift;
  shift.SetTranslation(gp_Vec(0.0, 50.0, 0.0));
  tool->AddComponent(assembly, part, TopLoc_Location(a));
  tool->AddComponent(assembly, part, TopLoc_Location(shift * rot));
  tool->UpdateAssemblies();
  STEPCAFControl_Writer cafwriter;
  if (!cafwriter.Transfer(doc, STEPControl_AsIs)) return 5;
  if (cafwriter.Write("assembly.step") != IFSelect_RetDone) return 6;
  std::puts("fixtures written");
  return 0;
}
