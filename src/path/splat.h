#pragma once
// What one traced sample contributes: a list of splats, each tagged with its path class.
#include <cmath>
#include <vector>

#include "core/math.h"

namespace relt {

// Path classes of Kitaoka et al. 2009 Sec. 4.2.1 (DESIGN §3). The replica families weight them.
enum class PathClass : uint8_t {
  L0 = 0,  // s = 0 (camera path hits an emitter) with at least one specular scattering
  L1 = 1,  // s = 0, no specular scattering
  L2 = 2,  // s = 1 (next-event estimation)
  L3 = 3,  // t = 0 (light path hits the lens; impossible with a pinhole camera)
  L4 = 4,  // t = 1 (light tracing to the camera)
  L5 = 5,  // s >= 2 and t >= 2
};
inline constexpr int kPathClassCount = 6;

struct Splat {
  Vec2 film;     // continuous film position (pixels)
  Color value;   // MIS-weighted contribution, film-wide normalisation (divide by samples per pixel)
  PathClass cls;
};

struct PathSample {
  std::vector<Splat> splats;
  void clear() { splats.clear(); }
  void add(const Vec2& film, const Color& value, PathClass cls) {
    if (!isBlack(value) || !isFinite(value)) splats.push_back({film, value, cls});
  }
  bool finite() const {
    for (const Splat& s : splats)
      if (!isFinite(s.value)) return false;
    return true;
  }
  // Scalar target of the Markov chains: I(u) = luminance of all splats.
  // I(u) for the Markov chains: the luminance sum, or 0 if any splat is not finite (such a sample
  // is never accepted nor splatted).
  float target() const {
    const float sum = luminanceSum();
    return std::isfinite(sum) && finite() ? sum : 0.0f;
  }
  float luminanceSum() const {
    float sum = 0.0f;
    for (const Splat& s : splats) sum += luminance(s.value);
    return sum;
  }
};

}  // namespace relt
