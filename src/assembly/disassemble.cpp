// The disassembly sequence (disassemble.h; docs/assembly.md): rounds of straight pulls, the
// planner as fallback, subassemblies, and the blocking graph of what stays.
#include "bodies.h"
#include "swept/assembly/disassemble.h"

#include "swept/plan/planner.h"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <functional>
#include <map>
#include <numeric>
#include <set>

namespace swept {
namespace {

using contact::Body;
using contact::PullSettings;
using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

struct Attempt {
  bool removed = false;
  RemovalMethod method = RemovalMethod::pull;
  Vec3 direction = Vec3::Zero();
  double distance = 0.0;
  Path path;
  Vec3 reference = Vec3::Zero();
  double time_ms = 0.0;
};

// The scale of the assembly: the diagonal of its box.
double assembly_size(const std::vector<Body>& bodies) {
  Aabb all;
  for (const Body& b : bodies) all.extend(b.box);
  return all.extent();
}

class Sequencer {
 public:
  Sequencer(const Assembly& a, const DisassemblyOptions& o, double tolerance)
      : a_(a), o_(o), settings_{o.clearance, tolerance}, progress_(o.progress) {}

  DisassemblyResult run() {
    DisassemblyResult out;
    std::vector<bool> is_fixed = prepare(out);
    const std::size_t n = a_.parts.size();
    const auto t0 = Clock::now();
    touching_ = contact_graph();
    blocked_pulls_.assign(n, {});
    std::vector<std::size_t> remaining(n);
    std::iota(remaining.begin(), remaining.end(), std::size_t{0});
    const std::size_t movable_total = static_cast<std::size_t>(std::count(is_fixed.begin(), is_fixed.end(), false));
    int round = 0;
    for (;;) {
      std::vector<std::size_t> movable;
      for (std::size_t i : remaining)
        if (!is_fixed[i]) movable.push_back(i);
      progress_.set("removals", movable_total - movable.size(), movable_total);
      if (movable.empty()) {
        out.complete = true;
        break;
      }
      ++round;
      // Single parts, straight pulls; then the planner; then subassemblies. The first success in
      // part order is removed.
      std::vector<std::vector<std::size_t>> candidates;
      for (std::size_t i : movable) candidates.push_back({i});
      std::optional<std::pair<std::vector<std::size_t>, Attempt>> chosen = first_removal(candidates, remaining, false);
      if (!chosen && o_.plan_time_limit > 0) chosen = first_removal(candidates, remaining, true);
      if (!chosen && o_.subassemblies) chosen = first_removal(subassemblies(movable), remaining, false);
      if (!chosen) {
        // What stays, and why: the blocking graph.
        std::vector<SequenceStep> blocked(movable.size());
        tbb::parallel_for(std::size_t{0}, movable.size(),
                          [&](std::size_t k) { blocked[k] = blocking_of(movable[k], remaining, round); });
        for (SequenceStep& s : blocked) out.sequence.push_back(std::move(s));
        break;
      }
      SequenceStep s;
      s.parts = chosen->first;
      s.removed = true;
      s.method = chosen->second.method;
      s.direction = chosen->second.direction;
      s.distance = chosen->second.distance;
      s.path = std::move(chosen->second.path);
      s.reference = chosen->second.reference;
      s.round = round;
      s.time_ms = chosen->second.time_ms;
      for (std::size_t i : s.parts) std::erase(remaining, i);
      out.sequence.push_back(std::move(s));
    }
    out.time_ms.sequence = ms_since(t0);
    out.distance_queries = queries_.load();
    return out;
  }

