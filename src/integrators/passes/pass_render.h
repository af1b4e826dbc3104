#pragma once
// pt's and bdpt's render: independent samples in passes (pass_loop.h), a checkpoint being the film
// and where the passes got to.
#include "integrators/integrator.h"

namespace relt {

// `rowsStandAlone`: a row's samples splat into that row only (render/pass_film.h).
void renderPasses(RenderContext& context, RowEstimator estimator, bool rowsStandAlone);

}  // namespace relt
