#include "replica/tempered_targets.h"

namespace relt {
namespace {

const Bsdf* orOwn(const std::optional<Bsdf>& b) { return b ? &*b : nullptr; }

}  // namespace

void TemperedTargets::beginPath() { targets_.assign(size_t(tempering_.levels()), 0.0); }

// The end BSDFs each level uses and their values. From the hottest level down: a zero there is a
// zero for every cooler level too (same geometry, narrower lobes), which skips most connections
// through smooth surfaces.
bool TemperedTargets::prepare(const ConnectionEnds& c) {
  auto temperable = [](const PathVertex* v) { return v && v->bsdf->material().kind != MaterialKind::Lambert; };
  const PathVertex* tl = temperable(c.lightEnd()) ? c.lightEnd() : nullptr;
  const PathVertex* tc = temperable(c.cameraEnd()) ? c.cameraEnd() : nullptr;
  levels_ = tl || tc ? tempering_.levels() : 0;
  if (levels_ == 0) return false;
  value_.assign(size_t(levels_), Color(0.0f));
  own_.assign(size_t(levels_), 0);
  atLight_.resize(size_t(levels_));
  atCamera_.resize(size_t(levels_));
  bool any = false, cooler = true;  // cooler: the levels below may still contribute
  for (int k = levels_ - 1; k >= 0; --k) {
    const auto roughL = tl ? tempering_.roughness(tl->bsdf->material(), k) : std::nullopt;
    const auto roughC = tc ? tempering_.roughness(tc->bsdf->material(), k) : std::nullopt;
    if (!roughL && !roughC) {
      own_[size_t(k)] = 1;
      continue;
    }
    if (!cooler) continue;
    std::optional<Bsdf>&bL = atLight_[size_t(k)], &bC = atCamera_[size_t(k)];
    bL.reset();
    bC.reset();
    if (roughL) bL.emplace(tl->bsdf->material(), tl->sp.ns, tl->sp.ng, *roughL);
    if (roughC) bC.emplace(tc->bsdf->material(), tc->sp.ns, tc->sp.ng, *roughC);
    value_[size_t(k)] = c.value(orOwn(bL), orOwn(bC));
    cooler = !isBlack(value_[size_t(k)]);
    any |= cooler;
  }
  return any;
}

void TemperedTargets::add(const ConnectionEnds& c, double own) {
  if (levels_ == 0) {
    for (double& q : targets_) q += own;
    return;
  }
  for (int k = 0; k < levels_; ++k) {
    if (own_[size_t(k)]) {
      targets_[size_t(k)] += own;
    } else if (!isBlack(value_[size_t(k)])) {
      const float w = c.misWeight(orOwn(atLight_[size_t(k)]), orOwn(atCamera_[size_t(k)]));
      targets_[size_t(k)] += luminance(value_[size_t(k)]) * double(w);
    }
  }
}

}  // namespace relt
