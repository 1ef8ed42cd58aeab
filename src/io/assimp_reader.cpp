// OBJ, PLY, glTF/GLB and COLLADA through assimp (STL and OFF too, for ompl_app_center alone).
// Post-processing is limited to validating the scene and triangulating polygons so the soup
// stays as the file has it (no degenerate removal, no vertex merging). The files are checked by format_checks.cpp first.
#include "format_checks.h"
#include "import_detail.h"

#include <assimp/DefaultIOSystem.h>
#include <assimp/Importer.hpp>
#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <new>
#include <optional>
#include <string_view>

namespace swept::io_detail {

namespace {

using Affine = Eigen::Matrix<double, 3, 4>;

Affine to_affine(const aiMatrix4x4& m) {
  Affine a;
  a << m.a1, m.a2, m.a3, m.a4, m.b1, m.b2, m.b3, m.b4, m.c1, m.c2, m.c3, m.c4;
  return a;
}

Affine compose(const Affine& parent, const Affine& child) {
  Affine out;
  out.leftCols<3>() = parent.leftCols<3>() * child.leftCols<3>();
  out.col(3) = parent.leftCols<3>() * child.col(3) + parent.col(3);
  return out;
}

// Appends the triangles of `node` and its children, in the file's frame scaled to the output
// unit. "" on success, else the reason: every face index is checked against the mesh's vertex
// count here too (not only by ValidateDataStructure), since reading past mVertices is a crash.
std::string collect(const aiScene& scene, const aiNode& node, const Affine& parent, double scale,
                    const std::string& stem, std::vector<TriangleSoup>& parts) {
  const Affine world = compose(parent, to_affine(node.mTransformation));
  for (unsigned m = 0; m < node.mNumMeshes; ++m) {
    if (node.mMeshes[m] >= scene.mNumMeshes)
      return "node '" + std::string(node.mName.C_Str()) + "' refers to mesh " + std::to_string(node.mMeshes[m]) +
             " of " + std::to_string(scene.mNumMeshes);
    const aiMesh& mesh = *scene.mMeshes[node.mMeshes[m]];
    TriangleSoup soup;
    soup.name = mesh.mName.length > 0 ? std::string(mesh.mName.C_Str())
                : node.mName.length > 0 ? std::string(node.mName.C_Str())
                                        : stem;
    soup.triangles.reserve(mesh.mNumFaces);
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const aiFace& face = mesh.mFaces[f];
      if (face.mNumIndices != 3) continue;  // points and lines are not surface
      Triangle t;
      for (int v = 0; v < 3; ++v) {
        const unsigned index = face.mIndices[v];
        if (index >= mesh.mNumVertices || mesh.mVertices == nullptr)
          return "mesh '" + soup.name + "' face " + std::to_string(f) + " refers to vertex " + std::to_string(index) +
                 " but the mesh has " + std::to_string(mesh.mNumVertices) + " vertices";
        const aiVector3D& a = mesh.mVertices[index];
        const Vec3 p(a.x, a.y, a.z);
        t[v] = scale * (world.leftCols<3>() * p + world.col(3));
      }
      soup.triangles.push_back(t);
    }
    parts.push_back(std::move(soup));
  }
  for (unsigned c = 0; c < node.mNumChildren; ++c)
    if (std::string err = collect(scene, *node.mChildren[c], world, scale, stem, parts); !err.empty()) return err;
  return {};
}

}  // namespace

namespace {

// assimp's glTF 2 importer drops a face whose index is past the vertex list, with only a log
// message (and fails only when no face is left): compare what each primitive declares with
// what assimp kept. assimp makes one mesh per primitive, named like the glTF mesh ("name-k" for
// primitive k of several), but orders them as the scene first refers to them, not as the file
// lists them, and reads no mesh that no node uses (Khronos' 2CylinderEngine sample has both). So
// each of assimp's meshes is matched with a declared primitive of the same vertex count and
// name (an unnamed one matches any name): one with as many faces when there is one, else one
// with more, which is the error. "" when every mesh matched one with as many faces or matched
// none (the mapping is unknown: no error is made up). `warnings` gets the matched TRIANGLES
// primitives whose count leaves indices past the last whole triangle.
std::string check_gltf_faces(const std::string& bytes, bool binary, const aiScene& scene,
                             std::vector<std::string>& warnings) {
  const std::vector<GltfPrimitive> declared = gltf_declared_faces(bytes, binary);
  std::vector<bool> matched(declared.size(), false);
  auto label = [](const GltfPrimitive& p) {
    return "mesh '" + p.mesh + "' (primitive " + std::to_string(p.primitive) + ")";
  };
  for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
    const aiMesh& mesh = *scene.mMeshes[m];
    const std::string_view name(mesh.mName.C_Str());
    std::optional<std::size_t> same, more;
    for (std::size_t i = 0; i < declared.size() && !same; ++i) {
      const GltfPrimitive& p = declared[i];
      if (matched[i] || p.vertices != mesh.mNumVertices) continue;
      if (!p.mesh.empty() && name != (p.primitives > 1 ? p.mesh + "-" + std::to_string(p.primitive) : p.mesh))
        continue;
      if (p.faces == mesh.mNumFaces)
        same = i;
      else if (p.faces > mesh.mNumFaces && !more)
        more = i;
    }
    if (same) {
      matched[*same] = true;
      const GltfPrimitive& p = declared[*same];
      if (p.leftover > 0)
        warnings.push_back(label(p) + ": TRIANGLES with " + std::to_string(3 * p.faces + p.leftover) +
                           " indices (or vertices), not a multiple of 3: the last " + std::to_string(p.leftover) +
                           " make no triangle and are left out");
    } else if (more) {
      const GltfPrimitive& p = declared[*more];
      return label(p) + ": " + std::to_string(p.faces - mesh.mNumFaces) + " of its " + std::to_string(p.faces) +
             " faces refer to vertices past its " + std::to_string(p.vertices) + " vertices";
    }
  }
  return {};
}

