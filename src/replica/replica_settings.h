#pragma once
// Options of the replica-exchange integrator and where its chains live (DESIGN §4).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <string_view>

#include "path/path_context.h"
#include "pss/chain_defaults.h"
#include "replica/exchange.h"
#include "replica/family.h"

namespace relt {

enum class Placement : uint8_t {
  Spread,  // chain c on rank c mod P: ladders span ranks; every rank decides every ladder's exchange
  Packed,  // ladders G j .. G j + G - 1 on rank j mod P: whole ladders per rank, exchanges decided locally
  Auto,    // packed beyond 8 ranks when every rank can hold a ladder of each round group, else spread
};

inline std::optional<Placement> parsePlacement(std::string_view name) {
  if (name == "spread") return Placement::Spread;
  if (name == "packed") return Placement::Packed;
  if (name == "auto") return Placement::Auto;
  return std::nullopt;
}
inline const char* placementName(Placement placement) {
  return placement == Placement::Spread ? "spread" : placement == Placement::Packed ? "packed" : "auto";
}

// Spread replicates every exchange decision and every target on every rank, about 0.1 % of the
// stepping time per rank (docs/SCALING.md): negligible on a few ranks, where moving single chains
// balances load more finely than whole ladders. Packed keeps a rank's work per round independent
// of the rank count; it needs two ladders per rank so that each rank steps in both round groups.
// The render loop staggers the ladders' rounds in this many groups (ladder l in group l mod G):
// a rank waits for a group's collective only after stepping the G - 1 others (docs/SCALING.md).
constexpr int kRoundGroups = 2;
inline int roundGroups(int ladders) { return ladders < 1 ? 1 : ladders < kRoundGroups ? ladders : kRoundGroups; }

inline Placement resolvePlacement(Placement placement, int ladders, int ranks) {
  if (placement != Placement::Auto) return placement;
  return ranks > 8 && ladders >= kRoundGroups * ranks ? Placement::Packed : Placement::Spread;
}

// The rank that hosts chain c (ladder c / levels). Packed keeps runs of kRoundGroups consecutive
// ladders together, so every rank steps chains in every staggered round group.
inline int chainRank(int chain, int levels, int ranks, Placement placement) {
  return placement == Placement::Spread ? chain % ranks : (chain / levels / kRoundGroups) % ranks;
}

// How chains get their first states (DESIGN §3.4).
enum class InitKind : uint8_t {
  Resample,   // each chain resamples the bootstrap in proportion to its level's target
  Annealing,  // population annealing down the ladder (seed 000 Alg. 2)
};

struct AnnealingSettings {
  int particles = 4096;
  int mutationsPerLevel = 8;
};

// The normaliser lag (in rounds) of a group that has posted `postedRounds` rounds: the base lag,
// growing as postedRounds / growth up to 8 x the base (growth 0: fixed).
inline uint64_t normaliserLagAt(int lag, int growth, uint64_t postedRounds) {
  const uint64_t base = uint64_t(lag > 0 ? lag : 1);
  return growth > 0 ? std::clamp(postedRounds / uint64_t(growth), base, 8 * base) : base;
}

// With local decisions a rank may run ahead of the slowest by as many rounds as the normaliser
// lag, and a stop request takes effect once the others have caught up with it. A rank therefore
// also waits, without reading them back (the image does not change), for the collectives older
// than about kMaxLeadSeconds of its rounds: a stall shorter than that still costs nobody else, and
// a stop is acted on within it. The rounds a rank may lead by, from its seconds per round so far
// (0: not measured yet, no cap).
constexpr double kMaxLeadSeconds = 0.3;
inline size_t leadCapRounds(double secondsPerRound) {
  if (!(secondsPerRound > 0.0)) return std::numeric_limits<size_t>::max();
  return size_t(std::clamp(std::ceil(kMaxLeadSeconds / secondsPerRound), 1.0, 1e9));
}

struct ReplicaSettings {
  FamilySettings family;
  int ladders = 32;
  ExchangeOptions exchange;
  int exchangeInterval = 16;  // steps per chain between exchanges
  // Rounds between taking large-step sums and using them in the normalisers: a group reads the
  // messages of its round R at the end of its round R + lag - 1, so with packed placement a rank
  // may run lag rounds ahead of the slowest before it waits (docs/SCALING.md).
  int normaliserLag = 32;
  // The lag grows with the render: at round R it is R / normaliserLagGrowth, at least
  // normaliserLag and at most 8 times that (0: fixed). The ranks move at the pace of whichever is
  // slowest over the last lag rounds, so a drift of a rank's speed that outlasts the lag costs in
  // every stretch of the render; a longer lag outlasts more of them, and starting short keeps the
  // normalisers of short renders fresh (docs/SCALING.md, "Render length"). The cap bounds how late
  // a stop request is read back.
  int normaliserLagGrowth = 8;
  Placement placement = Placement::Auto;  // where chains start
  double balanceWindow = 0.25;  // seconds of stepping (slowest rank) between placement decisions (0: never)
  MisHeuristic levelHeuristic = MisHeuristic::Balance;  // MIS over levels
  int bootstrap = kBootstrapPaths;
  InitKind init = InitKind::Resample;
  AnnealingSettings annealing;
  bool perLevel = false;      // also write each level's MIS-weighted contribution as an EXR layer
};

}  // namespace relt
