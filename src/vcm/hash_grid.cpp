#include "vcm/hash_grid.h"

namespace relt {

void HashGrid::build(std::span<const Vec3> points, float radius) {
  radius2_ = radius * radius;
  inverseCell_ = 1.0f / (2.0f * radius);
  Bounds3 bounds;
  for (const Vec3& p : points) bounds.extend(p);
  lo_ = bounds.empty() ? Vec3(0.0f) : bounds.lo;
  // As many buckets as points: a counting sort by bucket.
  const size_t buckets = std::max<size_t>(points.size(), 1);
  start_.assign(buckets + 1, 0);
  std::vector<uint32_t> bucket(points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    const Vec3 cell = glm::floor((points[i] - lo_) * inverseCell_);
    bucket[i] = bucketOf(int64_t(cell.x), int64_t(cell.y), int64_t(cell.z));
    ++start_[bucket[i] + 1];
  }
  for (size_t b = 0; b < buckets; ++b) start_[b + 1] += start_[b];
  order_.resize(points.size());
  std::vector<uint32_t> next(start_.begin(), start_.end() - 1);
  for (size_t i = 0; i < points.size(); ++i) order_[next[bucket[i]]++] = uint32_t(i);
  sorted_.resize(points.size());
  for (size_t k = 0; k < points.size(); ++k) sorted_[k] = points[order_[k]];
}

}  // namespace relt
