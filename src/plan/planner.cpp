// The planner's driver (SPEC §4; docs/planner.md): checks the problem against its search space,
// escapes from a start in contact, then runs the phases in order — straight moves, lazy A* on
// the multi-resolution grid (Bohlin & Kavraki 2000; Bohlin 2001) with a budget, trees from both
// ends on a Halton sequence (Kuffner & LaValle 2000; Janson, Ichter & Pavone 2018), shortcut
// smoothing — every
// motion certified (Schwarzer, Saha & Latombe 2005), and ends with the final certification of
// the whole path (check_path.cpp). Each phase is its own file; this one only sequences them.
//
// Determinism: no randomness, no clocks or addresses in decisions, ordered containers where
// order matters; the work done in parallel (the trees' rounds, the final certification) is
// consumed in a fixed order.
#include "swept/plan/planner.h"

#include "checker.h"
#include "contact_moves.h"
#include "escape.h"
#include "grid.h"
#include "lazy_astar.h"
#include "plan_context.h"
#include "smoothing.h"
#include "straight_moves.h"
#include "tree_search.h"
#include "swept/geometry/assert.h"
#include "swept/plan/check.h"
#include "swept/plan/search_space.h"

#include <tbb/task_arena.h>
#include <tbb/task_group.h>

#include <atomic>
#include <optional>
#include <sstream>
#include <vector>