  // The fewest removals that free the targets (DisassemblyOptions::targets): a breadth-first
  // search over the sets of parts removed, by straight pulls. Every blocking is taken with every
  // part in place and pulls long enough to leave the whole assembly's box, so a part blocks a
  // pull on its own or not whatever else is gone, and a set of removals is feasible when its
  // parts can be ordered so that each one's blockers along some direction are gone before it.
  // The first level that holds every target is the fewest.
  DisassemblyResult run_target() {
    DisassemblyResult out;
    const std::vector<bool> is_fixed = prepare(out, /*contacts=*/false);
    const auto t0 = Clock::now();
    out.targets = o_.targets;
    const std::size_t n = a_.parts.size();
    all_.resize(n);
    std::iota(all_.begin(), all_.end(), std::size_t{0});
    block_.assign(n, std::nullopt);
    // The parts the targets may need off: their blockers, and those parts' blockers, and so on.
    std::vector<std::size_t> relevant;
    std::vector<bool> seen(n, false);
    std::vector<std::size_t> stack(o_.targets.rbegin(), o_.targets.rend());
    for (std::size_t t : o_.targets) seen[t] = true;
    while (!stack.empty()) {
      const std::size_t p = stack.back();
      stack.pop_back();
      progress_.set("blockings", relevant.size(), relevant.size() + stack.size() + 1);
      relevant.push_back(p);
      for (const SequenceStep::Blocking& b : blocking(p).blocking)
        for (std::size_t q : b.blockers)
          if (!seen[q] && !is_fixed[q]) seen[q] = true, stack.push_back(q);
    }
    progress_.set("blockings", relevant.size(), relevant.size());
    std::sort(relevant.begin(), relevant.end());
    {
      // Interferences where they can matter: the pairs with a part the targets may need off.
      const auto ti = Clock::now();
      std::vector<bool> among(n, false);
      for (std::size_t p : relevant) among[p] = true;
      out.interferences = assembly_detail::interferences(bodies_, settings_.tolerance, among, &progress_);
      out.time_ms.interference = ms_since(ti);
    }
    std::vector<Removal> level{Removal{}};
    std::set<std::vector<std::size_t>> visited{{}};
    std::optional<Removal> found;
    std::size_t states = 1;
    bool cut = false;
    while (!level.empty() && !found && !cut) {
      std::vector<Removal> next;
      for (const Removal& r : level) {
        std::vector<bool> gone(n, false);
        for (std::size_t p : r.parts) gone[p] = true;
        for (std::size_t p : relevant) {
          if (gone[p]) continue;
          const int d = freeing(p, gone);
          if (d < 0) continue;
          std::vector<std::size_t> key = r.parts;
          key.push_back(p);
          std::sort(key.begin(), key.end());
          if (!visited.insert(key).second) continue;
          Removal t = r;
          t.parts.push_back(p);
          t.direction.push_back(d);
          gone[p] = true;
          const bool done = targets_gone(gone);
          gone[p] = false;
          if (done) {
            found = std::move(t);
            break;
          }
          next.push_back(std::move(t));
          if (++states >= o_.target_states) {
            cut = true;
            break;
          }
        }
        if (found || cut) break;
      }
      // Every set of this size was tried: none frees the targets.
      if (!found && !cut) out.lower_bound = level.front().parts.size() + 1;
      level = std::move(next);
    }
    if (cut) found = greedy_removal();
    out.fewest = found.has_value() && !cut;
    if (found) {
      out.complete = true;
      if (!cut) out.lower_bound = found->parts.size();
      for (std::size_t k = 0; k < found->parts.size(); ++k) {
        const std::size_t p = found->parts[k];
        const SequenceStep::Blocking& b = blocking(p).blocking[static_cast<std::size_t>(found->direction[k])];
        SequenceStep step;
        step.parts = {p};
        step.removed = true;
        step.direction = b.direction;
        step.distance = contact::exit_length(bodies_[p], others({p}, all_), b.direction, exit_margin());
        step.path.poses = {Pose{}, Pose::from_translation(step.distance * b.direction)};
        step.reference = bodies_[p].box.center();
        step.round = static_cast<int>(k) + 1;
        out.sequence.push_back(std::move(step));
      }
    }
    // Why: the targets, then the parts removed for them, each with its directions and blockers.
    std::vector<std::size_t> why = o_.targets;
    for (const SequenceStep& st : out.sequence)
      if (std::find(why.begin(), why.end(), st.parts[0]) == why.end()) why.push_back(st.parts[0]);
    for (std::size_t p : why) out.why.push_back(blocking(p));
    out.time_ms.sequence = ms_since(t0);
    out.distance_queries = queries_.load();
    return out;
  }

