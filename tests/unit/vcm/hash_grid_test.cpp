// The merging range search finds exactly the points within the radius, as a search over all does.
#include <gtest/gtest.h>

#include <algorithm>

#include "core/rng.h"
#include "vcm/hash_grid.h"

using namespace relt;

namespace {

std::vector<Vec3> randomPoints(size_t n, uint64_t seed, float extent) {
  Rng rng(seed, 1);
  std::vector<Vec3> points(n);
  for (Vec3& p : points) p = Vec3(rng.uniform(), rng.uniform(), rng.uniform()) * extent - Vec3(extent / 2);
  return points;
}

}  // namespace

TEST(HashGrid, FindsExactlyThePointsWithinTheRadius) {
  const std::vector<Vec3> points = randomPoints(5000, 3, 2.0f);
  HashGrid grid;
  for (float radius : {0.01f, 0.05f, 0.3f}) {
    grid.build(points, radius);
    const std::vector<Vec3> queries = randomPoints(300, 7, 2.4f);
    size_t found = 0;
    for (const Vec3& q : queries) {
      std::vector<uint32_t> near, expected;
      grid.forEachNear(q, [&](uint32_t i) { near.push_back(i); });
      for (uint32_t i = 0; i < points.size(); ++i)
        if (glm::dot(points[i] - q, points[i] - q) <= radius * radius) expected.push_back(i);
      std::sort(near.begin(), near.end());
      EXPECT_EQ(near, expected) << "radius " << radius;
      found += expected.size();
    }
    if (radius > 0.2f) EXPECT_GT(found, 1000u) << "the test must look at many points";
  }
}

TEST(HashGrid, AnEmptyGridFindsNothing) {
  HashGrid grid;
  grid.build({}, 0.1f);
  int found = 0;
  grid.forEachNear(Vec3(0.0f), [&](uint32_t) { ++found; });
  EXPECT_EQ(found, 0);
}

TEST(HashGrid, SlotsNameThePointsInBucketOrder) {
  const std::vector<Vec3> points = randomPoints(2000, 5, 1.0f);
  HashGrid grid;
  grid.build(points, 0.05f);
  const std::span<const uint32_t> order = grid.order();
  std::vector<uint32_t> all(order.begin(), order.end());
  std::sort(all.begin(), all.end());
  for (uint32_t i = 0; i < all.size(); ++i) ASSERT_EQ(all[i], i) << "order() must be a permutation";
  for (const Vec3& q : randomPoints(100, 9, 1.0f)) {
    std::vector<uint32_t> byIndex, bySlot;
    grid.forEachNear(q, [&](uint32_t i) { byIndex.push_back(i); });
    grid.forEachSlotNear(q, [&](uint32_t slot) { bySlot.push_back(order[slot]); });
    EXPECT_EQ(bySlot, byIndex);  // the same points, in the same order
  }
}

// gatherBySlot puts each point's item in that point's slot: a neighbour found by slot is its item.
TEST(HashGrid, GatheredItemsSitInTheirPointsSlots) {
  const std::vector<Vec3> points = randomPoints(500, 3, 1.0f);
  HashGrid grid;
  grid.build(points, 0.1f);
  std::vector<const Vec3*> items;
  for (const Vec3& p : points) items.push_back(&p);
  std::vector<Vec3> bySlot;
  grid.gatherBySlot<Vec3>(items, bySlot);
  ASSERT_EQ(bySlot.size(), points.size());
  for (const Vec3& q : randomPoints(50, 4, 1.0f))
    grid.forEachSlotNear(q, [&](uint32_t slot) { EXPECT_LE(glm::length(bySlot[slot] - q), 0.1f); });
  for (size_t slot = 0; slot < bySlot.size(); ++slot) EXPECT_EQ(bySlot[slot], points[grid.order()[slot]]);
}