// assimp's messages may span lines; ours are one line each.
std::string one_line(std::string text) {
  for (char& c : text)
    if (c == '\n' || c == '\r') c = ' ';
  while (!text.empty() && text.back() == ' ') text.pop_back();
  return text;
}

// Every vertex of every mesh under `node` (all of them, as OMPL.app's scene::extractVertices
// does: points and lines too), node transformations applied: their sum, count and box.
void gather_vertices(const aiScene& scene, const aiNode& node, const Affine& parent, Vec3& sum, std::size_t& count,
                     Aabb& box) {
  const Affine world = compose(parent, to_affine(node.mTransformation));
  for (unsigned m = 0; m < node.mNumMeshes; ++m) {
    if (node.mMeshes[m] >= scene.mNumMeshes) continue;  // ValidateDataStructure rejects these first
    const aiMesh& mesh = *scene.mMeshes[node.mMeshes[m]];
    for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
      const aiVector3D& a = mesh.mVertices[v];
      const Vec3 placed = world.leftCols<3>() * Vec3(a.x, a.y, a.z) + world.col(3);
      sum += placed;
      box.extend(placed);
      ++count;
    }
  }
  for (unsigned c = 0; c < node.mNumChildren; ++c) gather_vertices(scene, *node.mChildren[c], world, sum, count, box);
}

}  // namespace

namespace {

// assimp follows a model's external references (glTF buffer and image uris, OBJ mtllib, COLLADA
// images) to any path, so a model could make us read any file on the machine. This file system
// opens, for reading only, the model itself and files in its folder or below; anything else (an
// absolute path elsewhere, a "../" escaping the folder, a URL such as http://) is refused and
// remembered, never opened. glTF's data: uris are decoded by assimp without opening a file.
class ModelFolderIOSystem : public Assimp::DefaultIOSystem {
 public:
  explicit ModelFolderIOSystem(const std::filesystem::path& model) {
    // The folder the model is named in (a symbolic link to the model does not move it), resolved
    // as every requested path is, so that "a/./b" and "a/x/../b" compare equal.
    std::error_code ec;
    model_ = std::filesystem::weakly_canonical(model, ec);
    folder_ = std::filesystem::weakly_canonical(std::filesystem::absolute(model, ec).parent_path(), ec);
  }
  bool Exists(const char* file) const override {
    if (allowed(file)) return DefaultIOSystem::Exists(file);
    refuse(file);
    return false;
  }
  Assimp::IOStream* Open(const char* file, const char* mode = "rb") override {
    if (!allowed(file) || std::string_view(mode).find_first_of("wa+") != std::string_view::npos) {
      refuse(file);
      return nullptr;
    }
    return DefaultIOSystem::Open(file, mode);
  }
  /// The references refused, as assimp asked for them (joined to the model's folder if relative).
  mutable std::vector<std::string> refused;

 private:
  bool allowed(const char* file) const {
    const std::string_view name(file);
    if (name.find("://") != std::string_view::npos) return false;  // a URL: never fetched
    std::error_code ec;
    const std::filesystem::path p = std::filesystem::weakly_canonical(std::filesystem::path(name), ec);
    if (ec) return false;
    if (p == model_) return true;
    // Inside the folder: the folder is a prefix of the path, component by component.
    auto [f, q] = std::mismatch(folder_.begin(), folder_.end(), p.begin(), p.end());
    return f == folder_.end() && q != p.end();
  }
  void refuse(const char* file) const {
    if (std::find(refused.begin(), refused.end(), file) == refused.end()) refused.emplace_back(file);
  }
  std::filesystem::path model_, folder_;
};

// "" when nothing was refused; else the message naming the references.
std::string refused_references(const ModelFolderIOSystem& io) {
  std::string out;
  for (const std::string& r : io.refused) out += (out.empty() ? "'" : ", '") + r + "'";
  return out;
}

}  // namespace

