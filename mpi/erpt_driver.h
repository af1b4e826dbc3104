#pragma once
// The distributed part of erpt: bootstrap shares, then seeds by work unit (sample index, row).
#include "checkpoint_io.h"
#include "comm.h"
#include "film/film.h"
#include "mcmc/erpt.h"
#include "render/renderer.h"

namespace relt::mpi {

struct ErptOutcome {
  double normaliser = 0.0;  // mean energy of the bootstrap samples
  int seedsPerPixel = 0;
  ErptCounters counters;    // summed over ranks
  std::vector<double> proposals;  // --erpt-proposal-filter: proposed mutations per pixel, on the root
};

// Renders this rank's share into `film` (not yet reduced); collective. `plan` writes checkpoints
// (film, passes, counters, normaliser, proposal tally); a render resumed from `resumed` (or null)
// continues after its passes without running the bootstrap again.
ErptOutcome runErpt(const Session& session, Renderer& renderer, const RenderSettings& settings, Film& film,
                    const CheckpointPlan& plan = {}, const Resumed* resumed = nullptr);

}  // namespace relt::mpi
