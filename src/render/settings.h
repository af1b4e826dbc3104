#pragma once
// The effective settings of a render, filled in one place (the command line over the scene's
// defaults) and written back into stats.json so every image says how it was made.
#include <cstdint>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "path/path_context.h"
#include "pss/chain_defaults.h"
#include "pss/kelemen.h"
#include "render/own_settings.h"

namespace relt {

constexpr const char* kDefaultIntegrator = "bdpt";

struct RenderSettings;

// What the renderer needs to know of the integrator a render uses; each integrator's folder fills
// it in (src/integrators/registry.h), and only there are integrators told apart.
// Default-constructed it is the default integrator's (bdpt has no settings of its own).
struct IntegratorKind {
  std::string name = kDefaultIntegrator;
  // Can estimate the emission seen directly or through specular surfaces only (camera - delta* -
  // emitter paths, path/specular_chain.h) in a pass apart (directSpp).
  bool directEmissionApart = false;
  // Adds its own settings to toJson's (stats.json, the EXR metadata, the checkpoints' identity).
  void (*settingsJson)(const RenderSettings& settings, nlohmann::json& j) = nullptr;
};

constexpr int kDirectSppAuto = -1;
constexpr int kDefaultSpp = 16;  // pt, bdpt, erpt when neither --spp nor --time is given

struct RenderSettings {
  std::string scenePath;
  std::string output;             // .exr
  std::string png;                // optional preview
  std::string stats;              // optional stats.json
  std::string trace;              // relt, optional: every rank's stepping time of each group round (JSON)
  IntegratorKind integrator;
  OwnSettings own;                // the integrator's own (its folder's type; render/own_settings.h)
  std::optional<int> spp;         // samples per pixel (default when neither spp nor time: kDefaultSpp)
  std::optional<double> seconds;  // time budget
  int width = 0, height = 0;      // resolved (scene extras unless overridden)
  int maxDepth = 0;
  uint64_t seed = 1;
  std::string camera;             // empty: first camera
  float exposure = 0.0f;
  MisHeuristic heuristic = MisHeuristic::Power;
  // Worker threads of a rank: the image does not depend on them (to rounding).
  int threads = 1;
  // Markov-chain integrators.
  std::optional<double> mutationsPerPixel;  // default kDefaultMutationsPerPixel
  int chains = 256;
  float largeStepProbability = kDefaultLargeStepProbability;  // pssmlt, mmlt, relt
  float smallStepMin = KelemenSizes{}.s1, smallStepMax = KelemenSizes{}.s2;  // Kelemen small-step sizes
  double snapshotEvery = 0.0;  // Markov chains: write the image so far every this many seconds (0: never)
  // pssmlt, relt, vcm, meb: estimate the emission seen directly or through specular surfaces only
  // apart, with this many camera rays per pixel (a shifted (0,2)-sequence), and leave the main
  // estimator the other paths (0: it does them all; kDirectSppAuto: sized from the budget, dropped
  // when no such emission is in view, render/direct_pass.h).
  int directSpp = kDirectSppAuto;

  nlohmann::json toJson() const;
};

// pssmlt, relt, vcm and meb unless directSpp is 0: camera - delta* - emitter paths are estimated apart.
inline bool directEmissionApart(const RenderSettings& s) { return s.directSpp != 0 && s.integrator.directEmissionApart; }
// A float setting as the number it was given as (0.3, not 0.30000001192092896): the shortest
// decimal that reads back as the same float.
double shortestDecimal(float v);

}  // namespace relt
