#include "render/chain_settings.h"

#include <cmath>

namespace relt {

PssmltSettings pssmltSettings(const RenderSettings& settings) {
  PssmltSettings ps;
  ps.mutationsPerPixel = settings.mutationsPerPixel.value_or(kDefaultMutationsPerPixel);
  const double area = double(settings.width) * settings.height;
  ps.chains = chainsForBudget(settings.chains, settings.seconds.has_value(),
                              static_cast<uint64_t>(std::llround(ps.mutationsPerPixel * area)));
  ps.largeStepProbability = settings.largeStepProbability;
  ps.sizes = KelemenSizes{settings.smallStepMin, settings.smallStepMax};
  return ps;
}

}  // namespace relt
