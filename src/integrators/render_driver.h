#pragma once
// A render from loading the scene to writing the outputs, for every integrator.
#include "checkpoint/checkpoint_io.h"
#include "core/clock.h"
#include "parallel/job.h"
#include "render/settings.h"
#include "scene/scene.h"

namespace relt {

// Loads the scene on every rank, renders it with the integrator the settings name (registry.h),
// continuing a checkpoint and writing checkpoints as the plan says, reduces the films on the root
// and writes the outputs. Throws InputError for anything the user can fix.
void runRender(Job& job, const RenderSettings& settings, const CheckpointPlan& plan = {});
// The same for a scene already loaded (the tests' edited scenes); `wallStart` is when loading began.
void renderScene(Job& job, Scene scene, RenderSettings settings, CheckpointPlan plan = {},
                 Clock::time_point wallStart = Clock::now());

}  // namespace relt
