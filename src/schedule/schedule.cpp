#include "schedule/schedule.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace relt {

int autoDirectSpp(double mutationsPerPixel) {
  const double target = std::max(2.0 * mutationsPerPixel, double(kDirectMinSpp));
  const double exponent = std::min(std::round(std::log2(target)), std::log2(double(kDirectMaxSpp)));
  return 1 << int(exponent);
}

std::string progressLine(double fraction, double elapsed, double samplesPerSecond, const char* unit) {
  char buf[160];
  const double eta = fraction > 0.0 ? elapsed * (1.0 - fraction) / fraction : 0.0;
  std::snprintf(buf, sizeof buf, "%5.1f%%  %.1f s elapsed  ETA %.1f s  %.2f M %s/s", 100.0 * fraction, elapsed, eta,
                samplesPerSecond * 1e-6, unit);
  return buf;
}

}  // namespace relt
