#include "replica/annealing.h"

#include "core/sampling.h"
#include "mcmc/pssmlt.h"

namespace relt {
namespace {
constexpr uint64_t kAnnealingPurpose = 0xa22e;

uint64_t particleKey(uint64_t seed, int level, int particle) {
  return hashKey(seed, kAnnealingPurpose, uint64_t(level), uint64_t(particle));
}

// Weights that sum to zero cannot be resampled: fall back to uniform ones.
Distribution1D resampling(std::vector<double> weights) {
  double total = 0.0;
  for (double w : weights) total += w;
  if (!(total > 0.0)) weights.assign(weights.size(), 1.0);
  return Distribution1D(weights);
}
}  // namespace

std::vector<std::vector<StreamValues>> annealedStarts(const LevelEvaluator& eval, const LevelFamily& family,
                                                      const std::vector<std::vector<double>>& bootstrapTargets,
                                                      uint64_t seed, const AnnealingSettings& settings) {
  const int m = family.levels(), n = settings.particles;
  std::vector<std::vector<StreamValues>> starts(static_cast<size_t>(m));
  Rng rng(hashKey(seed, kAnnealingPurpose), 0);

  // The top level's particles: bootstrap samples picked in proportion to its target.
  std::vector<ReplicaChain> particles;
  particles.reserve(size_t(n));
  const Distribution1D top = resampling(bootstrapTargets[size_t(m - 1)]);
  for (int i = 0; i < n; ++i) {
    ReplicaChain& p = particles.emplace_back(particleKey(seed, m - 1, i), m - 1, family);
    p.start(eval, bootstrapKey(seed, top.sample(rng.uniform())));
  }
  for (int k = m - 1; k >= 0; --k) {
    if (k < m - 1) {
      // Reweight by q_k / q_{k+1} and resample; each child continues its parent's state.
      std::vector<double> w(static_cast<size_t>(n));
      for (int i = 0; i < n; ++i) {
        const double* q = particles[size_t(i)].targets();
        w[size_t(i)] = q[k + 1] > 0.0 ? q[k] / q[k + 1] : 0.0;
      }
      const Distribution1D pick = resampling(w);
      std::vector<ReplicaChain> children;
      children.reserve(size_t(n));
      for (int i = 0; i < n; ++i) {
        const ReplicaChain& parent = particles[pick.sample(rng.uniform())];
        children.emplace_back(particleKey(seed, k, i), k, family).start(eval, particleKey(seed, k, i), parent.state());
      }
      particles.swap(children);
    }
    for (ReplicaChain& p : particles) p.explore(uint64_t(settings.mutationsPerLevel), eval);
    for (const ReplicaChain& p : particles) starts[size_t(k)].push_back(p.state());
  }
  return starts;
}

}  // namespace relt
