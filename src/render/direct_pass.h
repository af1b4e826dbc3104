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
};

struct DirectPass {
  int spp = 0;           // rays per pixel taken; 0: no pass (the chains estimate that emission too)
  double seconds = 0.0;  // the slowest rank's time for it
};

// Renders the pass into `film` for rows firstRow, firstRow + rowStride, ... and returns its size
// (resolve with divisor spp). With --direct-emission-spp auto it first takes kDirectProbeSpp rays
// per pixel; when no rank's rays saw emission it hands the paths of one segment back to the chains
// (Renderer::keepDirectEmissionInChains), clears the film and returns spp 0. Then it takes the
// given N, a fixed budget's autoDirectSpp, or for a timed render kDirectMinSpp and then
// doublings while doubleDirectPass allows. Call it before the chains start.
DirectPass renderDirectPass(Renderer& renderer, int firstRow, int rowStride, Film& film, const RankReduce& reduce);

}  // namespace relt
