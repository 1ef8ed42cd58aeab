#pragma once
/// Mesh and CAD import into triangle soups (double precision), one soup per part.
///
/// STL (ASCII/binary), OFF and 3MF are read by swept itself in double precision; OBJ, PLY,
/// glTF/GLB and COLLADA with assimp (single precision); CAD (STEP, IGES, OCCT .brep) with OpenCASCADE, tessellated by BRepMesh,
/// assembly placements applied. Bad input gives an Error naming the file and the line, triangle or entity.
#include "swept/geometry/result.h"
#include "swept/geometry/types.h"

#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace swept {

/// Length units understood by the importer, with their size in metres.
/// Accepted spellings: "m", "cm", "mm", "um", "in", "ft".
/// Returns false for anything else.
bool unit_scale(std::string_view unit, double& metres_per_unit);

/// Reported while a CAD file is read (ImportOptions::progress).
struct ImportProgress {
  const char* phase = "";  ///< "shapes" (the file's entities to shapes), "meshing" (BRepMesh over the faces)
  double fraction = 0.0;   ///< of the phase, 0 to 1
};

/// How to import: output unit, the file's unit where it has none, tessellation of CAD.
struct ImportOptions {
  /// Unit of the output coordinates.
  std::string unit = "mm";
  /// Unit of the file's coordinates. Empty: "mm" for STL, OBJ, PLY, OFF and .brep; "m" for
  /// glTF/GLB (its spec) and COLLADA (assimp applies the file's <unit>, and its <up_axis> as
  /// assimp and OMPL.app do by default: Z_UP (x, y, z) reads as (x, z, -y)). Ignored for STEP and
  /// IGES, which declare their unit (e.g. inch) and are converted from it. A 3MF model declares its
  /// unit (millimeter when it does not say): a file unit given for it must be the same.
  std::string file_unit;
  /// BRepMesh linear deflection (max chord distance to the surface) in the *output* unit;
  /// CAD formats only, must be > 0.
  double linear_deflection = 0.1;
  /// BRepMesh angular deflection in radians; CAD formats only, must be > 0.
  double angular_deflection = 0.5;
  /// Most triangles a CAD tessellation may make (over every instance of every part). The count
  /// is estimated from each face's curvature and size and the deflections before BRepMesh runs,
  /// and counted again as the triangles are collected; past it the import is an error naming
  /// this limit, instead of meshing until memory runs out (a tiny deflection on a curved part).
  /// CAD formats only, must be > 0. BRepMesh peaks at about 1 KB per triangle while meshing
  /// (measured, OCCT 7.6), the soup keeps 72 bytes: 5 million triangles peak near 5 GB. It also
  /// bounds the triangles a 3MF build places (its components may repeat an object many times).
  std::size_t max_triangles = 5'000'000;
  /// Run the third-party readers (assimp, OpenCASCADE) in a child process, so that a crash, a
  /// failed assert, a hang or a leak of theirs on a malformed file becomes an Error naming the
  /// file instead of ending the caller (fuzzing found such files for both). CAD then meshes on
  /// one thread. Off: in this process, with BRepMesh in parallel.
  bool isolate_readers = true;
  /// Seconds a reader may take in its child process before it is stopped (an Error).
  double reader_timeout = 600.0;
  /// Bytes a reader may allocate in its child process (its address space past what it inherits,
  /// RLIMIT_AS); past it, or within a tenth of it (where BRepMesh catches failed allocations and
  /// leaves faces out), the read fails with an Error saying so, instead of the machine running out
  /// of memory (BRepMesh took 12 GB in two minutes on OCCT's sample terrain.brep at deflection
  /// 0.1 mm). 0: the environment's SWEPT_READER_MEMORY (gigabytes) if set, else three quarters of
  /// the physical memory. Not applied in AddressSanitizer builds.
  std::size_t reader_memory = 0;
  /// Called as a STEP, IGES or BREP read advances (OpenCASCADE's progress, at most about a
  /// hundred times a phase), one call at a time. With `isolate_readers` it runs in the reader's
  /// child process: it may draw on the terminal, but what it changes stays in the child. Not
  /// called for mesh formats, or when empty.
  std::function<void(const ImportProgress&)> progress;
};

/// What an import produced.
struct ImportedModel {
  std::string file;                  ///< the path as given
  std::string unit;                  ///< unit of the coordinates (ImportOptions::unit)
  std::vector<TriangleSoup> parts;   ///< one per part/solid/mesh, with its name
  /// Triangles kept in the parts although degenerate: shape_quality() ≤ 1e-12 (zero area,
  /// repeated or collinear vertices, up to rounding).
  std::size_t degenerate_triangles = 0;
  /// Non-fatal problems (e.g. CAD faces BRepMesh could not tessellate, left out), each naming the file.
  std::vector<std::string> warnings;

