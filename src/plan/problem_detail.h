#pragma once
// Internal to swept_plan: what the problem readers (problem_toml.cpp, problem_cfg.cpp) and the
// path files (path_io.cpp) share.
#include "swept/plan/problem.h"

#include <filesystem>
#include <numbers>
#include <optional>
#include <string>

namespace swept::problem_detail {

inline constexpr double kDeg = std::numbers::pi / 180.0;

/// A rotation from components of any magnitude: scaled by the largest component first, so that
/// huge components do not overflow the norm to infinity (which normalises to zero and reads as
/// the identity) and tiny ones do not underflow it. nullopt for all zero.
std::optional<Quat> unit_quaternion(double x, double y, double z, double w);

/// The unit vector along `axis`, scaled first like unit_quaternion; nullopt for zero.
std::optional<Vec3> unit_axis(const Vec3& axis);

/// `file` as written in a problem: relative to the folder of the problem file `base`.
std::filesystem::path resolve(const std::filesystem::path& base, const std::string& file);

/// A number as error messages show it (the stream's default: 6 significant digits).
std::string format_number(double v);

/// Our TOML format (docs/problem-format.md), read strictly.
Result<Problem> load_toml(const std::filesystem::path& file);

/// OMPL.app's .cfg, read as OMPL.app reads it.
Result<Problem> load_cfg(const std::filesystem::path& file);

}  // namespace swept::problem_detail
