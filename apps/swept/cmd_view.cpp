// `swept view`: one self-contained HTML file showing a problem and a path (docs/viewer.md).
//
// The page inlines the viewer script (three.js bundled by viewer/build.mjs at build time) and the
// scene as JSON. Meshes travel compactly: vertices deduplicated after quantisation to uint16
// within each mesh's bounding box, positions delta-coded and corner indices coded against the
// high-water mark, both zigzag coded in byte planes, deflated (zlib) and base64-encoded; the
// browser inflates them with its own DecompressionStream, offline (viewer/src/decode.js).
#include "commands.h"
#include "output.h"

#include "swept/assembly/disassemble.h"
#include "swept/plan/planner.h"
#include "swept/query/query.h"

#include <nlohmann/json.hpp>
#include <zlib.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iostream>
#include <limits>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace swept::cli {

// Generated at build time from viewer/src (see apps/swept/CMakeLists.txt).
extern const char viewer_script_data[];
extern const std::size_t viewer_script_size;

namespace {

struct ViewOptions {
  std::string problem;
  std::string path;
  std::string output = "view.html";
  int samples = 500;
};

std::string base64(const std::vector<std::uint8_t>& bytes) {
  static constexpr char alphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  std::size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const std::uint32_t v = (std::uint32_t{bytes[i]} << 16) | (std::uint32_t{bytes[i + 1]} << 8) | bytes[i + 2];
    out += alphabet[(v >> 18) & 63];
    out += alphabet[(v >> 12) & 63];
    out += alphabet[(v >> 6) & 63];
    out += alphabet[v & 63];
  }
  if (i + 1 == bytes.size()) {
    const std::uint32_t v = std::uint32_t{bytes[i]} << 16;
    out += alphabet[(v >> 18) & 63];
    out += alphabet[(v >> 12) & 63];
    out += "==";
  } else if (i + 2 == bytes.size()) {
    const std::uint32_t v = (std::uint32_t{bytes[i]} << 16) | (std::uint32_t{bytes[i + 1]} << 8);
    out += alphabet[(v >> 18) & 63];
    out += alphabet[(v >> 12) & 63];
    out += alphabet[(v >> 6) & 63];
    out += '=';
  }
  return out;
}

/// zlib stream (RFC 1950), which the browser's DecompressionStream("deflate") reads.
std::vector<std::uint8_t> deflate_bytes(const std::vector<std::uint8_t>& in) {
  uLongf size = compressBound(static_cast<uLong>(in.size()));
  std::vector<std::uint8_t> out(size);
  if (compress2(out.data(), &size, in.data(), static_cast<uLong>(in.size()), 6) != Z_OK)
    throw std::runtime_error("view: zlib compression failed");
  out.resize(size);
  return out;
}

nlohmann::json vec(const Vec3& v) { return {v.x(), v.y(), v.z()}; }

