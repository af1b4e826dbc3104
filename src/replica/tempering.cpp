#include "replica/tempering.h"

#include <algorithm>
#include <cmath>

namespace relt {

std::optional<Roughness> Tempering::roughness(const Material& m, int level) const {
  if (m.kind == MaterialKind::Lambert) return std::nullopt;
  const float s = scale[size_t(level)];
  const bool smooth = m.alpha <= 0.0f;
  if (s == 1.0f && (smooth ? minAlpha <= 0.0f : m.alpha >= minAlpha)) return std::nullopt;
  const float base = smooth ? kSmoothAlpha : m.alpha;
  return Roughness{s * std::max(base, minAlpha), smooth ? Microfacet::Beckmann : m.distribution};
}

std::vector<double> geometricTemperatures(int levels, double tMax) {
  std::vector<double> t(static_cast<size_t>(std::max(levels, 0)), 1.0);
  for (int k = 1; k < levels; ++k) t[size_t(k)] = std::pow(tMax, double(k) / double(levels - 1));
  return t;
}

}  // namespace relt
