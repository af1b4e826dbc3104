// The memory limits that refuse absurd inputs before allocating (scene triangles, film size).
#include <gtest/gtest.h>

#include "core/memory.h"

using namespace relt;

TEST(Memory, ABufferFitsInThreeQuartersOfPhysicalMemory) {
  const uint64_t gib = uint64_t(1) << 30;
  EXPECT_TRUE(fitsInMemory(18.0 * gib, 24 * gib));
  EXPECT_FALSE(fitsInMemory(18.1 * gib, 24 * gib));
  // A 16384 x 16384 film (double RGB, its reduced copy and the float image) needs 18 GiB: too much for 16 GiB.
  EXPECT_FALSE(fitsInMemory(3.0 * 3.0 * sizeof(double) * 16384.0 * 16384.0, 16 * gib));
  EXPECT_TRUE(fitsInMemory(1e30, 0)) << "unknown memory refuses nothing";
  EXPECT_GT(physicalMemoryBytes(), 0u);
  EXPECT_EQ(formatGiB(1.5 * gib), "1.5 GiB");
}
