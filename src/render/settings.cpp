#include "render/settings.h"

namespace relt {

const char* integratorName(Integrator i) {
  switch (i) {
    case Integrator::PathTracing: return "pt";
    case Integrator::Bdpt: return "bdpt";
    case Integrator::Pssmlt: return "pssmlt";
    case Integrator::Mmlt: return "mmlt";
    case Integrator::Erpt: return "erpt";
  }
  return "?";
}

nlohmann::json RenderSettings::toJson() const {
  nlohmann::json j;
  j["scene"] = scenePath;
  j["output"] = output;
  if (!png.empty()) j["png"] = png;
  j["integrator"] = integratorName(integrator);
  if (spp) j["spp"] = *spp;
  if (seconds) j["time"] = *seconds;
  j["width"] = width;
  j["height"] = height;
  j["max_depth"] = maxDepth;
  j["seed"] = seed;
  j["camera"] = camera;
  j["exposure"] = exposure;
  j["mis"] = heuristic == MisHeuristic::Power ? "power" : "balance";
  if (integrator == Integrator::Erpt) {
    j["chain_length"] = chainLength;
    if (erptMaxConsecutive > 0) j["max_consecutive"] = erptMaxConsecutive;
    if (erptProposalFilter) j["proposal_filter"] = true;
    j["small_step"] = {smallStepMin, smallStepMax};
  }
  if (isMarkovChain(integrator)) {
    j["mutations_per_pixel"] = mutationsPerPixel.value_or(16.0);
    j["chains"] = chains;
    j["large_step_probability"] = largeStepProbability;
    j["small_step"] = {smallStepMin, smallStepMax};
    if (kelemenWeights) j["kelemen_weights"] = true;
    if (snapshotEvery > 0.0) j["snapshot_every"] = snapshotEvery;
  }
  return j;
}

}  // namespace relt