 private:
  /// Parts removed in order, each by its direction (an index into blocking(p).blocking).
  struct Removal {
    std::vector<std::size_t> parts;
    std::vector<int> direction;
  };
  std::vector<std::size_t> all_;
  std::vector<std::optional<SequenceStep>> block_;

  // The directional blocking of p with every part in place (computed once): along each
  // direction, the fixed parts first; a direction a fixed part blocks lists the fixed parts that
  // block it, and nothing else (it can never be freed).
  const SequenceStep& blocking(std::size_t p) {
    if (block_[p]) return *block_[p];
    if (contacts_[p].empty()) contacts_[p] = contacts_of(p);
    block_[p] = blocking_of(p, all_, 0, /*fixed_first=*/true);
    return *block_[p];
  }
  // The contact facets of part p with every other part (as find_contacts finds them).
  std::vector<std::vector<contact::ContactFacet>> contacts_of(std::size_t p) const {
    const std::size_t n = bodies_.size();
    const double threshold = settings_.clearance + settings_.tolerance;
    std::vector<std::vector<contact::ContactFacet>> out(n);
    tbb::parallel_for(std::size_t{0}, n, [&](std::size_t j) {
      if (j == p || contact::box_gap(bodies_[j].box, bodies_[p].box) > threshold) return;
      out[j] = contact::touching_facets(bodies_[j], bodies_[p], threshold);
    });
    return out;
  }
  std::vector<bool> is_fixed_;
  // The first direction whose blockers are all gone (−1: none).
  int freeing(std::size_t p, const std::vector<bool>& gone) {
    const auto& dirs = blocking(p).blocking;
    for (std::size_t k = 0; k < dirs.size(); ++k)
      if (std::all_of(dirs[k].blockers.begin(), dirs[k].blockers.end(), [&](std::size_t q) { return gone[q]; }))
        return static_cast<int>(k);
    return -1;
  }
  bool targets_gone(const std::vector<bool>& gone) const {
    return std::all_of(o_.targets.begin(), o_.targets.end(), [&](std::size_t t) { return gone[t]; });
  }
  // Past the search's limit: each target in turn, each part by the direction with the fewest
  // blockers still in place, its blockers first (depth first; a part met again on the way is a
  // cycle, and that direction is given up).
  std::optional<Removal> greedy_removal() {
    const std::size_t n = a_.parts.size();
    std::vector<bool> gone(n, false), visiting(n, false);
    Removal out;
    std::function<bool(std::size_t)> take = [&](std::size_t p) -> bool {
      if (gone[p]) return true;
      if (visiting[p]) return false;
      visiting[p] = true;
      const auto dirs = blocking(p).blocking;
      std::vector<std::size_t> order(dirs.size());
      std::iota(order.begin(), order.end(), std::size_t{0});
      auto missing = [&](std::size_t k) {
        return std::count_if(dirs[k].blockers.begin(), dirs[k].blockers.end(), [&](std::size_t q) { return !gone[q]; });
      };
      std::stable_sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) { return missing(x) < missing(y); });
      for (std::size_t k : order) {
        bool ok = std::none_of(dirs[k].blockers.begin(), dirs[k].blockers.end(), [&](std::size_t q) { return is_fixed_[q]; });
        for (std::size_t q : dirs[k].blockers) ok = ok && take(q);
        const int d = ok ? freeing(p, gone) : -1;
        if (d >= 0) {
          out.parts.push_back(p);
          out.direction.push_back(d);
          gone[p] = true;
          visiting[p] = false;
          return true;
        }
      }
      visiting[p] = false;
      return false;
    };
    for (std::size_t t : o_.targets)
      if (!take(t)) return std::nullopt;
    return out;
  }

