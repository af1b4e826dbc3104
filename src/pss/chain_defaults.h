#pragma once
// Defaults shared by the primary-sample-space chain integrators (pssmlt, mmlt, erpt, relt),
// written once; the settings of each take them from here.

namespace relt {

constexpr double kDefaultMutationsPerPixel = 16.0;  // the chains' budget when neither it nor a time is given
constexpr float kDefaultLargeStepProbability = 0.3f;
constexpr int kBootstrapPaths = 100000;  // independent paths estimating the normaliser b (and seeding chains)

}  // namespace relt
