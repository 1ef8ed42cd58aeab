// Threads are passed in: plan() runs in its own task arena (or the caller's), and the path does
// not depend on which.
#include "plan/plan_support.h"

#include <tbb/task_arena.h>

namespace swept {
namespace {

using namespace swept::test;

TEST(PlannerThreads, CallersArenaGivesTheSamePath) {
  const auto g = scenes::l_tunnel();
  const PlanScene s = scene_of(g);
  PlanOptions two;
  two.threads = 2;
  const PlanResult reference = plan(g.problem, s, two);
  ASSERT_TRUE(reference.solved()) << reference.message;
  tbb::task_arena one_thread(1);
  PlanOptions in_arena;
  in_arena.arena = &one_thread;
  in_arena.threads = 3;  // not used with an arena
  const PlanResult r = plan(g.problem, s, in_arena);
  ASSERT_TRUE(r.solved()) << r.message;
  EXPECT_EQ(r.path_hash, reference.path_hash);
  // Nothing process-wide changed: the default arena still has every core.
  EXPECT_EQ(tbb::this_task_arena::max_concurrency(), tbb::task_arena(tbb::task_arena::automatic).max_concurrency());
}

TEST(PlannerThreads, QueriesAreCountedByKind) {
  const auto g = scenes::l_tunnel();
  const PlanScene s = scene_of(g);
  const PlanResult r = plan(g.problem, s);
  ASSERT_TRUE(r.solved()) << r.message;
  EXPECT_GT(r.queries.distance, 0u);
  EXPECT_EQ(r.queries.proximity, 0u);  // no start in contact
}

}  // namespace
}  // namespace swept
