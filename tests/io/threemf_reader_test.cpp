// swept's 3MF reader: the model's unit, build items and component transforms (3MF's row-vector
// convention, worked out by hand below), the production extension's model parts, and errors that
// name the package, the part and the line. The packages are written by the test with minizip.
#include "import_test_util.h"
#include "support/test_support.h"

#include "swept/io/mesh_io.h"

#include <gtest/gtest.h>
#include <minizip/zip.h>

#include <map>
#include <string>

namespace swept::test {
namespace {

namespace fs = std::filesystem;

const std::string kRels =
    R"(<?xml version="1.0" encoding="UTF-8"?>
<Relationships xmlns="http://schemas.openxmlformats.org/package/2006/relationships">
 <Relationship Target="/3D/3dmodel.model" Id="rel0" Type="http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel"/>
</Relationships>
)";

fs::path write_3mf(const fs::path& file, const std::map<std::string, std::string>& entries) {
  zipFile zip = zipOpen64(file.c_str(), APPEND_STATUS_CREATE);
  EXPECT_NE(zip, nullptr);
  for (const auto& [name, text] : entries) {
    zip_fileinfo info{};
    EXPECT_EQ(zipOpenNewFileInZip64(zip, name.c_str(), &info, nullptr, 0, nullptr, 0, nullptr, Z_DEFLATED, 6, 0), ZIP_OK);
    EXPECT_EQ(zipWriteInFileInZip(zip, text.data(), static_cast<unsigned>(text.size())), ZIP_OK);
    EXPECT_EQ(zipCloseFileInZip(zip), ZIP_OK);
  }
  EXPECT_EQ(zipClose(zip, nullptr), ZIP_OK);
  return file;
}

std::string model(const std::string& attributes, const std::string& resources, const std::string& build) {
  return R"(<?xml version="1.0" encoding="UTF-8"?>
<model xmlns="http://schemas.microsoft.com/3dmanufacturing/core/2015/02"
       xmlns:p="http://schemas.microsoft.com/3dmanufacturing/production/2015/06" )" +
         attributes + ">\n<resources>\n" + resources + "</resources>\n<build>\n" + build + "</build>\n</model>\n";
}

// A right triangle with legs of 1 along x and y, as object `id`.
std::string triangle_object(int id, const std::string& name = "") {
  return "<object id=\"" + std::to_string(id) + "\" type=\"model\"" + (name.empty() ? "" : " name=\"" + name + "\"") +
         "><mesh><vertices>\n<vertex x=\"0\" y=\"0\" z=\"0\"/>\n<vertex x=\"1\" y=\"0\" z=\"0\"/>\n"
         "<vertex x=\"0\" y=\"1\" z=\"0\"/>\n</vertices><triangles>\n<triangle v1=\"0\" v2=\"1\" v3=\"2\"/>\n"
         "</triangles></mesh></object>\n";
}

void expect_vertices(const Triangle& t, const Vec3& p, const Vec3& q, const Vec3& r) {
  EXPECT_TRUE(t.p.isApprox(p, 1e-15) || (t.p - p).norm() < 1e-15) << t.p.transpose() << " vs " << p.transpose();
  EXPECT_TRUE(t.q.isApprox(q, 1e-15) || (t.q - q).norm() < 1e-15) << t.q.transpose() << " vs " << q.transpose();
  EXPECT_TRUE(t.r.isApprox(r, 1e-15) || (t.r - r).norm() < 1e-15) << t.r.transpose() << " vs " << r.transpose();
}

