#pragma once
// The distributed part of erpt: bootstrap shares, then seeds by work unit (sample index, row).
#include <functional>

#include "checkpoint/checkpoint_io.h"
#include "parallel/job.h"
#include "film/film.h"
#include "mcmc/erpt.h"
#include "integrators/passes/pass_loop.h"
#include "render/renderer.h"

namespace relt {

struct ErptOutcome {
  double normaliser = 0.0;  // mean energy of the bootstrap samples
  PassPoint end;             // seeds per pixel: end.passes, one more in rows 0 .. end.rows - 1
  ErptCounters counters;    // summed over ranks
  Image image;              // on the root: the whole passes' (render/pass_film.h), filtered if asked
};

// Makes the film runErpt fills: a chain wanders out of its row, and --erpt-proposal-filter tallies
// the proposed mutations per pixel beside it.
PassFilm erptFilm(const RenderSettings& settings);

// Renders this rank's share into `film` (not reduced); collective. The root's `snapshot` (if
// any) gets the image so far on a save request and every --snapshot-every seconds. `plan` writes
// checkpoints (films, passes, counters, normaliser, proposal tallies); a render resumed from
// `resumed` (or null) continues where it stopped without running the bootstrap again.
ErptOutcome runErpt(Job& job, Renderer& renderer, const RenderSettings& settings, PassFilm& film,
                    const std::function<void(const Image&)>& snapshot = {}, const CheckpointPlan& plan = {},
                    const Resumed* resumed = nullptr);

}  // namespace relt
