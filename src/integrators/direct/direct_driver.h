#pragma once
// pssmlt, relt, vcm and meb: the emission seen directly or through specular surfaces only, rendered
// apart (row r on rank r mod P, every pixel on its own streams, so the image does not depend on P)
// and reduced; render/direct_pass.h decides how many rays, and whether at all. The pass is in every
// checkpoint: a resume never renders it again.
#include <functional>
#include <optional>

#include <nlohmann/json.hpp>

#include "checkpoint/checkpoint_io.h"
#include "parallel/job.h"
#include "film/film.h"
#include "image/image.h"
#include "render/renderer.h"

namespace relt {

struct DirectEstimate {
  Film film{0, 0};         // this rank's rows, not reduced (what checkpoints keep)
  Image image;             // on the root; empty elsewhere and without a pass
  int spp = 0;             // rays per pixel; 0: none (the chains estimate that emission too)
  bool inChains = false;   // auto found no emitter in view: the chains estimate it
  bool stopped = false;    // the ranks agreed to stop during the pass: the chains do not start
  uint64_t dropped = 0;    // non-finite samples, summed over ranks
  double seconds = 0.0;    // the slowest rank's time for it, the same on every rank
  // What a checkpoint keeps of it beside the film (under "direct" in its progress).
  nlohmann::json progress() const;
};

// Renders the pass, continues the one `resumed` holds alone (a checkpoint written during the pass,
// progress "phase": "direct"; `resumed` is then reset, the chains start afresh), or takes it out of
// a checkpoint of the chains (their films and parts stay). During the pass a save request (SIGCONT)
// writes `snapshot` (the root's image of the pass so far) and, like a due --checkpoint-every or a
// stop, a checkpoint of the pass alone. Collective.
DirectEstimate directEmission(Job& job, Renderer& renderer, const RenderSettings& settings,
                              const CheckpointPlan& plan, std::optional<Resumed>& resumed,
                              const std::function<void(const Image&)>& snapshot);

}  // namespace relt