TEST(ThreeMfReader, TheModelsUnitScalesIt) {
  const auto dir = scratch_dir();
  for (const auto& [unit, mm] : std::map<std::string, double>{
           {"micron", 1e-3}, {"millimeter", 1.0}, {"centimeter", 10.0}, {"inch", 25.4}, {"foot", 304.8}, {"meter", 1000.0}}) {
    const auto file = write_3mf(dir / (unit + ".3mf"), {{"_rels/.rels", kRels},
                                                        {"3D/3dmodel.model", model("unit=\"" + unit + "\"", triangle_object(1),
                                                                                   "<item objectid=\"1\"/>\n")}});
    const auto m = import_mesh(file);
    ASSERT_TRUE(m.ok()) << m.error().message;
    ASSERT_EQ(m->triangle_count(), 1u);
    expect_vertices(m->merged().triangles[0], Vec3::Zero(), Vec3(mm, 0, 0), Vec3(0, mm, 0));
  }
  // No unit attribute: millimetres (the specification's default); output in metres.
  ImportOptions in_m;
  in_m.unit = "m";
  const auto plain = import_mesh(
      write_3mf(dir / "default.3mf", {{"3D/3dmodel.model", model("", triangle_object(1), "<item objectid=\"1\"/>\n")}}), in_m);
  ASSERT_TRUE(plain.ok()) << plain.error().message;
  expect_vertices(plain->merged().triangles[0], Vec3::Zero(), Vec3(1e-3, 0, 0), Vec3(0, 1e-3, 0));

  // A file unit given for it must agree with the declared one.
  const auto inches = dir / "inch.3mf";
  ImportOptions says_mm;
  says_mm.file_unit = "mm";
  expect_error(import_mesh(inches, says_mm), {inches.string(), "declares unit 'inch'", "'mm'"});
  ImportOptions says_in;
  says_in.file_unit = "in";
  EXPECT_TRUE(import_mesh(inches, says_in).ok());
}

// Component and item transforms, 3MF's row-vector convention: x' = m00 x + m10 y + m20 z + m30.
TEST(ThreeMfReader, ItemsAndComponentsPlaceTheirObjects) {
  const auto dir = scratch_dir();
  // Object 2: object 1 moved by (10, 0, 0), and object 1 turned a quarter about z (x' = −y,
  // y' = x: m00 = 0, m01 = 1, m10 = −1, m11 = 0). The build moves object 2 up by 5.
  const std::string resources = triangle_object(1) +
                                "<object id=\"2\" name=\"pair\"><components>\n"
                                "<component objectid=\"1\" transform=\"1 0 0 0 1 0 0 0 1 10 0 0\"/>\n"
                                "<component objectid=\"1\" transform=\"0 1 0 -1 0 0 0 0 1 0 0 0\"/>\n"
                                "</components></object>\n";
  const auto file = write_3mf(dir / "placed.3mf",
                              {{"_rels/.rels", kRels},
                               {"3D/3dmodel.model", model("unit=\"millimeter\"", resources,
                                                          "<item objectid=\"2\" transform=\"1 0 0 0 1 0 0 0 1 0 0 5\"/>\n"
                                                          "<item objectid=\"1\"/>\n")}});
  const auto m = import_mesh(file);
  ASSERT_TRUE(m.ok()) << m.error().message;
  ASSERT_EQ(m->parts.size(), 2u);
  EXPECT_EQ(m->parts[0].name, "pair");
  EXPECT_EQ(m->parts[1].name, "object 1");
  ASSERT_EQ(m->parts[0].triangles.size(), 2u);
  expect_vertices(m->parts[0].triangles[0], {10, 0, 5}, {11, 0, 5}, {10, 1, 5});
  expect_vertices(m->parts[0].triangles[1], {0, 0, 5}, {0, 1, 5}, {-1, 0, 5});
  expect_vertices(m->parts[1].triangles.at(0), {0, 0, 0}, {1, 0, 0}, {0, 1, 0});
}

// Slicers write each object to its own model part (the production extension's p:path); the root
// names its model part through the package's relationships.
TEST(ThreeMfReader, ModelPartsOfTheProductionExtension) {
  const auto dir = scratch_dir();
  std::string rels = kRels;
  rels.replace(rels.find("/3D/3dmodel.model"), 17, "/3D/root.model");
  const std::string root = model("unit=\"centimeter\"",
                                 "<object id=\"7\" name=\"part\"><components>\n"
                                 "<component p:path=\"/3D/Objects/object_1.model\" objectid=\"3\" "
                                 "transform=\"1 0 0 0 1 0 0 0 1 0 0 1\"/>\n</components></object>\n",
                                 "<item objectid=\"7\"/>\n");
  const auto file = write_3mf(dir / "parts.3mf", {{"_rels/.rels", rels},
                                                  {"3D/root.model", root},
                                                  {"3D/Objects/object_1.model", model("unit=\"centimeter\"", triangle_object(3), "")}});
  const auto m = import_mesh(file);
  ASSERT_TRUE(m.ok()) << m.error().message;
  ASSERT_EQ(m->triangle_count(), 1u);
  expect_vertices(m->merged().triangles[0], {0, 0, 10}, {10, 0, 10}, {0, 10, 10});

  const auto mixed = write_3mf(dir / "mixed.3mf", {{"_rels/.rels", rels},
                                                   {"3D/root.model", root},
                                                   {"3D/Objects/object_1.model", model("unit=\"inch\"", triangle_object(3), "")}});
  expect_error(import_mesh(mixed), {mixed.string(), "3D/Objects/object_1.model", "unit 'inch' differs", "'centimeter'"});
}