/// The mesh in the page's format. Vertices are quantised to 16 bits per axis of the bounding
/// box (for a 1 m part: 15 µm steps, invisible on screen), merged when equal after
/// quantisation, numbered in order of first use; triangles that collapse are left out.
nlohmann::json encode_mesh(const TriangleSoup& soup) {
  const Aabb box = bounds(soup.triangles);
  const Vec3 lo = box.empty() ? Vec3::Zero() : box.min;
  const Vec3 size = box.size();
  auto quantise = [&](const Vec3& p) {
    std::array<std::uint16_t, 3> q{};
    for (int a = 0; a < 3; ++a) {
      const double u = size[a] > 0 ? (p[a] - lo[a]) / size[a] : 0.0;
      q[a] = static_cast<std::uint16_t>(std::lround(std::clamp(u, 0.0, 1.0) * 65535.0));
    }
    return q;
  };
  // Lookups only (never iterated), so the numbering is the order of first use: deterministic.
  std::unordered_map<std::uint64_t, std::uint32_t> index_of;
  index_of.reserve(soup.triangles.size() * 2);
  std::vector<std::array<std::uint16_t, 3>> vertices;
  std::vector<std::uint32_t> corners;
  corners.reserve(soup.triangles.size() * 3);
  for (const Triangle& t : soup.triangles) {
    std::array<std::uint32_t, 3> ids{};
    for (int k = 0; k < 3; ++k) {
      const auto q = quantise(t[k]);
      const std::uint64_t key = std::uint64_t{q[0]} | (std::uint64_t{q[1]} << 16) | (std::uint64_t{q[2]} << 32);
      auto [it, inserted] = index_of.try_emplace(key, static_cast<std::uint32_t>(vertices.size()));
      if (inserted) vertices.push_back(q);
      ids[k] = it->second;
    }
    if (ids[0] == ids[1] || ids[1] == ids[2] || ids[0] == ids[2]) continue;
    corners.insert(corners.end(), ids.begin(), ids.end());
  }

  // Positions: per coordinate, the difference from the previous vertex (modulo 2^16), zigzag
  // coded so that small steps either way are small numbers; stored as byte planes (all low
  // bytes, then all high bytes), which deflate compresses better than interleaved bytes.
  const std::size_t n = vertices.size() * 3;
  std::vector<std::uint8_t> positions(n * 2);
  std::array<std::uint16_t, 3> last{};
  for (std::size_t v = 0; v < vertices.size(); ++v)
    for (int a = 0; a < 3; ++a) {
      const auto step = static_cast<std::int16_t>(static_cast<std::uint16_t>(vertices[v][a] - last[a]));
      const auto code = static_cast<std::uint16_t>((static_cast<std::uint16_t>(step) << 1) ^ (step < 0 ? 0xffff : 0));
      positions[3 * v + a] = static_cast<std::uint8_t>(code & 0xff);
      positions[n + 3 * v + a] = static_cast<std::uint8_t>(code >> 8);
      last[a] = vertices[v][a];
    }
  // Corners: each index relative to the "high-water mark" (one past the largest index so far),
  // zigzag coded: a vertex used for the first time is 0, recently used ones are small. Stored as
  // four byte planes of uint32.
  const std::size_t m = corners.size();
  std::vector<std::uint8_t> indices(m * 4);
  std::int64_t high_water = 0;
  for (std::size_t i = 0; i < m; ++i) {
    const std::int64_t back = high_water - std::int64_t{corners[i]};
    const auto code = static_cast<std::uint32_t>(back >= 0 ? 2 * back : -2 * back - 1);
    for (int k = 0; k < 4; ++k) indices[k * m + i] = static_cast<std::uint8_t>((code >> (8 * k)) & 0xff);
    high_water = std::max(high_water, std::int64_t{corners[i]} + 1);
  }
  return {{"name", soup.name},
          {"triangles", corners.size() / 3},
          {"vertices", vertices.size()},
          {"source_triangles", soup.triangles.size()},
          {"min", vec(lo)},
          {"max", vec(lo + size)},
          {"positions", base64(deflate_bytes(positions))},
          {"indices", base64(deflate_bytes(indices))}};
}

/// Path parameter of each waypoint: cumulative motion length (SPEC §4 metric), normalised to
/// [0, 1]; by waypoint count when the path does not move at all.
std::vector<double> waypoint_parameters(const Path& path, const PlanScene& scene, double& total) {
  std::vector<double> s(path.poses.size(), 0.0);
  total = 0.0;
  for (std::size_t i = 1; i < path.poses.size(); ++i) {
    total += motion_length(path.poses[i - 1], path.poses[i], scene.reference, scene.radius);
    s[i] = total;
  }
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (total > 0) s[i] /= total;
    else s[i] = s.size() > 1 ? double(i) / double(s.size() - 1) : 0.0;
  }
  if (s.size() > 1) s.back() = 1.0;
  return s;
}

/// Pose at parameter u ∈ [0, 1], the motion `interpolate` describes between waypoints.
Pose pose_at(const Path& path, const std::vector<double>& s, double u, const Vec3& reference) {
  if (path.poses.size() == 1) return path.poses.front();
  std::size_t i = 0;
  while (i + 2 < s.size() && s[i + 1] <= u) ++i;
  const double span = s[i + 1] - s[i];
  const double t = span > 0 ? std::clamp((u - s[i]) / span, 0.0, 1.0) : 1.0;
  return interpolate(path.poses[i], path.poses[i + 1], t, reference);
}

std::string json_for_script(const nlohmann::json& doc) {
  // Inside <script>, "</script" or "<!--" would end or confuse the element: '<' only occurs in
  // JSON strings, where \u003c means the same.
  const std::string text = json_text(doc);
  std::string out;
  out.reserve(text.size() + 64);
  for (char c : text) {
    if (c == '<') out += "\\u003c";
    else out += c;
  }
  return out;
}

