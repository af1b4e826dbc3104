#pragma once
// The directly seen emission (paths of one segment) estimated apart from pssmlt's and relt's chains:
// how many rays per pixel, and whether to keep the pass at all. The ranks share the rows and
// combine their values through `reduce` (MPI collectives in mpi/, the identity in one process), so
// every rank takes the same decisions.
#include <functional>

#include "film/film.h"
#include "render/renderer.h"

namespace relt {

struct DirectPass {
  int spp = 0;           // rays per pixel taken; 0: no pass (the chains estimate that emission too)
  double seconds = 0.0;  // the slowest rank's time for it (an earlier render's included)
  bool stopped = false;  // a rank was asked to stop: spp is what every pixel had by then
};

// What the ranks agreed on after a chunk of the pass: the slowest rank's elapsed seconds, and
// whether any was asked to stop or to save (write the pass so far: its image and a checkpoint).
struct ChunkAgreement {
  double elapsed = 0.0;
  bool stop = false, save = false;
};

struct RankReduce {
  std::function<double(double)> max;  // over all ranks
  std::function<double(double)> sum;
  // Optional: the pass is taken in chunks, the ranks agreeing after each (from this rank's elapsed
  // seconds) and `chunkDone` told the pass so far and whether a save was agreed.
  std::function<ChunkAgreement(double)> agree = {};
  std::function<void(const DirectPass& sofar, bool save)> chunkDone = {};
};

// A pass continued from a checkpoint: the film holds `spp` rays of every pixel of this rank's rows,
// taken in `seconds` (a pass with spp > 0 has seen emission: the probe is not traced again).
struct DirectPassStart {
  int spp = 0;
  double seconds = 0.0;
};

// Renders the pass into `film` for rows firstRow, firstRow + rowStride, ... and returns its size
// (resolve with divisor spp). With --direct-emission-spp auto it first traces kDirectProbeSpp rays
// per pixel on streams of their own and discards them; when none of any rank saw emission it hands
// the paths of one segment back to the chains (Renderer::keepDirectEmissionInChains) and returns
// spp 0. Then it takes the given N, a fixed budget's autoDirectSpp, or for a timed render
// kDirectMinSpp and then doublings while doubleDirectPass allows. Rays are taken in chunks of
// every pixel of about kDirectChunkSeconds; between chunks the ranks agree on stop and save
// requests, and a stopped pass keeps the chunks done. Call it before the chains start.
DirectPass renderDirectPass(Renderer& renderer, int firstRow, int rowStride, Film& film, const RankReduce& reduce,
                            const DirectPassStart& start = {});

}  // namespace relt
