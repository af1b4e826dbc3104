#pragma once
// The settings each chain integrator runs with, from the render's: written once, used by the
// executable's drivers and by the tests' in-process renders alike.
#include "mcmc/erpt.h"
#include "mcmc/pssmlt.h"
#include "render/settings.h"

namespace relt {

// pssmlt and mmlt: the budget, the chain count for it, the large-step probability and step sizes.
PssmltSettings pssmltSettings(const RenderSettings& settings);
// erpt: chain length, step sizes and the consecutive-sample filter.
ErptSettings erptSettings(const RenderSettings& settings);

}  // namespace relt
