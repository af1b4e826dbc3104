#pragma once
#include "integrators/integrator.h"

namespace relt {

const IntegratorEntry& mmltIntegrator();

}  // namespace relt