TEST(ThreeMfReader, ErrorsNameThePackagePartAndLine) {
  const auto dir = scratch_dir();
  auto check = [&](const std::string& name, const std::map<std::string, std::string>& entries,
                   std::initializer_list<std::string> parts) { expect_import_error(write_3mf(dir / name, entries), parts); };
  const std::string item = "<item objectid=\"1\"/>\n";
  check("no_model.3mf", {{"_rels/.rels", kRels}}, {"no part '3D/3dmodel.model'"});
  check("bad_xml.3mf", {{"3D/3dmodel.model", "<model><resources></model>"}}, {"3D/3dmodel.model", "line 1", "not well-formed XML"});
  std::string bad_index = triangle_object(1);
  bad_index.replace(bad_index.find("v3=\"2\""), 6, "v3=\"3\"");
  check("bad_index.3mf", {{"3D/3dmodel.model", model("", bad_index, item)}},
        {"3D/3dmodel.model", "line 10", "object 1 triangle 0 refers to vertex 3 of 3"});
  std::string bad_number = triangle_object(1);
  bad_number.replace(bad_number.find("x=\"1\""), 5, "x=\"1,5\"");
  check("bad_number.3mf", {{"3D/3dmodel.model", model("", bad_number, item)}},
        {"line 7", "malformed number '1,5'", "object 1, vertex 1"});
  check("bad_unit.3mf", {{"3D/3dmodel.model", model("unit=\"furlong\"", triangle_object(1), item)}}, {"unknown unit 'furlong'"});
  check("no_items.3mf", {{"3D/3dmodel.model", model("", triangle_object(1), "")}}, {"the build holds no items"});
  check("missing.3mf", {{"3D/3dmodel.model", model("", triangle_object(1), "<item objectid=\"4\"/>\n")}},
        {"refers to object 4, which 3D/3dmodel.model does not define"});
  check("cycle.3mf",
        {{"3D/3dmodel.model", model("", "<object id=\"1\"><components><component objectid=\"1\"/></components></object>\n", item)}},
        {"nest deeper than 32 levels"});
  check("bad_transform.3mf",
        {{"3D/3dmodel.model", model("", triangle_object(1), "<item objectid=\"1\" transform=\"1 0 0 1\"/>\n")}},
        {"a transform needs 12 numbers, found 4"});
  // Ten levels of two components each place 2^10 copies of the triangle: past a limit of 1000.
  std::string doubling = triangle_object(1);
  for (int id = 2; id <= 11; ++id)
    doubling += "<object id=\"" + std::to_string(id) + "\"><components><component objectid=\"" + std::to_string(id - 1) +
                "\"/><component objectid=\"" + std::to_string(id - 1) + "\"/></components></object>\n";
  const auto doubled = write_3mf(dir / "doubling.3mf", {{"3D/3dmodel.model", model("", doubling, "<item objectid=\"11\"/>\n")}});
  ImportOptions small;
  small.max_triangles = 1000;
  expect_error(import_mesh(doubled, small), {doubled.string(), "places more than 1000 triangles", "--max-triangles"});
  small.max_triangles = 1024;
  const auto all = import_mesh(doubled, small);
  ASSERT_TRUE(all.ok()) << all.error().message;
  EXPECT_EQ(all->triangle_count(), 1024u);
  const auto text = write_file(dir / "text.3mf", "solid x\nendsolid x\n");
  expect_error(import_mesh(text), {text.string(), "not a 3MF package"});
}

}  // namespace
}  // namespace swept::test