namespace swept {
namespace {

using detail::Checker;
using detail::Clock;
using detail::ContactMoves;
using detail::PlanContext;

// Expansions the grid's levels may spend without running out of nodes before the trees take
// over. The axis-aligned narrow passages it is good at are solved within it: the hooks at 1.1
// and 1.2 at level 0 in 8 expansions (where the trees take 0.7 s), the air cleaner in 54 (the box
// problems and the hooks at 1.5 are straight moves). On the rest of the suite and the scenes (the
// house, the cubicles, the traps, the twisty slot, the spiral tube, the cylinder head, the tunnel
// console) it finds nothing within any budget tried, and its expansions only keep a core from the
// trees: 64 against 150 gives the same paths everywhere and the trees that core sooner. Larger
// budgets held the trees back more (500 against 150: 5–20 % more search time; 2000: 0.1–3 s
// more), and 50 left the air cleaner to the trees (2.9× slower). docs/lab/bench-plan-history.md.
constexpr std::size_t kGridBudget = 64;

// Coordinates far beyond the scene lose the precision the distance bounds rely on (a query at
// 1e100 visits every pair and takes seconds, so no time limit holds): the bounds, the start,
// the goal and the goal region must stay within 10^6 scene sizes. The reason when they do not.
std::optional<std::string> too_far_apart(const PlanContext& context) {
  const Problem& problem = context.problem;
  const double size = context.scene_size();
  Aabb reach = context.space.bounds;
  reach.extend(context.scene.obstacle_box);
  reach.extend(context.space.goal_box);
  reach.extend(context.reference_at(problem.start));
  if (problem.goal) reach.extend(context.reference_at(*problem.goal));
  const double across = (reach.max - reach.min).maxCoeff();
  if (across <= 1e6 * size) return std::nullopt;
  std::ostringstream os;
  os << "the bounds, start, goal and goal margin span " << across << " " << problem.unit << ", more than 10^6 times the scene's size ("
     << size << " " << problem.unit << "): coordinates that far apart lose the precision the certificate needs; check [bounds], "
     << "[start], [goal] and goal.margin";
  return os.str();
}

PlanResult run_planner(const Problem& problem, const PlanScene& scene, const PlanOptions& options) {
  const Clock::time_point started = Clock::now();
  const SearchSpace space = search_space(problem, scene);
  Checker check(scene, problem.clearance);
  PlanContext context{problem, scene, space, check, options, started, options.time_limit.value_or(problem.time_limit)};
  const double margin = problem.clearance;
  const double size = context.scene_size();

  PlanResult r;
  std::size_t nodes_known = 0;  // grid nodes known to the search
  std::uint64_t proximity_queries = 0;
  std::optional<ContactMoves> contact;           // the contact layer, once a pose in contact asks for it
  auto contact_sweeps = [&]() -> std::uint64_t { return contact ? contact->sweeps() : 0; };
  std::atomic<std::size_t>* searched = nullptr;  // the search's edges, once it runs
  auto edges_searched = [&]() -> std::size_t { return searched ? searched->load() : 0; };
  auto fail = [&](PlanStatus s, std::string msg) {
    r.status = s;
    r.message = std::move(msg);
    r.nodes_checked = nodes_known;
    r.edges_checked = context.edges_checked + edges_searched();
    r.queries.distance = check.distance_queries();
    r.queries.proximity = proximity_queries;
    r.queries.sweep = check.sweeps() + contact_sweeps();
    r.time_ms.total = context.elapsed_s() * 1e3;
    if (r.time_ms.search == 0.0) r.time_ms.search = r.time_ms.total;
    return r;
  };
  if (auto why = too_far_apart(context)) return fail(PlanStatus::invalid_bounds, *why);
  if (!in_bounds(space, context.reference_at(problem.start)))
    return fail(PlanStatus::invalid_start, "the start's reference point is outside the bounds");
  if (problem.goal && !in_bounds(space, context.reference_at(*problem.goal)))
    return fail(PlanStatus::invalid_goal, "the goal's reference point is outside the bounds");
  if (problem.goal_outside) {
    // The region must be reachable inside the bounds.
    bool reachable = false;
    for (int i = 0; i < 3; ++i)
      reachable = reachable || space.bounds.max[i] - space.radius > space.goal_box.max[i] ||
                  space.bounds.min[i] + space.radius < space.goal_box.min[i];
    if (!reachable) return fail(PlanStatus::invalid_goal, "the goal region (outside the obstacles' box) lies outside the bounds");
  }
  check.set_deadline(started + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(context.time_limit_s)));
  Pose start = problem.start;
  std::vector<Pose> prefix{problem.start};  // the start and its way out of contact
  std::vector<Pose> suffix;                 // the goal's way out of contact, played backwards (the approach)
  auto contact_moves = [&]() -> const ContactMoves& {
    if (!contact) contact.emplace(scene, margin, problem.contact_tolerance);
    return *contact;
  };
  auto in_contact_message = [&](const char* which, double d) {
    std::ostringstream os;
    os << "the " << which << " pose is " << (d <= 0 ? "in collision with" : "closer than the clearance to")
       << " the obstacles (distance " << d << ", clearance " << margin << "); set planner.contact_tolerance for a part "
       << (which[0] == 's' ? "that starts" : "that ends") << " in contact";
    return os.str();
  };
  double start_distance = check.clearance(start, margin + 0.05 * size);
  Problem inner = problem;  // the search's problem: its goal is the end of the approach
  if (problem.goal) {
    const double dg = check.clearance(*problem.goal, margin);
    if (dg > margin) {
      if (auto inside = enclosure_at(scene, *problem.goal)) return fail(PlanStatus::invalid_goal, "the goal pose is in collision: " + *inside);
    } else {
      if (problem.contact_tolerance <= 0.0) return fail(PlanStatus::invalid_goal, in_contact_message("goal", dg));
      const auto away = detail::escape_from_contact(context, contact_moves(), *problem.goal);
      if (!away)
        return fail(context.out_of_time() ? PlanStatus::no_path_time : PlanStatus::no_path_resolution,
                    "the goal is in contact and no straight approach (one pull, or a slide then a pull, along the contact "
                    "normals, the world axes, the body's axes or toward the start) reaches it from a pose with the full "
                    "clearance under the mate rule");
      suffix.assign(away->rbegin(), away->rend());
      suffix.push_back(*problem.goal);
      inner.goal = suffix.front();
    }
  }
  if (start_distance > margin) {
    if (auto inside = enclosure_at(scene, start)) return fail(PlanStatus::invalid_start, "the start pose is in collision: " + *inside);
  } else {
    if (problem.contact_tolerance <= 0.0) return fail(PlanStatus::invalid_start, in_contact_message("start", start_distance));
    const auto away = detail::escape_from_contact(context, contact_moves(), start);
    if (!away) {
      return fail(context.out_of_time() && check.cap_refusals() == 0 ? PlanStatus::no_path_time : PlanStatus::no_path_resolution,
                  "the body starts in contact and no straight escape (one pull, or a slide then a pull, along the contact "
                  "normals, the world axes, the body's axes or toward the goal) reaches a pose with the full clearance "
                  "under the mate rule");
    }
    prefix.insert(prefix.end(), away->begin(), away->end());
    start = prefix.back();
    start_distance = check.clearance(start, margin + 0.05 * size);
  }
  // The search runs toward the end of the approach.
  PlanContext search{inner, scene, space, check, options, started, context.time_limit_s};
  searched = &search.edges_checked;

