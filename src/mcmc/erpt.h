#pragma once
// Energy redistribution path tracing (Cline et al. 2005, seed 003): every pixel sample is a
// path-tracing seed in primary sample space; its energy e = I(u) flows into the film through
// floor(xi + e / (m e_d)) chains of m small-step mutations that each deposit e_d (equal-deposition
// flow, Fig. 6), with expected values: a e_d at the proposal, (1 - a) e_d at the current state.
// e_d = b / depositsPerSeed, b the mean energy of uniform samples (a bootstrap).
#include <cstdint>

#include "core/sample_source.h"
#include <vector>

#include "film/film.h"
#include "image/image.h"
#include "path/path_context.h"
#include "path/splat.h"
#include "pss/kelemen.h"

namespace relt {

struct ErptSettings {
  int chainLength = 100;          // m
  double depositsPerSeed = 100.0;  // e_d = b / this: on average b / e_d / m = 1 chain per average seed
  KelemenSizes sizes;
  // Cline et al. Sec. 4.4 consecutive-sample filter (biased, 0 = off): a chain that has stayed on
  // one pixel for this many mutations stops depositing until it moves to another pixel.
  int maxConsecutive = 0;
};

// Path tracing as a function of u; the film position is the first two camera numbers times the
// film size.
class PtEvaluator {
 public:
  PtEvaluator(const PathContext& ctx, int width, int height) : ctx_(ctx), width_(width), height_(height) {}
  float operator()(SampleSource& u, PathSample& out);
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  const PathContext& ctx_;
  int width_, height_;
};

struct ErptCounters {
  uint64_t seeds = 0, chains = 0, mutations = 0, accepted = 0, invalidProposals = 0;
  void add(const ErptCounters& o);
};

// Seed `sampleIndex` of every pixel of `row`, with its chains, into the film. Each deposit is
// weighted by filmWeight (1 / seeds per pixel). Keys: (seed, pixel, sampleIndex), so the result
// does not depend on which rank renders the row.
// proposals (optional, width x height): tally of proposed mutations per pixel, for the proposal filter.
ErptCounters erptRow(PtEvaluator& eval, const ErptSettings& settings, double normaliser, uint64_t seed,
                     uint64_t sampleIndex, int row, double filmWeight, Film& film,
                     std::vector<double>* proposals = nullptr);

// Cline et al. Sec. 4.4 proposed-mutations filter (biased): scales each pixel by the box-blurred
// ((2 radius + 1)^2) count of proposed mutations over its own count. Pixels nothing was proposed
// to are left unchanged.
void applyProposalFilter(Image& image, const std::vector<double>& proposals, int radius = 3);

// Mean energy of `count` uniform samples i = first, first + stride, ... (sum, not mean, so ranks
// can add their shares).
double erptBootstrapSum(PtEvaluator& eval, uint64_t seed, int count, int first, int stride);

}  // namespace relt