  // What both runs start with: the bodies and the fixed parts; with `contacts`, the
  // interferences of every pair and all the contacts at once (else the caller asks for what it
  // needs: contacts_of part by part, interferences of the pairs it moves).
  std::vector<bool> prepare(DisassemblyResult& out, bool contacts = true) {
    out.tolerance = settings_.tolerance;
    const std::size_t n = a_.parts.size();
    auto t0 = Clock::now();
    bodies_.resize(n);
    progress_.set("trees", 0, n);
    tbb::parallel_for(std::size_t{0}, n, [&](std::size_t i) {
      bodies_[i] = assembly_detail::make_body(a_, {i}, {});
      progress_.step("trees", n);
    });
    size_ = assembly_size(bodies_);
    out.time_ms.build = ms_since(t0);
    if (contacts) {
      t0 = Clock::now();
      out.interferences = assembly_detail::interferences(bodies_, settings_.tolerance, std::vector<bool>(n, true), &progress_);
      out.time_ms.interference = ms_since(t0);
    }
    out.fixed = fixed_parts();
    std::vector<bool> is_fixed(n, false);
    for (std::size_t i : out.fixed) is_fixed[i] = true;
    is_fixed_ = is_fixed;
    if (contacts) contacts_ = find_contacts(is_fixed);
    else contacts_.assign(n, {});
    return is_fixed;
  }

  const Assembly& a_;
  const DisassemblyOptions& o_;
  PullSettings settings_;
  // find_contacts is const and reports too.
  mutable assembly_detail::ProgressReporter progress_;
  std::vector<Body> bodies_;
  double size_ = 0.0;
  std::vector<std::vector<bool>> touching_;
  /// contacts_[i][j]: the triangles of the contact of part j (the obstacle) with movable part i at
  /// the mounted poses (contact::touching_facets), for pull_directions, which asks for
  /// them in every round.
  std::vector<std::vector<std::vector<contact::ContactFacet>>> contacts_;
  std::atomic<std::uint64_t> queries_{0};
  /// Pulls found blocked, per part: the direction, the length and the part that blocks it on its
  /// own. Removing other parts cannot clear it (the same pull meets the same pose), so while that
  /// part stays and the length is the same, the pull is not tried again. Each task of a round
  /// touches only its own part's list.
  struct BlockedPull {
    Vec3 direction;
    double length = 0;
    std::size_t by = 0;
  };
  std::vector<std::vector<BlockedPull>> blocked_pulls_;

