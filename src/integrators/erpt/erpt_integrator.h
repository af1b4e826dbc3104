#pragma once
#include "integrators/integrator.h"

namespace relt {

const IntegratorEntry& erptIntegrator();

}  // namespace relt
