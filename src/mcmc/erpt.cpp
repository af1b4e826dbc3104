#include "mcmc/erpt.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/rng.h"
#include "mcmc/metropolis.h"
#include "mcmc/pss_evaluator.h"
#include "path/path_tracer.h"
#include "pss/primary_sample_vector.h"

namespace relt {
namespace {

constexpr uint64_t kSeedPurpose = 0xe4b7, kBootstrapPurpose = 0xe4b8;

// Pixel of a chain state: its first two camera numbers are the film position.
int64_t pixelOf(const PrimarySampleVector& u, int w, int h) {
  const auto& c = u.coordinates(SampleStream::Camera);
  if (c.size() < 2) return -1;
  const int x = std::min(w - 1, static_cast<int>(c[0].value * w)), y = std::min(h - 1, static_cast<int>(c[1].value * h));
  return static_cast<int64_t>(y) * w + x;
}

void deposit(Film& film, const PathSample& sample, float energy, double weight) {
  if (energy > 0.0f && weight > 0.0) film.addSample(sample, weight / energy);
}

}  // namespace

float PtEvaluator::operator()(SampleSource& u, PathSample& out) {
  out.clear();
  const float x = u.next(SampleStream::Camera), y = u.next(SampleStream::Camera);
  tracePath(ctx_, Vec2(x * width_, y * height_), u, out);
  return out.target();
}

void ErptCounters::add(const ErptCounters& o) {
  seeds += o.seeds;
  chains += o.chains;
  mutations += o.mutations;
  accepted += o.accepted;
  invalidProposals += o.invalidProposals;
}

double erptBootstrapSum(PtEvaluator& eval, uint64_t seed, int count, int first, int stride) {
  double sum = 0.0;
  PathSample sample;
  for (int i = first; i < count; i += stride) {
    IndependentSource u(hashKey(seed, kBootstrapPurpose, static_cast<uint64_t>(i)));
    sum += eval(u, sample);
  }
  return sum;
}

ErptCounters erptRow(PtEvaluator& eval, const ErptSettings& settings, double normaliser, uint64_t seed,
                     uint64_t sampleIndex, int row, double filmWeight, Film& film, std::vector<double>* proposals) {
  ErptCounters counters;
  const int w = eval.width(), h = eval.height();
  const double energyPerDeposit = normaliser / settings.depositsPerSeed;
  if (!(energyPerDeposit > 0.0)) return counters;
  PathSample seedSample, current, proposal;
  for (int x = 0; x < w; ++x) {
    const uint64_t pixel = static_cast<uint64_t>(row) * w + x;
    const uint64_t key = hashKey(seed, kSeedPurpose, pixel, sampleIndex);
    Rng rng(key, 7);
    const float jx = rng.uniform(), jy = rng.uniform();
    RecordingSource source(key, StreamValues{{{(x + jx) / w, (row + jy) / h}, {}, {}}});
    const float e = eval(source, seedSample);
    ++counters.seeds;
    const int chains = static_cast<int>(std::floor(rng.uniform() + e / (settings.chainLength * energyPerDeposit)));
    for (int c = 0; c < chains; ++c) {
      ++counters.chains;
      PrimarySampleVector u(hashKey(key, c), settings.sizes);
      for (int s = 0; s < kSampleStreamCount; ++s) u.setState(static_cast<SampleStream>(s), source.values(static_cast<SampleStream>(s)));
      current = seedSample;
      float energy = e;
      int64_t currentPixel = pixelOf(u, w, h), lastPixel = -1;
      int consecutive = 0;
      for (int j = 0; j < settings.chainLength; ++j) {
        u.startIteration(false);
        const float proposed = eval(u, proposal);
        const int64_t proposedPixel = pixelOf(u, w, h);
        if (proposals && proposedPixel >= 0) (*proposals)[static_cast<size_t>(proposedPixel)] += 1.0;
        const float a = acceptance(energy, proposed);
        ++counters.mutations;
        if (!(proposed > 0.0f)) ++counters.invalidProposals;
        consecutive = currentPixel == lastPixel ? consecutive + 1 : 1;
        lastPixel = currentPixel;
        // Each deposit carries e_d: the state's splats scaled to luminance e_d.
        if (settings.maxConsecutive <= 0 || consecutive <= settings.maxConsecutive) {
          deposit(film, proposal, proposed, a * energyPerDeposit * filmWeight);
          deposit(film, current, energy, (1.0f - a) * energyPerDeposit * filmWeight);
        }
        if (keepOrRevert(rng.uniform() < a, u, current, proposal)) {
          energy = proposed;
          currentPixel = proposedPixel;
          ++counters.accepted;
        }
      }
    }
  }
  return counters;
}

void applyProposalFilter(Image& image, const std::vector<double>& proposals, int radius) {
  const int w = image.width, h = image.height;
  // Box blur by a summed-area table.
  std::vector<double> sat(static_cast<size_t>(w + 1) * (h + 1), 0.0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      sat[(y + 1) * size_t(w + 1) + x + 1] = proposals[size_t(y) * w + x] + sat[y * size_t(w + 1) + x + 1] +
                                             sat[(y + 1) * size_t(w + 1) + x] - sat[y * size_t(w + 1) + x];
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const double actual = proposals[size_t(y) * w + x];
      if (!(actual > 0.0)) continue;
      const int x0 = std::max(0, x - radius), x1 = std::min(w, x + radius + 1);
      const int y0 = std::max(0, y - radius), y1 = std::min(h, y + radius + 1);
      const double sum = sat[y1 * size_t(w + 1) + x1] - sat[y0 * size_t(w + 1) + x1] - sat[y1 * size_t(w + 1) + x0] +
                         sat[y0 * size_t(w + 1) + x0];
      const double expected = sum / double((x1 - x0) * (y1 - y0));
      for (int c = 0; c < 3; ++c) image.rgb[3 * (size_t(y) * w + x) + c] *= static_cast<float>(expected / actual);
    }
}

}  // namespace relt