  // From here on the search only asks whether a blocked pose is blocked (the messages above
  // report exact distances): its queries stop at the first pair closer than the margin.
  check.set_decide_blocked(true);
  // The search: straight moves, then the grid anchored at the search start.
  const detail::Grid grid(space, problem.start, start, margin, size);
  detail::LazyGridSearch grid_search(search, grid, start, start_distance);
  nodes_known = grid_search.nodes_known();
  std::vector<Pose> path;
  bool found = false;
  if (goal_reached(space, inner, start)) {
    path = {start};
    found = true;
    r.level = -1;
  }
  // Phases 1–3: straight moves; the grid, with its budget; the trees from both ends, until the
  // time limit. The first phase with a path gives the plan. With two cores or more and no query
  // budget the trees do not wait for the others: they grow while the straight moves and then
  // the grid search (whose work is mostly serial: one core idles), and stop — within the query
  // they are at, a join's included — once those have found a path or the grid has decided there
  // is none. The trees do not depend on when they run, so the path is the one the phases give
  // in turn, which they do at one thread, and under a query budget (whose count must not depend
  // on another phase).
  detail::GridOutcome outcome = detail::GridOutcome::resolution;
  if (!found) {
    std::atomic<bool> stop_trees{false};
    std::optional<std::vector<Pose>> tree_path;
    detail::TreeOutcome tree_outcome = detail::TreeOutcome::time_limit;
    std::size_t tree_nodes = 0;
    std::optional<double> goal_distance;
    auto grow_trees = [&] {
      detail::TreeSearch trees(search, start, start_distance, *goal_distance);
      trees.set_cancel(&stop_trees);
      tree_path = trees.run(tree_outcome);
      tree_nodes = trees.nodes();
    };
    const bool beside = !options.max_queries && tbb::this_task_arena::max_concurrency() >= 2;
    tbb::task_group beside_trees;
    if (beside) {
      goal_distance = inner.goal ? check.clearance(*inner.goal, margin + 0.05 * size) : 0.0;
      beside_trees.run(grow_trees);
    }
    // Isolated: while this thread waits inside the straight moves' or the grid's parallel work,
    // it takes no task of the trees beside them (it would have to finish it before going on).
    std::optional<std::vector<Pose>> cells;
    tbb::this_task_arena::isolate([&] {
      if (auto moves = detail::straight_moves(search, start, start_distance)) {
        path = std::move(*moves);
        found = true;
        r.level = -1;
      }
      if (!found && !search.out_of_time()) cells = grid_search.run(outcome, kGridBudget);
    });
    const bool trees_needed = !found && !cells && outcome == detail::GridOutcome::resolution;
    if (beside) {
      if (!trees_needed) stop_trees = true;
      beside_trees.wait();
    } else if (trees_needed && !search.out_of_time()) {
      goal_distance = inner.goal ? check.clearance(*inner.goal, margin + 0.05 * size) : 0.0;
      grow_trees();
    }
    if (!found) {  // else straight moves gave the path: the grid's and the trees' are not used
      r.level = grid_search.level_reached();
      if (cells) {
        path = std::move(*cells);
        found = true;
      } else if (outcome == detail::GridOutcome::resolution) {
        r.tree_nodes = tree_nodes;
        if (tree_path) {
          path = std::move(*tree_path);
          found = true;
          r.level = kTreeLevel;
        } else if (tree_outcome == detail::TreeOutcome::time_limit) {
          outcome = detail::GridOutcome::time_limit;
        } else if (tree_outcome == detail::TreeOutcome::budget) {
          outcome = detail::GridOutcome::budget;
        }
      }
    }
  }
  const double t_search = search.elapsed_s();
  r.time_ms.search = t_search * 1e3;
  nodes_known = grid_search.nodes_known();
  if (!found) {
    PlanStatus why = outcome == detail::GridOutcome::time_limit  ? PlanStatus::no_path_time
                     : outcome == detail::GridOutcome::budget    ? PlanStatus::no_path_budget
                     : outcome == detail::GridOutcome::exhausted ? PlanStatus::no_path_bounds
                                                                 : PlanStatus::no_path_resolution;
    // The budget, checked where the count is the same on every run, names the stop whenever it
    // was reached: a run that also ran out of time says the same.
    if (search.over_budget()) why = PlanStatus::no_path_budget;
    else if (search.out_of_time()) why = PlanStatus::no_path_time;
    std::ostringstream os;
    if (const std::uint64_t refused = check.cap_refusals(); refused > 0) {
      // The limiting factor was the resolution of the certificate, whatever the clock says.
      os << "no path found: " << refused << " motion" << (refused == 1 ? " grazes" : "s graze")
         << " the clearance too closely to certify (more than " << kMaxCertificateQueries
         << " distance queries each; a smaller clearance or a wider passage helps)";
      if (why == PlanStatus::no_path_time) os << ", and the search then reached the time limit of " << search.time_limit_s << " s";
      if (why == PlanStatus::no_path_budget) os << ", and the search then reached its budget of " << *options.max_queries << " distance queries";
      return fail(PlanStatus::no_path_resolution, os.str());
    }
    switch (why) {
      case PlanStatus::no_path_time: os << "no path found within the time limit of " << search.time_limit_s << " s"; break;
      case PlanStatus::no_path_budget:
        os << "no path found within the budget of " << *options.max_queries << " distance queries";
        break;
      case PlanStatus::no_path_bounds:
        os << "no path exists inside the bounds and rotation limits at the grid resolutions searched (finest step "
           << grid.fine_step() << " " << problem.unit << ")";
        break;
      default: os << "no path found down to the finest grid resolution (step " << grid.fine_step() << " " << problem.unit << ")"; break;
    }
    return fail(why, os.str());
  }
  // Smoothing between the way out of contact and the approach (which stay as they are).
  detail::smooth(search, path, 0);
  std::vector<Pose> full = prefix;
  full.insert(full.end(), path.begin() + 1, path.end());
  if (!suffix.empty()) full.insert(full.end(), suffix.begin() + 1, suffix.end());
  const std::size_t escape_segments = prefix.size() - 1, approach_segments = suffix.empty() ? 0 : suffix.size() - 1;
  r.time_ms.smooth = (search.elapsed_s() - t_search) * 1e3;