std::string html_escape(std::string_view text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

void write_view(const Problem& problem, const PlanScene& scene, const Path& path, const std::string& html_file,
                int samples) {
  if (path.poses.empty()) throw std::runtime_error("view: the path has no poses");
  if (samples < 2) throw std::runtime_error("view: --samples must be at least 2");
  for (std::size_t i = 0; i < path.poses.size(); ++i) {
    const Pose& p = path.poses[i];
    if (!p.rotation.allFinite() || !p.translation.allFinite())
      throw std::runtime_error("view: pose " + std::to_string(i) + " of the path is not finite");
  }
  if (scene.obstacles.triangles.empty()) throw std::runtime_error("view: the problem has no obstacle triangles");
  if (scene.body.triangles.empty()) throw std::runtime_error("view: the problem has no body triangles");

  double total = 0.0;
  const std::vector<double> s = waypoint_parameters(path, scene, total);

  // Clearance at uniform parameters (distance_batch answers in parallel, in input order).
  std::vector<Pose> poses(static_cast<std::size_t>(samples));
  std::vector<double> sample_s(poses.size());
  for (std::size_t k = 0; k < poses.size(); ++k) {
    sample_s[k] = double(k) / double(poses.size() - 1);
    poses[k] = pose_at(path, s, sample_s[k], scene.reference);
  }
  const std::vector<DistanceResult> d = distance_batch(scene.obstacle_tree, Pose{}, scene.body_tree, poses);
  nlohmann::json distances = nlohmann::json::array(), point_a = nlohmann::json::array(),
                 point_b = nlohmann::json::array();
  double min_distance = std::numeric_limits<double>::infinity();
  for (const DistanceResult& r : d) {
    distances.push_back(r.distance);
    for (int a = 0; a < 3; ++a) {
      point_a.push_back(r.point_a[a]);
      point_b.push_back(r.point_b[a]);
    }
    min_distance = std::min(min_distance, r.distance);
  }

  nlohmann::json waypoints = nlohmann::json::array();
  for (std::size_t i = 0; i < path.poses.size(); ++i) {
    const Quat q = path.poses[i].quaternion();
    waypoints.push_back({{"s", s[i]},
                         {"translation", vec(path.poses[i].translation)},
                         {"quaternion", {q.x(), q.y(), q.z(), q.w()}}});
  }

  // File names need not be UTF-8 (POSIX allows any byte but '/' and NUL); the page and its JSON must be.
  const std::string title = valid_utf8(problem.source.empty() ? std::string("swept") : problem.source.filename().string());
  const nlohmann::json doc{
      {"format", 1},
      {"title", title},
      {"unit", problem.unit},
      {"meshes", {{"obstacles", encode_mesh(scene.obstacles)}, {"body", encode_mesh(scene.body)}}},
      {"reference", vec(scene.reference)},
      {"radius", scene.radius},
      {"path_length", total},
      {"waypoints", waypoints},
      {"clearance",
       {{"s", sample_s}, {"distance", distances}, {"point_a", point_a}, {"point_b", point_b},
        {"margin", problem.clearance}, {"min", min_distance}}},
  };

  std::ostringstream out;  // written whole or not at all below
  out << "<!doctype html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
      << "<title>swept view: " << html_escape(title) << "</title>\n</head>\n<body>\n"
      << "<script id=\"swept-data\" type=\"application/json\">" << json_for_script(doc) << "</script>\n"
      << "<script>";
  out.write(viewer_script_data, static_cast<std::streamsize>(viewer_script_size));
  out << "</script>\n</body>\n</html>\n";
  write_output(html_file, out.str());
}

void run(const ViewOptions& o) {
  auto problem = load_problem(o.problem);
  if (!problem) throw std::runtime_error(problem.error().message);
  auto scene = load_scene(*problem, problem->build);
  if (!scene) throw std::runtime_error(scene.error().message);
  for (const std::string& w : scene->warnings) std::cerr << "swept: warning: " << w << "\n";
  auto path = read_path(o.path);
  if (!path) throw std::runtime_error(path.error().message);
  const auto t0 = std::chrono::steady_clock::now();
  write_view(*problem, *scene, *path, o.output, o.samples);
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  std::ifstream written(o.output, std::ios::binary | std::ios::ate);
  std::cout << o.output << ": " << scene->obstacles.triangles.size() << " obstacle and "
            << scene->body.triangles.size() << " body triangles, " << path->poses.size() << " poses, "
            << o.samples << " clearance samples, " << static_cast<long long>(written.tellg()) << " bytes ("
            << static_cast<long long>(std::lround(ms)) << " ms)\n";
}

}  // namespace

