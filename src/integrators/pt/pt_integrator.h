#pragma once
#include "integrators/integrator.h"

namespace relt {

const IntegratorEntry& ptIntegrator();

}  // namespace relt
