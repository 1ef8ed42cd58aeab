#pragma once
/// The one writer of problem files (SPEC §4's TOML): the box problems of box_problems.h and the
/// CAD scenes of `swept scene` both write theirs here, so that a key added to the format is
/// written by every generator.
#include "swept/plan/problem.h"

#include <string>
#include <string_view>

namespace swept::scenes {

/// A mesh of a problem file: `file` (relative to the problem file) in `file_unit` (empty: the
/// importer's default), at `pose`.
MeshRef mesh_ref(const std::filesystem::path& file, const std::string& file_unit = {}, const Pose& pose = {});

/// The problem as problem.toml text, readable back by load_problem() to the same Problem (numbers
/// written with the fewest digits that read back exactly). Mesh files are written as given
/// (relative to the problem file when relative); a mesh's pose only when it is not the identity.
/// `comment` (several lines allowed) heads the file as `# ` lines.
std::string problem_toml(const Problem& problem, std::string_view comment);

}  // namespace swept::scenes
