#pragma once
// The range search of vertex merging: the light vertices of one iteration in a hashed grid of cells
// twice the merging radius wide, so the points within the radius of any position lie in the 2x2x2
// cells nearest it (Georgiev et al. 2012's SmallVCM does the same). Rebuilt every iteration.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "core/math.h"

namespace relt {

class HashGrid {
 public:
  // Indexes `points` (copied, in bucket order) for queries within `radius`.
  void build(std::span<const Vec3> points, float radius);

  // Calls found(i) for every point i within the radius of p (distance <= radius), in no
  // particular order but the same for the same points and p.
  template <class Found>
  void forEachNear(const Vec3& p, Found&& found) const {
    forEachSlotNear(p, [&](uint32_t slot) { found(order_[slot]); });
  }
  // The same, naming each point by its slot: its place in bucket order. A caller that keeps its
  // points' data in slot order (order()) reads neighbours side by side instead of chasing them.
  template <class Found>
  void forEachSlotNear(const Vec3& p, Found&& found) const {
    if (sorted_.empty()) return;
    const Vec3 cell = (p - lo_) * inverseCell_;
    const Vec3 base = glm::floor(cell);
    // The neighbour on each axis is on the side of p within its cell.
    const int step[3] = {cell.x - base.x < 0.5f ? -1 : 1, cell.y - base.y < 0.5f ? -1 : 1, cell.z - base.z < 0.5f ? -1 : 1};
    uint32_t seen[8];
    for (int k = 0; k < 8; ++k) {
      const int64_t x = int64_t(base.x) + ((k & 1) ? step[0] : 0), y = int64_t(base.y) + ((k & 2) ? step[1] : 0),
                    z = int64_t(base.z) + ((k & 4) ? step[2] : 0);
      const uint32_t bucket = bucketOf(x, y, z);
      seen[k] = bucket;
      if (std::find(seen, seen + k, bucket) != seen + k) continue;  // two cells hashed alike: once
      for (uint32_t i = start_[bucket]; i < start_[bucket + 1]; ++i) {
        const Vec3 d = sorted_[i] - p;  // most candidates are farther: scanned in a row
        if (glm::dot(d, d) <= radius2_) found(i);
      }
    }
  }
  // order()[slot]: the index in `points` of the point in that slot.
  std::span<const uint32_t> order() const { return order_; }
  // The items of the indexed points (items[i] is point i's) copied into slot order, for
  // forEachSlotNear's callers.
  template <class T>
  void gatherBySlot(std::span<const T* const> items, std::vector<T>& bySlot) const {
    bySlot.resize(order_.size());
    for (size_t slot = 0; slot < order_.size(); ++slot) bySlot[slot] = *items[order_[slot]];
  }

 private:
  uint32_t bucketOf(int64_t x, int64_t y, int64_t z) const {
    const uint64_t h = (uint64_t(x) * 73856093u) ^ (uint64_t(y) * 19349663u) ^ (uint64_t(z) * 83492791u);
    return uint32_t(h % uint64_t(start_.size() - 1));
  }

  Vec3 lo_{0.0f};
  float inverseCell_ = 0.0f, radius2_ = 0.0f;
  std::vector<uint32_t> start_;  // bucket b's points are order_[start_[b] .. start_[b + 1])
  std::vector<uint32_t> order_;
  std::vector<Vec3> sorted_;  // points[order_[i]]: a bucket's positions side by side
};

}  // namespace relt