  std::vector<std::size_t> fixed_parts() const {
    if (o_.fixed) return *o_.fixed;
    std::vector<std::size_t> out;
    for (std::size_t i = 0; i < a_.parts.size(); ++i)
      if (a_.parts[i].fixed) out.push_back(i);
    if (!out.empty() || a_.parts.empty()) return out;
    // The base: the part with the largest bounding box (the first of equals); a part alone is
    // the base, with nothing to take out of it.
    std::size_t best = 0;
    double volume = -1.0;
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
      const Vec3 e = (bodies_[i].box.max - bodies_[i].box.min).cwiseMax(Vec3::Zero());
      const double v = e.x() * e.y() * e.z();
      if (v > volume) volume = v, best = i;
    }
    return {best};
  }

  // Parts closer than clearance + tolerance at the mounted poses.
  std::vector<std::vector<bool>> contact_graph() const {
    const std::size_t n = bodies_.size();
    const double threshold = settings_.clearance + settings_.tolerance;
    std::vector<std::vector<bool>> g(n, std::vector<bool>(n, false));
    std::vector<std::pair<std::size_t, std::size_t>> pairs;
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = i + 1; j < n; ++j) pairs.push_back({i, j});
    std::vector<char> near(pairs.size(), 0);
    tbb::parallel_for(std::size_t{0}, pairs.size(), [&](std::size_t k) {
      const auto [i, j] = pairs[k];
      const DistanceResult d = distance(*bodies_[i].tree, bodies_[i].pose, *bodies_[j].tree, bodies_[j].pose, {.enough = threshold});
      near[k] = d.distance < threshold;
    });
    for (std::size_t k = 0; k < pairs.size(); ++k)
      if (near[k]) g[pairs[k].first][pairs[k].second] = g[pairs[k].second][pairs[k].first] = true;
    return g;
  }

  // The contact facets pull_directions needs, once: for every movable part and every other part
  // whose box comes within clearance + tolerance of its box, in parallel.
  std::vector<std::vector<std::vector<contact::ContactFacet>>> find_contacts(
      const std::vector<bool>& is_fixed) const {
    const std::size_t n = bodies_.size();
    const double threshold = settings_.clearance + settings_.tolerance;
    std::vector<std::vector<std::vector<contact::ContactFacet>>> out(
        n, std::vector<std::vector<contact::ContactFacet>>(n));
    std::vector<std::pair<std::size_t, std::size_t>> pairs;
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < n; ++j)
        if (i != j && !is_fixed[i] && contact::box_gap(bodies_[j].box, bodies_[i].box) <= threshold)
          pairs.push_back({i, j});
    progress_.set("contacts", 0, pairs.size());
    tbb::parallel_for(std::size_t{0}, pairs.size(), [&](std::size_t k) {
      const auto [i, j] = pairs[k];
      out[i][j] = contact::touching_facets(bodies_[j], bodies_[i], threshold);
      progress_.step("contacts", pairs.size());
    });
    return out;
  }

  // The known contact facets of a single part, for pull_directions.
  std::function<const std::vector<contact::ContactFacet>*(const Body&)> known_contacts(std::size_t part) const {
    return [this, part](const Body& o) { return &contacts_[part][static_cast<std::size_t>(&o - bodies_.data())]; };
  }

  // Connected groups of touching movable parts: each connected component (two parts or more),
  // then each touching pair, smallest first.
  std::vector<std::vector<std::size_t>> subassemblies(const std::vector<std::size_t>& movable) const {
    std::set<std::vector<std::size_t>> groups;
    std::set<std::size_t> seen;
    for (std::size_t start : movable) {
      if (seen.count(start)) continue;
      std::vector<std::size_t> component{start}, stack{start};
      seen.insert(start);
      while (!stack.empty()) {
        const std::size_t i = stack.back();
        stack.pop_back();
        for (std::size_t j : movable)
          if (touching_[i][j] && !seen.count(j)) seen.insert(j), component.push_back(j), stack.push_back(j);
      }
      std::sort(component.begin(), component.end());
      if (component.size() >= 2) groups.insert(component);
    }
    for (std::size_t x = 0; x < movable.size(); ++x)
      for (std::size_t y = x + 1; y < movable.size(); ++y)
        if (touching_[movable[x]][movable[y]]) groups.insert({movable[x], movable[y]});
    std::vector<std::vector<std::size_t>> out(groups.begin(), groups.end());
    std::stable_sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.size() < b.size(); });
    return out;
  }

  std::vector<const Body*> others(const std::vector<std::size_t>& group, const std::vector<std::size_t>& remaining) const {
    std::vector<const Body*> out;
    for (std::size_t i : remaining)
      if (std::find(group.begin(), group.end(), i) == group.end()) out.push_back(&bodies_[i]);
    return out;
  }

  double exit_margin() const { return settings_.clearance + 1e-3 * size_; }

  // Straight pulls along the directions of local freedom, the first clear one. `part`: the part
  // moving alone (its blocked pulls are remembered), or none for a group.
  Attempt try_pulls(const Body& moving, const std::vector<const Body*>& obstacles, std::optional<std::size_t> part,
                    const std::vector<std::size_t>& remaining) {
    Attempt at;
    const double threshold = settings_.clearance + settings_.tolerance;
    for (const Vec3& d : contact::pull_directions(moving, obstacles, threshold,
                                                          part ? known_contacts(*part) : nullptr)) {
      const double length = contact::exit_length(moving, obstacles, d, exit_margin());
      if (part) {
        bool known = false;
        for (const BlockedPull& b : blocked_pulls_[*part])
          known = known || (b.direction == d && b.length == length &&
                            std::find(remaining.begin(), remaining.end(), b.by) != remaining.end());
        if (known) continue;
      }
      const Body* blocker = nullptr;
      if (!contact::pull_is_clear(moving, obstacles, d, length, settings_, queries_, &blocker)) {
        if (part && blocker) blocked_pulls_[*part].push_back({d, length, static_cast<std::size_t>(blocker - bodies_.data())});
        continue;
      }
      at.removed = true;
      at.direction = d;
      at.distance = length;
      at.reference = moving.box.center();
      at.path.poses = {Pose{}, Pose::from_translation(length * d)};
      return at;
    }
    return at;
  }

  // The planner with the others as obstacles (part_problem), under the contact model.
  Attempt try_plan(const std::vector<std::size_t>& group, const std::vector<std::size_t>& remaining) {
    Attempt at;
    DisassemblyOptions o = o_;
    o.tolerance = settings_.tolerance;
    auto pp = part_problem(a_, group, remaining, o);
    if (!pp) return at;
    PlanOptions options;
    options.threads = 1;
    if (o_.plan_max_queries > 0) options.max_queries = o_.plan_max_queries;
    const PlanResult r = plan(pp->problem, pp->scene, options);
    queries_ += r.queries.distance;
    if (!r.solved()) return at;
    at.removed = true;
    at.method = RemovalMethod::plan;
    at.path = r.path;
    at.reference = pp->scene.reference;
    at.distance = r.path_length;
    return at;
  }

  std::optional<std::pair<std::vector<std::size_t>, Attempt>> first_removal(
      const std::vector<std::vector<std::size_t>>& candidates, const std::vector<std::size_t>& remaining, bool planner) {
    std::vector<Attempt> attempts(candidates.size());
    tbb::parallel_for(std::size_t{0}, candidates.size(), [&](std::size_t k) {
      const auto t0 = Clock::now();
      const std::vector<std::size_t>& group = candidates[k];
      if (planner) {
        attempts[k] = try_plan(group, remaining);
      } else if (group.size() == 1) {
        attempts[k] = try_pulls(bodies_[group[0]], others(group, remaining), group[0], remaining);
      } else {
        const Body body = assembly_detail::make_body(a_, group, {});
        attempts[k] = try_pulls(body, others(group, remaining), std::nullopt, remaining);
      }
      attempts[k].time_ms = ms_since(t0);
    });
    for (std::size_t k = 0; k < candidates.size(); ++k)
      if (attempts[k].removed) return std::make_pair(candidates[k], std::move(attempts[k]));
    return std::nullopt;
  }

  // For a part that stays: along each direction of local freedom, the parts that block a pull
  // on their own (the directional blocking graph, Wilson & Latombe 1994), in index order. With
  // `fixed_first` the fixed parts are tried first, and a direction one of them blocks lists the
  // fixed parts that block it and nothing else (it can never be freed).
  SequenceStep blocking_of(std::size_t part, const std::vector<std::size_t>& remaining, int round,
                           bool fixed_first = false) {
    SequenceStep s;
    s.parts = {part};
    s.round = round;
    const auto t0 = Clock::now();
    const std::vector<const Body*> obstacles = others({part}, remaining);
    const Body& moving = bodies_[part];
    const double threshold = settings_.clearance + settings_.tolerance;
    std::vector<std::size_t> order;
    for (std::size_t i : remaining)
      if (i != part) order.push_back(i);
    if (fixed_first) std::stable_partition(order.begin(), order.end(), [&](std::size_t i) { return is_fixed_[i]; });
    const std::vector<Vec3> directions = contact::pull_directions(moving, obstacles, threshold, known_contacts(part));
    s.blocking.resize(directions.size());
    // Directions are independent: each task fills its own entry.
    tbb::parallel_for(std::size_t{0}, directions.size(), [&](std::size_t k) {
      const Vec3& d = directions[k];
      const double length = contact::exit_length(moving, obstacles, d, exit_margin());
      SequenceStep::Blocking b{d, {}};
      bool by_fixed = false;
      for (std::size_t i : order) {
        if (by_fixed && !is_fixed_[i]) break;
        if (!contact::pull_is_clear(moving, {&bodies_[i]}, d, length, settings_, queries_)) {
          b.blockers.push_back(i);
          by_fixed = by_fixed || (fixed_first && is_fixed_[i]);
        }
      }
      std::sort(b.blockers.begin(), b.blockers.end());
      s.blocking[k] = std::move(b);
    });
    s.time_ms = ms_since(t0);
    return s;
  }
};

}  // namespace

