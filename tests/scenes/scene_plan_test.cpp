// Every built-in scene at test scale is solved by the planner, and the path is checked by the
// oracle of tests/oracle (no code shared with swept): its own certificate of every segment,
// dense exact distances, and the planner's reported minimum against them.
#include "plan/plan_support.h"
#include "swept/scenes/scenes.h"

#include <filesystem>
#include <unistd.h>

namespace swept {
namespace {

namespace fs = std::filesystem;

TEST(ScenePlan, EveryTestScaleSceneIsSolved) {
  const fs::path dir = fs::temp_directory_path() / ("swept_scene_plan_" + std::to_string(::getpid()));
  for (const auto& info : scenes::catalog()) {
    auto report = scenes::generate_scene({.name = info.name, .scale = scenes::Scale::test, .output_dir = dir / info.name});
    ASSERT_TRUE(report) << report.error().message;
    auto problem = load_problem(report->problem_file);
    ASSERT_TRUE(problem) << problem.error().message;
    auto scene = load_scene(*problem, problem->build);
    ASSERT_TRUE(scene) << scene.error().message;
    const PlanResult r = plan(*problem, *scene);
    ASSERT_TRUE(r.solved()) << info.name << ": " << r.message;
    std::printf("%s: %zu waypoints, %.0f ms, %llu distance queries, min clearance %.3f\n", info.name.c_str(),
                r.path.poses.size(), r.time_ms.total, static_cast<unsigned long long>(r.queries.distance), r.min_clearance);
    SCOPED_TRACE(info.name);
    test::check_independently(*scene, *problem, r);
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace swept
