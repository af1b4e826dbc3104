#pragma once
// vcm's render: iterations dealt to the ranks in turn (iteration i on rank i mod P), each on the
// rank's worker threads; --spp iterations, or --time decided collectively after every round of P.
// Snapshots and checkpoints are taken between rounds; a checkpoint holds the film and the
// iterations done, so a resumed render (on any number of ranks) goes on with the next iteration.
#include "integrators/integrator.h"

namespace relt {

void renderVcm(RenderContext& context);

}  // namespace relt
