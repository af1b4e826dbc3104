#pragma once
#include "integrators/integrator.h"

namespace relt {

const IntegratorEntry& vcmIntegrator();

}  // namespace relt
