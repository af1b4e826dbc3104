#pragma once
// Tempered connection BSDFs (DESIGN §3.1 `tempered`; thesis ch. 5, Eq. 5.5): level k roughens the
// BSDFs at the two vertices where a BDPT strategy joins its subpaths, alpha' = sqrt(T_k) * max(alpha,
// reg), and treats smooth (delta) surfaces there as Beckmann with alpha = 1e-4. Diffuse surfaces,
// geometry terms, visibility and the subpaths themselves (sampled with the untempered BSDFs) are
// not tempered, so one traced path gives every level's target.
#include <optional>
#include <vector>

#include "material/bsdf.h"

namespace relt {

struct Tempering {
  // Roughness a smooth surface has once tempered or regularised.
  static constexpr float kSmoothAlpha = 1e-4f;

  std::vector<float> scale;  // sqrt(T_k) per level; 1 leaves the level untempered
  float minAlpha = 0.0f;     // regularisation: connection roughness is at least this (0 = off)

  int levels() const { return static_cast<int>(scale.size()); }
  // The roughness level k gives a connection vertex of material m; nothing when the vertex keeps
  // its own BSDF (diffuse, or nothing to change at this level).
  std::optional<Roughness> roughness(const Material& m, int level) const;
};

// Temperatures geometric from 1 to tMax over `levels` levels (one level: T = 1).
std::vector<double> geometricTemperatures(int levels, double tMax);

}  // namespace relt
