#pragma once
// The emission seen directly or through specular surfaces only (camera - delta* - emitter paths,
// path/specular_chain.h) estimated apart from pssmlt's, relt's, vcm's and meb's main estimators:
// how many rays per pixel, and whether to keep the pass at all. The ranks share the rows (rank r of
// P takes rows r, r + P, ...) and combine their values through the job's collectives, so every rank
// takes the same decisions.
#include <functional>

#include "film/film.h"
#include "parallel/job.h"
#include "render/renderer.h"

namespace relt {

struct DirectPass {
  int spp = 0;           // rays per pixel taken; 0: no pass (the chains estimate that emission too)
  double seconds = 0.0;  // the slowest rank's time for it (an earlier render's included)
  bool stopped = false;  // a rank was asked to stop: spp is what every pixel had by then
};

// Told after every chunk: the pass so far and whether the ranks agreed to save it (write its image
// and a checkpoint now; a stop saves too).
using DirectChunkDone = std::function<void(const DirectPass& sofar, bool save)>;

// A pass continued from a checkpoint: the film holds `spp` rays of every pixel of this rank's rows,
// taken in `seconds` (a pass with spp > 0 has seen emission: the probe is not traced again).
struct DirectPassStart {
  int spp = 0;
  double seconds = 0.0;
};

// The rays per pixel a pass takes with no clock to follow: --direct-emission-spp N, or on auto
// with a fixed budget autoDirectSpp of its iterations (vcm, meb) or mutations per pixel; 0 for a
// timed auto pass (doublings while doubleDirectPass allows).
int fixedDirectSpp(const RenderSettings& settings);

// Renders the pass into `film` for this rank's rows and returns its size
// (resolve with divisor spp). With --direct-emission-spp auto it first traces kDirectProbeSpp rays
// per pixel on streams of their own and discards them; when none of any rank saw emission it hands
// those paths back to the main estimator (Renderer::keepDirectEmissionInChains) and returns
// spp 0. Then it takes the given N, a fixed budget's autoDirectSpp, or for a timed render
// kDirectMinSpp and then doublings while doubleDirectPass allows. Rays are taken in chunks of
// every pixel of about kDirectChunkSeconds; between chunks the ranks agree on stop and save
// requests (Job::agree), and a stopped pass keeps the chunks done. Call it before the chains
// start; collective.
DirectPass renderDirectPass(Renderer& renderer, Job& job, Film& film, const DirectPassStart& start = {},
                            const DirectChunkDone& chunkDone = {});

}  // namespace relt
