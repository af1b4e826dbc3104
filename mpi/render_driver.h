#pragma once
// The distributed render loop for the independent-sample integrators (pt, bdpt).
#include "comm.h"
#include "render/settings.h"

namespace relt::mpi {

// Loads the scene on every rank, renders, reduces the films on the root and writes the outputs.
// Throws InputError for anything the user can fix.
void runRender(const Session& session, RenderSettings settings);

}  // namespace relt::mpi
