#include "integrators/relt/relt_settings.h"

namespace relt {

ReplicaSettings effectiveReplicaSettings(const RenderSettings& s) {
  ReplicaSettings r = replicaSettings(s);
  r.family.sizes = KelemenSizes{s.smallStepMin, s.smallStepMax};
  r.family.largeStepProbability = s.largeStepProbability;
  return r;
}

}  // namespace relt
