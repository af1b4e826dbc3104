#include "render/settings.h"

#include <charconv>

namespace relt {
namespace {

// A float setting as the number it was given as (0.3, not 0.30000001192092896): the shortest
// decimal that reads back as the same float.
double shortest(float v) {
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, v).ptr;
  double out = v;
  std::from_chars(text, end, out);
  return out;
}

}  // namespace

const char* integratorName(Integrator i) {
  switch (i) {
    case Integrator::PathTracing: return "pt";
    case Integrator::Bdpt: return "bdpt";
    case Integrator::Pssmlt: return "pssmlt";
    case Integrator::Mmlt: return "mmlt";
    case Integrator::Erpt: return "erpt";
    case Integrator::Relt: return "relt";
  }
  return "?";
}

ReplicaSettings effectiveReplicaSettings(const RenderSettings& s) {
  ReplicaSettings r = s.replica;
  r.family.sizes = KelemenSizes{s.smallStepMin, s.smallStepMax};
  r.family.largeStepProbability = s.largeStepProbability;
  return r;
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
  j["exposure"] = shortest(exposure);
  j["mis"] = heuristic == MisHeuristic::Power ? "power" : "balance";
  j["threads"] = threads;
  if (integrator == Integrator::Erpt) {
    j["chain_length"] = chainLength;
    if (erptMaxConsecutive > 0) j["max_consecutive"] = erptMaxConsecutive;
    if (erptProposalFilter) j["proposal_filter"] = true;
    j["small_step"] = {shortest(smallStepMin), shortest(smallStepMax)};
  }
  if (isMarkovChain(integrator)) {
    if (!seconds) j["mutations_per_pixel"] = mutationsPerPixel.value_or(kDefaultMutationsPerPixel);  // a timed render has no such count
    if (integrator == Integrator::Relt) {
      const ReplicaSettings& r = replica;
      j["family"] = familyName(r.family.kind);
      switch (r.family.kind) {
        case FamilyKind::Relaxed:
          j["levels"] = r.family.levels;
          j["relaxed_eps1"] = r.family.relaxedEps1;
          j["relaxed_ratio"] = r.family.relaxedRatio;
          break;
        case FamilyKind::Kitaoka: j["kitaoka_delta"] = r.family.kitaokaDelta; break;
        case FamilyKind::Tempered:
          j["levels"] = r.family.levels;
          j["temperature_max"] = r.family.temperatureMax;
          j["regularisation"] = r.family.regularisation;
          if (r.family.regularisation > 0.0) j["regularisation_decay"] = r.family.regularisationDecay;
          break;
      }
      j["ladders"] = r.ladders;
      j["exchange"] = exchangeMoveName(r.exchange.move);
      j["exchange_interval"] = r.exchangeInterval;
      j["normaliser_lag"] = r.normaliserLag;
      j["normaliser_lag_growth"] = r.normaliserLagGrowth;
      j["placement"] = placementName(r.placement);
      j["balance_window"] = r.balanceWindow;
      j["mis_levels"] = r.beta == 1.0 ? "balance" : "power";
      j["init"] = r.init == InitKind::Annealing ? "annealing" : "resample";
      if (r.perLevel) j["per_level"] = true;
    } else {
      j["chains"] = chains;
    }
    j["large_step_probability"] = shortest(largeStepProbability);
    j["small_step"] = {shortest(smallStepMin), shortest(smallStepMax)};
    if (snapshotEvery > 0.0) j["snapshot_every"] = snapshotEvery;
    if (directEmissionApart(*this)) j["direct_emission_spp"] = directSpp == kDirectSppAuto ? nlohmann::json("auto") : nlohmann::json(directSpp);
  }
  return j;
}

}  // namespace relt
