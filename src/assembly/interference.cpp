// Interferences at the mounted poses (disassemble.h): parts that overlap by more than the mating
// tolerance, found before any part is moved.
#include "bodies.h"
#include "swept/assembly/disassemble.h"

#include "swept/geometry/distance.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <optional>

namespace swept {

std::vector<Interference> find_interferences(const Assembly& assembly, double tolerance) {
  const std::size_t n = assembly.parts.size();
  std::vector<contact::Body> bodies(n);
  tbb::parallel_for(std::size_t{0}, n, [&](std::size_t i) { bodies[i] = assembly_detail::make_body(assembly, {i}, {}); });
  return assembly_detail::interferences(bodies, tolerance, std::vector<bool>(n, true));
}

void assembly_detail::ProgressReporter::step(const char* phase, std::size_t total) {
  if (!sink_) return;
  const std::lock_guard lock(mutex_);
  if (!phase_ || std::strcmp(phase, phase_) != 0) phase_ = phase, done_ = 0, last_s_ = -1.0;
  ++done_;
  report_locked(total);
}

void assembly_detail::ProgressReporter::set(const char* phase, std::size_t done, std::size_t total) {
  if (!sink_) return;
  const std::lock_guard lock(mutex_);
  if (!phase_ || std::strcmp(phase, phase_) != 0) phase_ = phase, last_s_ = -1.0;
  done_ = done;
  report_locked(total);
}

void assembly_detail::ProgressReporter::report_locked(std::size_t total) {
  const double now = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  if (done_ < total && last_s_ >= 0.0 && now - last_s_ < 0.1) return;
  last_s_ = now;
  sink_(DisassemblyProgress{.phase = phase_, .done = done_, .total = total, .elapsed_s = now});
}

std::vector<Interference> assembly_detail::interferences(const std::vector<contact::Body>& bodies, double tolerance,
                                                         const std::vector<bool>& among, ProgressReporter* progress) {
  const std::size_t n = bodies.size();
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      if (!among[i] && !among[j]) continue;
      const Aabb& a = bodies[i].box;
      const Aabb& b = bodies[j].box;
      if ((a.min.array() <= b.max.array()).all() && (b.min.array() <= a.max.array()).all()) pairs.push_back({i, j});
    }
  std::vector<std::optional<Interference>> found(pairs.size());
  if (progress) progress->set("interferences", 0, pairs.size());
  tbb::parallel_for(std::size_t{0}, pairs.size(), [&](std::size_t k) {
    struct Done {
      ProgressReporter* progress;
      std::size_t total;
      ~Done() { if (progress) progress->step("interferences", total); }
    } done{progress, pairs.size()};
    const auto [i, j] = pairs[k];
    const contact::Body& a = bodies[i];
    const contact::Body& b = bodies[j];
    const CollideResult c = collide(*a.tree, a.pose, *b.tree, b.pose, {.all_contacts = true});
    Interference f{i, j};
    Aabb where;
    // A shaft in its bore: the CAD's cylinders, not their facets, tell whether they cross.
    const auto cylinders = contact::cylinder_mates(a, b, Vec3::UnitZ(), 0.0, tolerance);
    for (const ContactPair& p : c.contacts) {
      const Triangle& ta = a.triangles[p.triangle_a];
      const Triangle& tb = b.triangles[p.triangle_b];
      const double overlap = pair_overlap(ta, a.planes[p.triangle_a], tb, b.planes[p.triangle_b]);
      if (!(overlap > tolerance) || !std::isfinite(overlap)) continue;  // degenerate pairs have no depth
      if (!cylinders.empty() &&
          contact::cylinder_mate_allows(cylinders, a, p.triangle_a, b, p.triangle_b, tolerance))
        continue;
      ++f.triangle_pairs;
      f.depth = std::max(f.depth, overlap);
      const TriangleDistance d = triangle_distance(ta, tb);
      where.extend(d.point_a);
    }
    if (f.triangle_pairs == 0) return;
    f.extent = where.extent();
    found[k] = f;
  });
  std::vector<Interference> out;
  for (const auto& f : found)
    if (f) out.push_back(*f);
  return out;
}

}  // namespace swept
