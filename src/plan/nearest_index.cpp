// The trees' nearest-node index (nearest_index.h).
#include "nearest_index.h"

#include <algorithm>
#include <numeric>

namespace swept::detail {
namespace {

constexpr std::uint32_t kLeaf = 8;          // nodes in a cell that is not split
constexpr std::size_t kScannedShare = 16;  // the k-d tree is rebuilt past size / 16 scanned nodes
constexpr std::size_t kScannedMin = 64;    // ... and past this many

}  // namespace

void NearestIndex::add(const Vec3& point, const Quat& rotation) {
  // q and −q are one rotation: keys on the half w ≥ 0 (the bound takes both signs of the query).
  const double s = rotation.w() < 0.0 ? -2.0 * radius_ : 2.0 * radius_;
  keys_.push_back({point.x(), point.y(), point.z(), s * rotation.w(), s * rotation.x(), s * rotation.y(), s * rotation.z()});
  rotations_.push_back(rotation);
  if (keys_.size() - indexed_ > std::max(kScannedMin, keys_.size() / kScannedShare)) rebuild();
}

void NearestIndex::rebuild() {
  indexed_ = keys_.size();
  order_.resize(indexed_);
  std::iota(order_.begin(), order_.end(), 0U);
  cells_.clear();
  cells_.reserve(2 * indexed_ / kLeaf + 2);
  build(0, static_cast<std::uint32_t>(indexed_));
}

std::int32_t NearestIndex::build(std::uint32_t begin, std::uint32_t end) {
  const auto id = static_cast<std::int32_t>(cells_.size());
  Cell cell;
  cell.begin = begin;
  cell.end = end;
  cell.lo.fill(std::numeric_limits<double>::infinity());
  cell.hi.fill(-std::numeric_limits<double>::infinity());
  for (std::uint32_t k = begin; k < end; ++k)
    for (int d = 0; d < 7; ++d) {
      cell.lo[d] = std::min(cell.lo[d], keys_[order_[k]][d]);
      cell.hi[d] = std::max(cell.hi[d], keys_[order_[k]][d]);
    }
  cells_.push_back(cell);
  if (end - begin <= kLeaf) return id;
  int axis = 0;
  for (int d = 1; d < 7; ++d)
    if (cell.hi[d] - cell.lo[d] > cell.hi[axis] - cell.lo[axis]) axis = d;
  const std::uint32_t mid = begin + (end - begin) / 2;
  // Ties by index make the build reproducible; the answers do not depend on the tree's shape.
  std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end, [&](std::uint32_t a, std::uint32_t b) {
    return keys_[a][axis] < keys_[b][axis] || (keys_[a][axis] == keys_[b][axis] && a < b);
  });
  const std::int32_t left = build(begin, mid);
  const std::int32_t right = build(mid, end);
  cells_[id].left = left;
  cells_[id].right = right;
  return id;
}

}  // namespace swept::detail