void write_view_file(const Problem& problem, const PlanScene& scene, const Path& path, const std::string& html_file) {
  write_view(problem, scene, path, html_file, 500);
}

void write_disassembly_view_file(const Assembly& assembly, const DisassemblyResult& result,
                                 const std::string& html_file) {
  nlohmann::json parts = nlohmann::json::array();
  for (std::size_t i = 0; i < assembly.parts.size(); ++i) {
    const bool fixed = std::find(result.fixed.begin(), result.fixed.end(), i) != result.fixed.end();
    parts.push_back({{"name", valid_utf8(assembly.parts[i].name)}, {"fixed", fixed}, {"mesh", encode_mesh(assembly.parts[i].mesh)}});
  }
  nlohmann::json steps = nlohmann::json::array(), blocked = nlohmann::json::array(), blocking = nlohmann::json::array();
  for (const SequenceStep& step : result.sequence) {
    if (!step.removed) {
      for (std::size_t i : step.parts) blocked.push_back(valid_utf8(assembly.parts[i].name));
      // The directional blocking graph of the parts that stay: per direction tried, the parts
      // that block a pull along it on their own (the viewer draws an arrow per direction).
      nlohmann::json directions = nlohmann::json::array();
      for (const auto& b : step.blocking) directions.push_back({{"direction", vec(b.direction)}, {"blockers", b.blockers}});
      blocking.push_back({{"parts", step.parts}, {"directions", directions}});
      continue;
    }
    // The path's parameter: by the reference point's travel (a pull: 0 and 1).
    std::vector<double> along{0.0};
    for (std::size_t k = 1; k < step.path.poses.size(); ++k)
      along.push_back(along.back() + (step.path.poses[k].apply(step.reference) - step.path.poses[k - 1].apply(step.reference)).norm());
    nlohmann::json waypoints = nlohmann::json::array();
    for (std::size_t k = 0; k < step.path.poses.size(); ++k) {
      const Quat q = step.path.poses[k].quaternion();
      const double s = along.back() > 0 ? along[k] / along.back() : (step.path.poses.size() > 1 ? double(k) / double(step.path.poses.size() - 1) : 0.0);
      waypoints.push_back({{"s", s}, {"translation", vec(step.path.poses[k].translation)}, {"quaternion", {q.x(), q.y(), q.z(), q.w()}}});
    }
    steps.push_back({{"parts", step.parts},
                     {"method", step.method == RemovalMethod::pull ? "pull" : "plan"},
                     {"reference", vec(step.reference)},
                     {"waypoints", waypoints}});
  }
  const std::string title = valid_utf8(assembly.source.filename().string());
  const nlohmann::json doc{{"format", 2},       {"title", title},   {"unit", assembly.unit}, {"parts", parts},
                           {"steps", steps},     {"complete", result.complete}, {"blocked", blocked},
                           {"blocking", blocking}};
  std::ostringstream out;  // written whole or not at all below
  out << "<!doctype html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
      << "<title>swept disassemble: " << html_escape(title) << "</title>\n</head>\n<body>\n"
      << "<script id=\"swept-data\" type=\"application/json\">" << json_for_script(doc) << "</script>\n"
      << "<script>";
  out.write(viewer_script_data, static_cast<std::streamsize>(viewer_script_size));
  out << "</script>\n</body>\n</html>\n";
  write_output(html_file, out.str());
}

void add_view_command(CLI::App& app) {
  auto options = std::make_shared<ViewOptions>();
  CLI::App* cmd = app.add_subcommand(
      "view", "Write one self-contained HTML file (three.js inlined, works offline) showing the obstacles and the "
              "body moving along a path, with the clearance along the path.");
  cmd->add_option("problem", options->problem, "problem file (.toml or OMPL.app .cfg)")->required();
  cmd->add_option("path", options->path, "path file (swept JSON or OMPL .path, either of OMPL's forms)")->required();
  cmd->add_option("-o,--output", options->output, "HTML file to write")->capture_default_str();
  cmd->add_option("--samples", options->samples, "poses along the path where the clearance is computed")
      ->capture_default_str()
      ->check(CLI::Range(2, 100000));
  cmd->callback([options] { run(*options); });
}

}  // namespace swept::cli
