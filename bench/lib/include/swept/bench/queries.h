#pragma once
/// `swept bench queries A B` as a library: collide / distance / tolerance timings of swept's RSS
/// trees (one per fitter of all_fitters()) and FCL's OBBRSS and RSS trees, side by side in the
/// same run, on the seeded pose sets of pose_sets.h (overlapping, near contact, far), and the
/// speed-up of a distance batch on two threads.
#include "swept/bvh/bvh.h"

#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

namespace swept::bench {

struct QueriesOptions {
  std::string file_a, file_b;
  int poses = 100;         ///< per pose set
  std::uint64_t seed = 1;  ///< of the pose sets
  bool json = false;       ///< one JSON document on `out` instead of the table
  /// Leaf sizes to build every fitter's trees with (each a row of its own; the first one's
  /// INERTIA_FIT trees draw the pose sets and are the reference of the comparison with FCL).
  std::vector<int> leaf_sizes{kDefaultLeafSize};
  SplitRule split = SplitRule::min_sa;
};

/// Runs the benchmark: the table (or JSON) on `out`, the batch line of the JSON mode on `log`.
/// Throws std::runtime_error on unreadable files, empty meshes or pose sets it cannot fill.
void run_queries_benchmark(const QueriesOptions& o, std::ostream& out, std::ostream& log);

}  // namespace swept::bench
