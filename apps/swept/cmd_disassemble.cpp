// `swept disassemble`: the disassembly sequence of a whole assembly (docs/assembly.md).
#include "cli_options.h"
#include "commands.h"
#include "output.h"
#include "progress_line.h"

#include "swept/assembly/disassemble.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <filesystem>
#include <iostream>
#include <memory>
#include <set>
#include <sstream>

namespace swept::cli {
namespace {

namespace fs = std::filesystem;

struct DisassembleCliOptions {
  std::string assembly;
  std::string output_dir;
  std::string view;
  bool json = false;
  int jobs = 0;
  double clearance = 0.01;
  double tolerance = 0.0;
  double plan_time = 60.0;
  std::uint64_t plan_queries = 20000;
  bool no_subassemblies = false;
  std::vector<std::string> targets;
  bool reassemble = false;
  bool quiet = false;
  ImportCliOptions import;
};

// The directions tried for a part and what blocks each, one line per direction.
nlohmann::json blocking_json(const Assembly& a, const SequenceStep& s) {
  nlohmann::json per = nlohmann::json::array();
  for (const auto& b : s.blocking) {
    nlohmann::json names = nlohmann::json::array();
    for (std::size_t q : b.blockers) names.push_back(a.parts[q].name);
    per.push_back({{"direction", nlohmann::json::array({b.direction.x(), b.direction.y(), b.direction.z()})}, {"blockers", names}});
  }
  return per;
}

nlohmann::json vec(const Vec3& v) { return {v.x(), v.y(), v.z()}; }

std::string direction_text(const Vec3& d) {
  static const std::pair<Vec3, const char*> kAxes[] = {{Vec3::UnitX(), "+x"}, {-Vec3::UnitX(), "-x"}, {Vec3::UnitY(), "+y"},
                                                       {-Vec3::UnitY(), "-y"}, {Vec3::UnitZ(), "+z"}, {-Vec3::UnitZ(), "-z"}};
  for (const auto& [axis, name] : kAxes)
    if (axis.dot(d) > 1.0 - 1e-12) return name;
  std::ostringstream os;
  os.precision(4);
  os << "(" << d.x() << ", " << d.y() << ", " << d.z() << ")";
  return os.str();
}

// A file name from a part name: letters, digits, '-', '_' and '.' kept, the rest '_'.
std::string file_stem(const std::string& name) {
  std::string out;
  for (char c : name) out += (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.') ? c : '_';
  return out.empty() ? "part" : out;
}

std::string step_name(const Assembly& a, const SequenceStep& s) {
  std::string out;
  for (std::size_t i : s.parts) out += (out.empty() ? "" : " + ") + a.parts[i].name;
  return out;
}

void run(const DisassembleCliOptions& o) {
  const auto t0 = std::chrono::steady_clock::now();
  ProgressLine line(!o.quiet);
  AssemblyReadOptions read_options{o.import.import_options()};
  read_options.import.progress = line.import_progress(fs::path(o.assembly).filename().string());
  auto assembly = read_assembly(o.assembly, read_options);
  line.clear();
  if (!assembly) throw std::runtime_error(assembly.error().message);
  const double read_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  for (const std::string& w : assembly->warnings) std::cerr << "swept: warning: " << w << "\n";

  DisassemblyOptions options;
  options.clearance = o.clearance;
  options.tolerance = o.tolerance > 0 ? o.tolerance : 2.0 * o.import.deflection;
  options.jobs = o.jobs;
  options.plan_time_limit = o.plan_time;
  options.plan_max_queries = o.plan_queries;
  options.subassemblies = !o.no_subassemblies;
  for (const std::string& name : o.targets) {
    const auto t = find_part(*assembly, name);
    if (!t) throw std::runtime_error(t.error().message);
    if (std::find(options.targets.begin(), options.targets.end(), *t) == options.targets.end()) options.targets.push_back(*t);
  }
  if (o.reassemble && o.targets.empty()) throw std::runtime_error("--reassemble goes with --target");
  if (line.on()) {
    options.progress = [&line](const DisassemblyProgress& p) {
      const bool parts = std::string_view(p.phase) == "trees" || std::string_view(p.phase) == "removals" ||
                         std::string_view(p.phase) == "blockings";
      line.count(p.phase, p.done, p.total, parts ? "parts" : "pairs");
    };
  }
  const DisassemblyResult r = disassemble(*assembly, options);
  line.clear();
  for (std::size_t t : r.targets)
    if (std::find(r.fixed.begin(), r.fixed.end(), t) != r.fixed.end())
      throw std::runtime_error(o.assembly + ": the target '" + assembly->parts[t].name +
                               "' is fixed (the base, or marked fixed = true): it is never moved");
  const Assembly& a = *assembly;

  // Path files: NN-name.json, one per removal, in order; written after the sequence, all of them.
  std::vector<std::string> path_files(r.sequence.size());
  if (!o.output_dir.empty()) {
    std::error_code ec;
    fs::create_directories(o.output_dir, ec);
    if (ec) throw std::runtime_error(o.output_dir + ": cannot create the folder: " + ec.message());
    int k = 0;
    for (std::size_t i = 0; i < r.sequence.size(); ++i) {
      const SequenceStep& s = r.sequence[i];
      if (!s.removed) continue;
      char prefix[16];
      std::snprintf(prefix, sizeof prefix, "%02d-", ++k);
      const std::string name = std::string(prefix) + file_stem(s.parts.size() == 1 ? a.parts[s.parts[0]].name : step_name(a, s)) + ".json";
      auto w = write_path(fs::path(o.output_dir) / name, s.path, a.unit, s.reference);
      if (!w) throw std::runtime_error(w.error().message);
      path_files[i] = name;
    }
    // The way back: the same removals in reverse order, each path played backwards into its
    // mounted pose (NN-name.json again, NN the order of putting back).
    if (o.reassemble) {
      const fs::path back = fs::path(o.output_dir) / "reassemble";
      fs::create_directories(back, ec);
      if (ec) throw std::runtime_error(back.string() + ": cannot create the folder: " + ec.message());
      int j = 0;
      for (std::size_t i = r.sequence.size(); i-- > 0;) {
        const SequenceStep& s = r.sequence[i];
        if (!s.removed) continue;
        char prefix[16];
        std::snprintf(prefix, sizeof prefix, "%02d-", ++j);
        Path reversed{{s.path.poses.rbegin(), s.path.poses.rend()}};
        auto w = write_path(back / (std::string(prefix) + file_stem(step_name(a, s)) + ".json"), reversed, a.unit, s.reference);
        if (!w) throw std::runtime_error(w.error().message);
      }
    }
  }

  if (!o.view.empty()) write_disassembly_view_file(a, r, o.view);

  const double total_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  if (o.json) {
    nlohmann::json parts = nlohmann::json::array();
    for (std::size_t i = 0; i < a.parts.size(); ++i) {
      const bool fixed = std::find(r.fixed.begin(), r.fixed.end(), i) != r.fixed.end();
      parts.push_back({{"name", a.parts[i].name}, {"triangles", a.parts[i].mesh.triangles.size()}, {"fixed", fixed}});
    }
    nlohmann::json interferences = nlohmann::json::array();
    for (const Interference& f : r.interferences)
      interferences.push_back({{"parts", {a.parts[f.part_a].name, a.parts[f.part_b].name}},
                               {"depth", f.depth},
                               {"extent", f.extent},
                               {"triangle_pairs", f.triangle_pairs}});
    nlohmann::json sequence = nlohmann::json::array();
    for (std::size_t i = 0; i < r.sequence.size(); ++i) {
      const SequenceStep& s = r.sequence[i];
      nlohmann::json e;
      e["round"] = s.round;
      if (s.parts.size() == 1) e["part"] = a.parts[s.parts[0]].name;
      else {
        e["parts"] = nlohmann::json::array();
        for (std::size_t p : s.parts) e["parts"].push_back(a.parts[p].name);
      }
      e["status"] = s.removed ? "removed" : "blocked";
      if (s.removed) {
        e["method"] = s.method == RemovalMethod::pull ? "pull" : "plan";
        if (s.method == RemovalMethod::pull) e["direction"] = vec(s.direction);
        e["distance"] = s.distance;
        e["path"] = path_files[i].empty() ? nlohmann::json(nullptr) : nlohmann::json(path_files[i]);
        e["blockers"] = nlohmann::json::array();
      } else {
        std::set<std::size_t> all;
        nlohmann::json per = nlohmann::json::array();
        for (const auto& b : s.blocking) {
          nlohmann::json names = nlohmann::json::array();
          for (std::size_t q : b.blockers) names.push_back(a.parts[q].name), all.insert(q);
          per.push_back({{"direction", vec(b.direction)}, {"blockers", names}});
        }
        e["blockers"] = nlohmann::json::array();
        for (std::size_t q : all) e["blockers"].push_back(a.parts[q].name);
        e["blocking"] = per;
      }
      sequence.push_back(e);
    }
    nlohmann::json doc{{"assembly", o.assembly},
                       {"unit", a.unit},
                       {"complete", r.complete},
                       {"clearance", options.clearance},
                       {"tolerance", r.tolerance},
                       {"parts", parts},
                       {"interferences", interferences},
                       {"sequence", sequence},
                       {"warnings", a.warnings},
                       {"target", nullptr},
                       {"time_ms",
                        {{"total", total_ms},
                         {"read", read_ms},
                         {"build", r.time_ms.build},
                         {"interference", r.time_ms.interference},
                         {"sequence", r.time_ms.sequence}}}};
    if (!r.targets.empty()) {
      nlohmann::json names = nlohmann::json::array(), why = nlohmann::json::array(), back = nlohmann::json::array();
      for (std::size_t t : r.targets) names.push_back(a.parts[t].name);
      for (const SequenceStep& w : r.why) why.push_back({{"part", a.parts[w.parts[0]].name}, {"blocking", blocking_json(a, w)}});
      for (std::size_t i = r.sequence.size(); i-- > 0;)
        if (r.sequence[i].removed) back.push_back(step_name(a, r.sequence[i]));
      doc["target"] = {{"parts", names},
                       {"removals", r.complete ? nlohmann::json(r.sequence.size()) : nlohmann::json(nullptr)},
                       {"fewest", r.fewest},
                       {"lower_bound", r.lower_bound},
                       {"why", why},
                       {"reassemble", back}};
    }
    std::cout << json_text(doc, 2) << "\n";
  } else {
    std::cout << "assembly     " << o.assembly << ": " << a.parts.size() << (a.parts.size() == 1 ? " part, " : " parts, ")
              << a.triangle_count()
              << " triangles (unit " << a.unit << ")\n";
    std::cout << "contact      clearance " << options.clearance << ", mating tolerance " << r.tolerance << "\n";
    for (const Interference& f : r.interferences)
      std::cout << "interference " << a.parts[f.part_a].name << " and " << a.parts[f.part_b].name << ": depth "
                << f.depth << " " << a.unit << ", extent " << f.extent << " " << a.unit << " (" << f.triangle_pairs
                << " triangle pairs)\n";
    Table table({"#", "round", "part", "status", "how", "direction", "distance", "blockers", "ms"});
    table.limit_width(2, 40);  // a group of many parts, and a long list of blockers, wrap
    table.limit_width(7, 48);
    int k = 0;
    for (const SequenceStep& s : r.sequence) {
      std::string blockers;
      std::set<std::size_t> all;
      for (const auto& b : s.blocking) all.insert(b.blockers.begin(), b.blockers.end());
      for (std::size_t q : all) blockers += (blockers.empty() ? "" : ", ") + a.parts[q].name;
      table.add({s.removed ? std::to_string(++k) : "-", std::to_string(s.round), step_name(a, s),
                 s.removed ? "removed" : "blocked",
                 s.removed ? (s.method == RemovalMethod::pull ? (s.parts.size() > 1 ? "pull (group)" : "pull") : "plan") : "",
                 s.removed && s.method == RemovalMethod::pull ? direction_text(s.direction) : "",
                 s.removed ? fmt_fixed(s.distance, 2) : "", blockers, fmt_fixed(s.time_ms, 1)});
    }
    if (!r.sequence.empty()) table.print(std::cout);
    if (!r.targets.empty()) {
      std::string names;
      for (std::size_t t : r.targets) names += (names.empty() ? "" : ", ") + a.parts[t].name;
      // Why: each target and each part taken off for it, the way it leaves and what blocks the
      // other directions tried (--json lists them direction by direction).
      Table why({"part", "out along", "after", "tried", "the other directions blocked by"});
      auto list = [&](const auto& parts) {
        std::string out;
        for (std::size_t q : parts) out += (out.empty() ? "" : ", ") + a.parts[q].name;
        return out;
      };
      for (const SequenceStep& w : r.why) {
        const std::size_t p = w.parts[0];
        const SequenceStep* step = nullptr;
        for (const SequenceStep& st : r.sequence)
          if (st.parts[0] == p) step = &st;
        std::set<std::size_t> by;
        std::vector<std::size_t> after;
        for (const auto& b : w.blocking) {
          if (step && b.direction == step->direction) after = b.blockers;
          else by.insert(b.blockers.begin(), b.blockers.end());
        }
        why.add({a.parts[p].name, step ? direction_text(step->direction) : "-", step ? (after.empty() ? "-" : list(after)) : "",
                 std::to_string(w.blocking.size()), list(by)});
      }
      std::cout << "why          with every part in place (the directions one by one: --json)\n";
      why.print(std::cout);
      if (r.complete)
        std::cout << "result       " << names << ": " << r.sequence.size() << " removal" << (r.sequence.size() == 1 ? "" : "s")
                  << " (the target" << (r.targets.size() == 1 ? "" : "s") << " included), "
                  << (r.fewest ? "the fewest" : "not proved the fewest (the search's limit was reached; at least " +
                                                    std::to_string(r.lower_bound) + ")")
                  << "; the other parts stay mounted\n";
      else
        std::cout << "result       " << names << " cannot come out by straight pulls (no set of removals frees "
                  << (r.targets.size() == 1 ? "it" : "them") << "; the blockers are above)\n";
      if (o.reassemble) {
        std::string back;
        for (std::size_t i = r.sequence.size(); i-- > 0;) back += (back.empty() ? "" : ", ") + step_name(a, r.sequence[i]);
        std::cout << "reassemble   " << back << (o.output_dir.empty() ? "" : " (paths in " + o.output_dir + "/reassemble)") << "\n";
      }
    } else {
    const bool nothing_moves = r.fixed.size() == a.parts.size();
    std::cout << "result       "
              << (nothing_moves ? "complete: nothing to take apart, no part is movable"
                                : r.complete ? "complete: every movable part comes out" : "not complete: parts stay")
              << " (fixed: ";
    for (std::size_t i = 0; i < r.fixed.size(); ++i) std::cout << (i ? ", " : "") << a.parts[r.fixed[i]].name;
    std::cout << ")\n";
    }
    std::cout
              << "time         total " << fmt_fixed(total_ms, 1) << " ms (read " << fmt_fixed(read_ms, 1) << ", build "
              << fmt_fixed(r.time_ms.build, 1) << ", interference " << fmt_fixed(r.time_ms.interference, 1)
              << ", sequence " << fmt_fixed(r.time_ms.sequence, 1) << "), queries " << r.distance_queries << " (pull sweeps and planner distances)"
              << "\n";
    if (!o.output_dir.empty()) std::cout << "written      path files in " << o.output_dir << "\n";
    if (!o.view.empty()) std::cout << "written      " << o.view << "\n";
  }
  if (!r.complete) throw ExitCode{2};
}

}  // namespace

void add_disassemble_command(CLI::App& app) {
  auto o = std::make_shared<DisassembleCliOptions>();
  CLI::App* cmd = app.add_subcommand(
      "disassemble",
      "Take a whole assembly apart: a STEP/IGES/BREP file with several solids, a TOML assembly\n"
      "file (docs/assembly-format.md) or a folder of placed meshes. Reports interferences first,\n"
      "then removes one part (or group of touching parts) per round by certified straight pulls\n"
      "(the planner when none is clear), and names the blockers of the parts that stay.\n"
      "Exit 0: every movable part comes out; 2: some stay; 1: bad input.");
  cmd->add_option("assembly", o->assembly, "Assembly: CAD file, .toml assembly file, or folder of meshes")->required();
  cmd->add_option("-o,--output", o->output_dir, "Folder for the path files (NN-part.json, one per removal)");
  cmd->add_flag("--json", o->json, "Print one JSON document (complete, parts, sequence, interferences, time_ms)");
  cmd->add_option("--jobs", o->jobs, "Threads for the candidates of a round (0: all cores); the same result at any count")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--view", o->view, "Also write a self-contained HTML page playing the whole disassembly (docs/viewer.md)");
  cmd->add_option("--clearance", o->clearance, "Every pair that is not a mate keeps more than this (assembly unit)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  cmd->add_option("--tolerance", o->tolerance,
                  "Mating tolerance: how far mated faces may overlap (tessellation sag) and the interference "
                  "threshold; default 2 x --deflection")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--plan-queries", o->plan_queries,
                  "Distance queries per planner attempt when no straight pull is clear: the limit that ends an attempt, "
                  "the same on every machine (0: none)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  cmd->add_option("--plan-time", o->plan_time,
                  "Seconds per planner attempt (0: no planner): a safety net behind --plan-queries; an attempt it ends "
                  "could end otherwise on another machine")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  cmd->add_flag("--no-subassemblies", o->no_subassemblies, "Do not try groups of touching parts");
  cmd->add_option("--target", o->targets,
                  "Take out only this part (repeat for several) and the fewest others that must come off first, by "
                  "straight pulls; the others stay mounted. Prints why (what blocks each direction)");
  cmd->add_flag("--reassemble", o->reassemble,
                "With --target: also the order to put it back, the paths played backwards (-o DIR/reassemble)");
  cmd->add_flag("-q,--quiet", o->quiet, "No progress line (there is none either when stderr is not a terminal)");
  add_import_options(*cmd, o->import);
  cmd->callback([o] { run(*o); });
}

}  // namespace swept::cli