Result<PartProblem> part_problem(const Assembly& assembly, const std::vector<std::size_t>& group,
                                 const std::vector<std::size_t>& present, const DisassemblyOptions& options) {
  TriangleSoup obstacles, body;
  auto add = [](TriangleSoup& to, const TriangleSoup& from) {
    append_placed(to, from);
    to.name += (to.name.empty() ? "" : "+") + from.name;
  };
  for (std::size_t i : present) {
    const bool moving = std::find(group.begin(), group.end(), i) != group.end();
    add(moving ? body : obstacles, assembly.parts[i].mesh);
  }
  if (obstacles.triangles.empty()) return Error{"no part stays in place: there is nothing to take it out of"};
  if (body.triangles.empty()) return Error{"no part to move"};
  Aabb box = bounds(body.triangles);
  auto scene = make_scene(std::move(obstacles), std::move(body), {}, box.center());
  if (!scene) return scene.error();
  PartProblem out{{}, std::move(*scene)};
  Problem& p = out.problem;
  p.source = assembly.source;
  p.unit = assembly.unit;
  p.start = Pose{};
  p.goal_outside = true;
  p.clearance = options.clearance;
  p.contact_tolerance = options.tolerance > 0 ? options.tolerance : 2.0 * ImportOptions{}.linear_deflection;
  p.rotation = RotationMode::free;
  p.time_limit = options.plan_time_limit > 0 ? options.plan_time_limit : p.time_limit;
  p.threads = 1;
  return out;
}

Result<std::size_t> find_part(const Assembly& assembly, const std::string& name) {
  for (std::size_t i = 0; i < assembly.parts.size(); ++i)
    if (assembly.parts[i].name == name) return i;
  std::string known;
  for (const AssemblyPart& part : assembly.parts) known += (known.empty() ? "" : ", ") + part.name;
  return Error{assembly.source.string() + ": no part named '" + name + "' (its parts: " + known + ")"};
}

DisassemblyResult disassemble(const Assembly& assembly, const DisassemblyOptions& options) {
  const double tolerance = options.tolerance > 0 ? options.tolerance : 2.0 * ImportOptions{}.linear_deflection;
  tbb::task_arena arena(options.jobs > 0 ? options.jobs : tbb::task_arena::automatic);
  DisassemblyResult out;
  arena.execute([&] {
    Sequencer sequencer(assembly, options, tolerance);
    out = options.targets.empty() ? sequencer.run() : sequencer.run_target();
  });
  return out;
}

}  // namespace swept
