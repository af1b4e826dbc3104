// The shifted (0,2)-sequence of the direct-emission pass: the first 2^m points put exactly one
// point in every elementary interval of area 2^-m, for any shift, and the shifted points are
// uniform on average (every point's mean and variance over shifts match U[0,1)).
#include <gtest/gtest.h>

#include <vector>

#include "core/low_discrepancy.h"
#include "core/rng.h"

using namespace relt;

TEST(Sobol02, FirstPowerOfTwoPointsFormANetForEveryShift) {
  Rng rng(5);
  for (int trial = 0; trial < 20; ++trial) {
    const uint32_t sx = trial ? rng.nextU32() : 0, sy = trial ? rng.nextU32() : 0;
    for (int m = 0; m <= 10; ++m) {
      const uint32_t n = 1u << m;
      for (int a = 0; a <= m; ++a) {  // cells 2^-a wide and 2^-(m-a) high
        std::vector<int> count(n, 0);
        for (uint32_t i = 0; i < n; ++i) {
          const Vec2 p = shiftedSobol02(i, sx, sy);
          const uint32_t cx = static_cast<uint32_t>(p.x * float(1u << a));
          const uint32_t cy = static_cast<uint32_t>(p.y * float(1u << (m - a)));
          ++count[(cy << a) + cx];
        }
        for (uint32_t c = 0; c < n; ++c)
          ASSERT_EQ(count[c], 1) << "m " << m << " a " << a << " cell " << c << " shift " << trial;
      }
    }
  }
}

TEST(Sobol02, ShiftedPointsAreUniformOverShifts) {
  Rng rng(11);
  const int shifts = 20000;
  for (uint32_t i : {0u, 1u, 5u, 200u}) {
    double sx = 0, sxx = 0, sy = 0, syy = 0;
    for (int s = 0; s < shifts; ++s) {
      const Vec2 p = shiftedSobol02(i, rng.nextU32(), rng.nextU32());
      sx += p.x, sxx += double(p.x) * p.x, sy += p.y, syy += double(p.y) * p.y;
    }
    // Mean 1/2 (standard error 0.002), second moment 1/3 (standard error 0.0021).
    EXPECT_NEAR(sx / shifts, 0.5, 0.01) << i;
    EXPECT_NEAR(sy / shifts, 0.5, 0.01) << i;
    EXPECT_NEAR(sxx / shifts, 1.0 / 3.0, 0.01) << i;
    EXPECT_NEAR(syy / shifts, 1.0 / 3.0, 0.01) << i;
  }
}

TEST(Sobol02, SecondDimensionIsSobols) {
  // The first eight points of Sobol's sequence: (0,0) (.5,.5) (.25,.75) (.75,.25) (.125,.625)
  // (.625,.125) (.375,.375) (.875,.875).
  const float want[8][2] = {{0, 0}, {.5f, .5f}, {.25f, .75f}, {.75f, .25f}, {.125f, .625f}, {.625f, .125f}, {.375f, .375f}, {.875f, .875f}};
  for (uint32_t i = 0; i < 8; ++i) {
    const Vec2 p = shiftedSobol02(i, 0, 0);
    EXPECT_EQ(p.x, want[i][0]) << i;
    EXPECT_EQ(p.y, want[i][1]) << i;
  }
}
