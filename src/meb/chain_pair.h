#pragma once
// meb's two Markov chains over light subpaths in primary sample space (thesis digest §5.3, Fig.
// 6.10): a visibility chain (pi_vis = 1[C > 0], large steps with probability 0.3) and a
// contribution chain (pi_con = lum(C), small steps only) step in turn; after every step they may
// exchange states (two_chain.h). Every step splats the stepped chain's current state and its
// proposal as expected values (weights 1 - a and a) times mebSplatScale.
//
// Generic over the contribution (a list of splats in the renderer, a number in tests): it needs
// `double luminance() const`. `evaluate(SampleSource&)` computes one; `splat(chain, C, weight)`
// takes it. Everything random comes from the pair's own stream, so a pair's steps are a function
// of its key and its start states.
#include <cstdint>
#include <utility>
#include <vector>

#include "core/rng.h"
#include "meb/adaptive_step.h"
#include "meb/growing_point.h"
#include "meb/two_chain.h"

namespace relt {

enum class MebChain : uint8_t { Visibility = 0, Contribution = 1 };

struct MebChainCounters {
  uint64_t steps = 0, accepted = 0, largeSteps = 0;
};

template <class Contribution>
class MebChainPair {
 public:
  struct State {
    std::vector<float> u;
    Contribution c{};
  };

  MebChainPair(uint64_t key, const MebNormalisers& frozen, float largeStepProbability)
      : rng_(key), frozen_(frozen), largeStep_(largeStepProbability) {}

  void start(State visibility, State contribution) {
    states_[0] = std::move(visibility);
    states_[1] = std::move(contribution);
  }

  // One step of the chain whose turn it is, then an exchange attempt. Large steps' targets go to
  // `largeSteps` (the normalisers' estimate).
  template <class Evaluate, class Splat>
  void step(Evaluate&& evaluate, Splat&& splat, NormaliserSums& largeSteps) {
    const MebChain chain = (turn_++ % 2 == 0) ? MebChain::Contribution : MebChain::Visibility;
    const int k = int(chain);
    State& current = states_[k];
    const bool large = chain == MebChain::Visibility && rng_.uniform() < largeStep_;
    proposal_.u.clear();
    if (!large) {
      const float theta = adaptation_[k].theta();
      for (float x : current.u) proposal_.u.push_back(adaptiveSmallStep(x, rng_.uniform(), theta));
    }
    GrowingPoint point(proposal_.u, rng_);
    proposal_.c = evaluate(static_cast<SampleSource&>(point));
    const double proposed = proposal_.c.luminance(), now = current.c.luminance();
    if (large) largeSteps.add(proposed);
    const double a = chain == MebChain::Visibility ? acceptance(visibilityTarget(now), visibilityTarget(proposed))
                                                   : acceptance(now, proposed);
    if (large) ++counters_[k].largeSteps;
    else adaptation_[k].record(a);
    if (a < 1.0 && now > 0.0) splat(chain, current.c, (1.0 - a) * mebSplatScale(now, frozen_));
    if (a > 0.0) splat(chain, proposal_.c, a * mebSplatScale(proposed, frozen_));
    ++counters_[k].steps;
    if (rng_.uniform() < a) {
      std::swap(current, proposal_);
      ++counters_[k].accepted;
    }
    const double r = mebExchangeAcceptance(states_[0].c.luminance(), states_[1].c.luminance());
    ++exchangesTried_;
    if (r > 0.0 && rng_.uniform() < r) {
      std::swap(states_[0], states_[1]);
      ++exchanges_;
    }
  }

  const State& state(MebChain chain) const { return states_[int(chain)]; }
  const MebChainCounters& counters(MebChain chain) const { return counters_[int(chain)]; }
  const StepSizeAdaptation& adaptation(MebChain chain) const { return adaptation_[int(chain)]; }
  uint64_t exchanges() const { return exchanges_; }
  uint64_t exchangesTried() const { return exchangesTried_; }

 private:
  Rng rng_;
  MebNormalisers frozen_;
  float largeStep_;
  State states_[2];
  State proposal_;
  StepSizeAdaptation adaptation_[2];
  MebChainCounters counters_[2];
  uint64_t turn_ = 0, exchanges_ = 0, exchangesTried_ = 0;
};

}  // namespace relt
