#include "render/schedule.h"

#include <cstdio>

namespace relt {

std::string progressLine(double fraction, double elapsed, double samplesPerSecond, const char* unit) {
  char buf[160];
  const double eta = fraction > 0.0 ? elapsed * (1.0 - fraction) / fraction : 0.0;
  std::snprintf(buf, sizeof buf, "%5.1f%%  %.1f s elapsed  ETA %.1f s  %.2f M %s/s", 100.0 * fraction, elapsed, eta,
                samplesPerSecond * 1e-6, unit);
  return buf;
}

}  // namespace relt
