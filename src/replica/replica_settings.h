#pragma once
// Options of the replica-exchange integrator and where its chains live (DESIGN §4).
#include <cstdint>
#include <optional>
#include <string_view>

#include "replica/exchange.h"
#include "replica/family.h"

namespace relt {

enum class Placement : uint8_t {
  Spread,  // chain c on rank c mod P: every rank holds a mix of levels (balanced work)
  Packed,  // ladders 2j and 2j + 1 on rank j mod P: whole ladders per rank, both round groups on each
};

inline std::optional<Placement> parsePlacement(std::string_view name) {
  if (name == "spread") return Placement::Spread;
  if (name == "packed") return Placement::Packed;
  return std::nullopt;
}
inline const char* placementName(Placement placement) { return placement == Placement::Spread ? "spread" : "packed"; }

// The rank that hosts chain c (ladder c / levels). Packed keeps an even and an odd ladder together,
// so every rank steps chains in both staggered round groups (even and odd ladders).
inline int chainRank(int chain, int levels, int ranks, Placement placement) {
  return placement == Placement::Spread ? chain % ranks : (chain / levels / 2) % ranks;
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

struct ReplicaSettings {
  FamilySettings family;
  int ladders = 32;
  ExchangeOptions exchange;
  int exchangeInterval = 16;  // steps per chain between exchanges
  Placement placement = Placement::Spread;  // where chains start
  double balanceWindow = 0.25;  // seconds of stepping (slowest rank) between placement decisions (0: never)
  double beta = 1.0;          // MIS over levels: 1 balance, 2 power heuristic
  int bootstrap = 100000;
  InitKind init = InitKind::Resample;
  AnnealingSettings annealing;
  bool perLevel = false;      // also write each level's MIS-weighted contribution as an EXR layer
};

}  // namespace relt