Result<bool> read_with_assimp(const ReadContext& ctx, std::vector<TriangleSoup>& parts) {
  if (auto err = precheck(ctx)) return *err;
  try {
    // COLLADA's <up_axis> is honoured as assimp does by default, and so as OMPL.app does: a Z_UP
    // file's (x, y, z) reads as (x, z, -y), an X_UP file's as (-y, x, z) (ColladaLoader
    // multiplies the root node's transformation by that rotation after the <unit> scale).
    Assimp::Importer importer;
    auto* io = new ModelFolderIOSystem(ctx.file);  // owned by the importer
    importer.SetIOHandler(io);
    // ValidateDataStructure rejects face indices past the vertex list (and other broken scenes)
    // before any other step reads them.
    const aiScene* scene = importer.ReadFile(ctx.file.string(), aiProcess_ValidateDataStructure | aiProcess_Triangulate);
    const std::string refused = refused_references(*io);
    if (scene == nullptr && !refused.empty())
      return file_error(ctx.display, "refers to " + refused +
                                         " outside the model's folder (external files must be in its folder or below)");
    if (scene == nullptr) return file_error(ctx.display, "assimp: " + one_line(importer.GetErrorString()));
    // The geometry did not need them (e.g. an OBJ's mtllib: materials only): read without them.
    if (!refused.empty() && ctx.warnings != nullptr)
      ctx.warnings->push_back(ctx.display + ": " + refused + " outside the model's folder not read (materials skipped)");
    if (scene->mRootNode == nullptr) return file_error(ctx.display, "assimp: the file has no scene graph");
    const std::string ext = lower(ctx.file.extension().string());
    if (ext == ".gltf" || ext == ".glb") {
      Result<std::string> bytes = read_file_bytes(ctx.file, ctx.display);
      if (!bytes) return bytes.error();
      std::vector<std::string> notes;
      if (std::string err = check_gltf_faces(*bytes, ext == ".glb", *scene, notes); !err.empty())
        return file_error(ctx.display, err);
      if (ctx.warnings != nullptr)
        for (const std::string& note : notes) ctx.warnings->push_back(ctx.display + ": " + note);
    }
    const std::string stem = ctx.file.stem().string();
    if (std::string err = collect(*scene, *scene->mRootNode, Affine::Identity(), ctx.file_to_output, stem, parts);
        !err.empty())
      return file_error(ctx.display, err);
  } catch (const std::bad_alloc&) {
    return file_error(ctx.display, "assimp: out of memory: the file declares more data than fits in memory");
  } catch (const std::exception& e) {
    return file_error(ctx.display, "assimp: " + one_line(e.what()));
  }
  return true;
}

Result<OmplAppVertices> ompl_app_vertices_with_assimp(const ReadContext& ctx) {
  if (auto err = precheck(ctx)) return *err;
  try {
    // OMPL.app's RigidBodyGeometry::addRobotMesh reads with exactly these steps (plus the
    // validation, which changes no vertex). assimp runs them in its own fixed order, whatever the
    // order of the flags: OptimizeGraph, Triangulate, SortByPType, GenFaceNormals, then
    // JoinIdenticalVertices, which joins vertices whose position *and* normal agree.
    Assimp::Importer importer;
    auto* io = new ModelFolderIOSystem(ctx.file);  // owned by the importer
    importer.SetIOHandler(io);
    const aiScene* scene = importer.ReadFile(
        ctx.file.string(), aiProcess_ValidateDataStructure | aiProcess_GenNormals | aiProcess_Triangulate |
                               aiProcess_JoinIdenticalVertices | aiProcess_SortByPType | aiProcess_OptimizeGraph);
    if (scene == nullptr && !io->refused.empty())
      return file_error(ctx.display, "refers to " + refused_references(*io) +
                                         " outside the model's folder (external files must be in its folder or below)");
    if (scene == nullptr) return file_error(ctx.display, "assimp: " + one_line(importer.GetErrorString()));
    if (scene->mRootNode == nullptr) return file_error(ctx.display, "assimp: the file has no scene graph");
    Vec3 sum = Vec3::Zero();
    std::size_t count = 0;
    Aabb box;
    gather_vertices(*scene, *scene->mRootNode, Affine::Identity(), sum, count, box);
    if (count == 0) return file_error(ctx.display, "contains no vertices");
    // Never a NaN centre (assimp's BoxWithInfinites sample gave one).
    if (!box.min.allFinite() || !box.max.allFinite() || sum.hasNaN())
      return file_error(ctx.display, "a vertex has a non-finite coordinate");
    if (!sum.allFinite()) return file_error(ctx.display, "vertex coordinates too large to average (their sum overflows)");
    // file_to_output is a positive scale: the box's corners scale with it.
    return OmplAppVertices{Vec3(ctx.file_to_output * sum / static_cast<double>(count)),
                           Aabb{ctx.file_to_output * box.min, ctx.file_to_output * box.max}};
  } catch (const std::exception& e) {
    return file_error(ctx.display, "assimp: " + one_line(e.what()));
  }
}

}  // namespace swept::io_detail
