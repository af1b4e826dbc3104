#pragma once
// meb's render: vcm's loop of iterations (integrators/passes/iteration_loop.h) over MebRenderer.
#include "integrators/integrator.h"

namespace relt {

void renderMeb(RenderContext& context);

}  // namespace relt