  /// Total number of triangles over all parts.
  std::size_t triangle_count() const;
  /// All parts in one soup (the file's stem as its name).
  TriangleSoup merged() const;
};

/// Reads a mesh or CAD file; the format is chosen from the extension (case-insensitive):
/// .stl → swept's own reader (ASCII and binary, double precision, exact line/triangle errors);
/// .off → swept's own reader (Geomview's header variants, polygons of any size by ear clipping);
/// .3mf → swept's own reader (minizip and expat: the core specification, build items and
/// components placed, the production extension's model parts; one part per build item);
/// .obj .ply .gltf .glb .dae → assimp (aiProcess_ValidateDataStructure and
/// aiProcess_Triangulate only: degenerate triangles and duplicate vertices are kept);
/// .step .stp .iges .igs .brep → OpenCASCADE (XCAF for assembly placements and names; BRepMesh in
/// parallel, deterministic). Part names: STL solid names, 3MF object names ("object <id>" for an
/// unnamed one), assimp mesh/node names, STEP/IGES
/// product names, "<stem>_solid<k>" for .brep solids; repeated names get "#2", "#3", ... in file
/// order. Parts without triangles are dropped, each named in a warning (unless the file holds
/// nothing else: then it is an error).
///
/// Errors (never exceptions), each one line starting with the file as given: unknown output/file
/// unit (with the accepted list), unknown extension, missing file, empty file, a binary STL whose
/// size is not exactly 84 + 50 · count ("header says N triangles, file holds M", truncated or
/// with extra records), malformed ASCII STL/OBJ/OFF/PLY ("line L: ..."), a face index past the
/// vertex list (OBJ, OFF, PLY with the line; glTF with the mesh and how many faces; any assimp
/// format with the mesh and face), non-finite coordinates ("triangle I has a non-finite
/// coordinate", I 0-based within its part, or the line for ASCII formats), unreadable STEP/IGES
/// (with the failing entities), a file without triangles, non-positive deflections for CAD formats,
/// a CAD tessellation past options.max_triangles (estimated before BRepMesh runs, naming the limit),
/// a count declared past what the file's bytes can hold (COLLADA count attributes, PLY and OFF
/// element counts, the binary STL count), refused before anything is allocated for it, a glTF/GLB
/// buffer or image uri that is not a data: URI or a relative path inside the model's folder
/// (naming it). assimp opens other references (an OBJ's mtllib) only inside the model's folder
/// and below: one elsewhere is never opened, and the geometry loads without it.
Result<ImportedModel> import_mesh(const std::filesystem::path& file, const ImportOptions& options = {});

/// The point OMPL.app centres a robot mesh on before placing it by a `.cfg` pose
/// (RigidBodyGeometry::getRobotCenter → scene::sceneCenter): the mean of the vertices of every
/// mesh in the file, node transformations applied, as assimp returns them after OMPL.app's
/// post-processing aiProcess_GenNormals | Triangulate | JoinIdenticalVertices | SortByPType |
/// OptimizeGraph. Vertices are joined only where position *and* face normal agree, so a corner
/// shared by faces of different normals counts once per normal, and a corner inside a flat
/// region once. STL, OBJ, PLY, OFF, 3MF, glTF and COLLADA (its <unit> and <up_axis> applied) go
/// through assimp as in OMPL.app; the mean is summed in double precision (OMPL.app: float).
/// CAD files, which OMPL.app cannot read, give the mean of the tessellation's distinct vertex
/// positions. In options.unit, from options.file_unit as import_mesh(); errors as import_mesh().
Result<Vec3> ompl_app_center(const std::filesystem::path& file, const ImportOptions& options = {});

/// The vertices ompl_app_center() averages, as OMPL.app reads them: their mean (`center`) and
/// their axis-aligned box (`box`), which is the box OMPL.app infers for an environment mesh when a
/// problem sets no bounds (RigidBodyGeometry::inferEnvironmentBounds → scene::inferBounds, with
/// its default factor 1 and addition 0). One read of the file.
struct OmplAppVertices {
  Vec3 center = Vec3::Zero();
  Aabb box;
};
Result<OmplAppVertices> ompl_app_vertices(const std::filesystem::path& file, const ImportOptions& options = {});

/// Writes a binary STL (little-endian, float32; normals from the vertex order, zero for
/// degenerate triangles; an 80-byte header not starting with "solid"). Deterministic bytes
/// for equal input. Written whole or not at all (write_file_atomically()). Error (nothing
/// written) on non-finite coordinates or an unwritable path.
Result<bool> write_stl_binary(const std::filesystem::path& file, const TriangleSoup& soup);

}  // namespace swept
