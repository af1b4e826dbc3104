#pragma once
#include "integrators/integrator.h"

namespace relt {

const IntegratorEntry& pssmltIntegrator();

}  // namespace relt
