#pragma once
// The directly seen emission (paths of one segment) estimated apart from pssmlt's and relt's chains:
// how many rays per pixel, and whether to keep the pass at all. The ranks share the rows and
// combine their values through `reduce` (MPI collectives in mpi/, the identity in one process), so
// every rank takes the same decisions.
#include <functional>

#include "film/film.h"
#include "render/renderer.h"

namespace relt {

struct RankReduce {
  std::function<double(double)> max;  // over all ranks
  std::function<double(double)> sum;
  std::function<bool()> stop = {};    // this rank was asked to stop (optional)
};

struct DirectPass {
  int spp = 0;           // rays per pixel taken; 0: no pass (the chains estimate that emission too)
  double seconds = 0.0;  // the slowest rank's time for it
  bool stopped = false;  // a rank was asked to stop: spp is what every pixel had by then
};

// Renders the pass into `film` for rows firstRow, firstRow + rowStride, ... and returns its size
// (resolve with divisor spp). With --direct-emission-spp auto it first traces kDirectProbeSpp rays
// per pixel on streams of their own and discards them; when none of any rank saw emission it hands
// the paths of one segment back to the chains (Renderer::keepDirectEmissionInChains) and returns
// spp 0. Then it takes the given N, a fixed budget's autoDirectSpp, or for a timed render
// kDirectMinSpp and then doublings while doubleDirectPass allows. Rays are taken in chunks of
// every pixel of about kDirectChunkSeconds; between chunks the ranks agree on a stop request, and
// a stopped pass keeps the chunks done. Call it before the chains start.
DirectPass renderDirectPass(Renderer& renderer, int firstRow, int rowStride, Film& film, const RankReduce& reduce);

}  // namespace relt
