#pragma once
#include "integrators/integrator.h"

namespace relt {

const IntegratorEntry& mebIntegrator();

}  // namespace relt