  // Final certification of every segment and the smallest distance along the path, by the
  // same function `swept check` runs (check_path.cpp), whatever the time.
  const PathCheckResult final_check = check_path(problem, scene, Path{full});
  if (!final_check.valid)
    return fail(PlanStatus::no_path_resolution, "internal: the found path failed its final certification: " + final_check.message);
  if (final_check.contact_segments != escape_segments + approach_segments)
    return fail(PlanStatus::no_path_resolution, "internal: the final certification disagrees on the motions in contact");
  r.escape_segments = escape_segments;
  r.approach_segments = approach_segments;
  r.status = PlanStatus::solved;
  r.path.poses = std::move(full);
  for (std::size_t i = 0; i + 1 < r.path.poses.size(); ++i) {
    const Pose& a = r.path.poses[i];
    const Pose& b = r.path.poses[i + 1];
    r.translation_length += (context.reference_at(b) - context.reference_at(a)).norm();
    r.rotation_length += rotation_angle(a.rotation, b.rotation);
    r.path_length += check.length(a, b);
  }
  r.min_clearance = final_check.min_clearance;
  r.path_hash = path_hash(r.path);
  r.nodes_checked = nodes_known;
  r.edges_checked = context.edges_checked + search.edges_checked;
  r.queries.distance = check.distance_queries() + final_check.distance_queries;
  r.queries.proximity = proximity_queries;
  r.queries.sweep = check.sweeps() + contact_sweeps() + final_check.sweeps;
  r.time_ms.total = context.elapsed_s() * 1e3;
  std::ostringstream os;
  os << "solved"
     << (r.level == kTreeLevel ? " by the trees from both ends"
         : r.level < 0         ? " by straight moves"
                               : " on the grid at level " + std::to_string(r.level))
     << ": "
     << r.path.poses.size() << " waypoints";
  r.message = os.str();
  return r;
}

}  // namespace

PlanResult plan(const Problem& problem, const PlanScene& scene, const PlanOptions& options) {
  auto run = [&] {
    PlanResult r = run_planner(problem, scene, options);
    r.time_ms.build = scene.build_ms;
    r.time_ms.total += scene.build_ms;
    return r;
  };
  if (options.arena) return options.arena->execute(run);
  // The parallel work runs in an arena of the requested size, not under a process-wide limit.
  const int threads = options.threads.value_or(problem.threads);
  SWEPT_ASSERT(threads >= 0, "PlanOptions::threads must be ≥ 0 (0: all cores)");
  tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
  return arena.execute(run);
}

}  // namespace swept
