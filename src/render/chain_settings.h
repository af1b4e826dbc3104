#pragma once
// The settings pssmlt's and mmlt's chains run with, from the render's (erpt's and relt's are in
// their folders).
#include "mcmc/pssmlt.h"
#include "render/settings.h"

namespace relt {

// pssmlt and mmlt: the budget, the chain count for it, the large-step probability and step sizes.
PssmltSettings pssmltSettings(const RenderSettings& settings);

}  // namespace relt
