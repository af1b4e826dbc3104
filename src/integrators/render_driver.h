#pragma once
// A render from loading the scene to writing the outputs, for every integrator.
#include "checkpoint/checkpoint_io.h"
#include "parallel/job.h"
#include "render/settings.h"

namespace relt {

// Loads the scene on every rank, renders (continuing a checkpoint and writing checkpoints as the
// plan says), reduces the films on the root and writes the outputs. Throws InputError for
// anything the user can fix.
void runRender(Job& job, RenderSettings settings, CheckpointPlan plan = {});

}  // namespace relt
