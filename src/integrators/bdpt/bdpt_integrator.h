#pragma once
#include "integrators/integrator.h"

namespace relt {

const IntegratorEntry& bdptIntegrator();

}  // namespace relt
