#pragma once
#include "integrators/integrator.h"

namespace relt {

const IntegratorEntry& reltIntegrator();

}  // namespace relt
