#pragma once
// Target families of a ladder (DESIGN §3.1): level k's unnormalised target q_k(u) as a function of
// one traced path, and which levels estimate which path class (the MIS matrix c of DESIGN §3.3).
//
// kitaoka and relaxed are linear in the class luminances L_0..L_5 of the path's splats,
//   q_k(u) = offset_k + sum_n d_{k,n} L_n(u);
// tempered takes each level's target from a hook on the path builder (TemperedTargets), which
// re-evaluates the connection BSDFs per level. Either way one traced path gives every level's
// target: the family reads a few numbers per path (its features) and maps them to targets.
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "path/splat.h"
#include "pss/chain_defaults.h"
#include "pss/kelemen.h"
#include "replica/tempering.h"

namespace relt {

enum class FamilyKind : uint8_t {
  Kitaoka,  // seed 000: specific, indirect, full and uniform replicas
  Relaxed,  // seed 001: q_k = I + eps_k
  Tempered, // seed 004 ch. 5: connection BSDFs roughened by sqrt(T_k)
};
std::optional<FamilyKind> parseFamily(std::string_view name);
const char* familyName(FamilyKind kind);

inline constexpr int kMaxLevels = 64;  // levels per ladder

using ClassLuminance = std::array<double, kPathClassCount>;
// L_n(u): luminance of the class-n splats of one path; nothing if any splat is not finite.
std::optional<ClassLuminance> classLuminance(const PathSample& sample);

struct FamilySettings {
  FamilyKind kind = FamilyKind::Kitaoka;  // the default: see docs/BENCHMARKS.md (relt equal time)
  int levels = 8;              // relaxed and tempered (kitaoka always has 4)
  double relaxedEps1 = 0.01;   // eps_1 as a multiple of the bootstrap mean of I
  double relaxedRatio = 10.0;  // eps_{k+1} / eps_k
  double kitaokaDelta = 0.01;  // weight of L5 in the specific replica
  double temperatureMax = 2500.0;     // tempered: T geometric from 1 to this
  double regularisation = 0.0;        // tempered: rho_0 of reg(n) = rho_0 (1 + n)^-gamma (0 = off)
  double regularisationDecay = 1e-5;  // tempered: gamma
  KelemenSizes sizes;          // the chains' small-step sizes (kitaoka scales them per level)
  float largeStepProbability = kDefaultLargeStepProbability;
  // Levels left out of the ladder (bit k: level k of the full ladder; see idleLevels). A class
  // that only left-out levels estimated is estimated by every level that remains.
  uint64_t leftOut = 0;
};

class LevelFamily;

// The levels with nothing to do by the bootstrap (`bootstrap`: the family's features per sample,
// as LevelFamily::meanTarget takes them): a target 0 on every sample (its chain would reject every
// proposal), or no sample in any class the level estimates (its chain would splat nothing:
// kitaoka's specific level, which alone estimates L0, on a scene without implicit paths after a
// specular bounce, a quarter of the ladder's work). Bit k: level k. Only the linear families
// (kitaoka, relaxed) are looked at; nothing when the bootstrap is black or every level is idle.
uint64_t idleLevels(const FamilySettings& settings, const std::vector<double>& bootstrap);

class LevelFamily {
 public:
  // `meanTarget` is the bootstrap mean of I(u) = sum_n L_n: relaxed levels scale eps with it so
  // that the ladder does not depend on the scene's brightness.
  LevelFamily(const FamilySettings& settings, double meanTarget);

  FamilyKind kind() const { return kind_; }
  int levels() const { return static_cast<int>(levels_.size()); }

  // How many numbers per path the family reads (class luminances, or one target per level).
  static int featureCount(const FamilySettings& settings);
  // The mean of I(u) over samples with the given features (count per sample: featureCount).
  static double meanTarget(const FamilySettings& settings, const std::vector<double>& features);
  // A path's features; false (and features 0) if the path is not finite. levelTargets: the
  // tempered family's, from TemperedTargets (replica/tempered_targets.h); the others take none.
  bool features(const PathSample& sample, std::span<const double> levelTargets, double* f) const;
  // q_0..q_{M-1} of a path with the given features.
  void targets(const double* f, double* q) const;
  void targets(const ClassLuminance& L, double* q) const { targets(L.data(), q); }

  // Tempered family: the connection BSDFs of each level (null for the other families), and the
  // regularisation after n steps per chain, reg(n) = rho_0 (1 + n)^-gamma. It moves in steps of at
  // least 1 % (each one costs every chain a re-evaluation of its state); true if it moved.
  const Tempering* tempering() const { return kind_ == FamilyKind::Tempered ? &tempering_ : nullptr; }
  bool setRegularisationStep(uint64_t n);
  // The connection roughness floor now, and setting it back to one saved in a checkpoint.
  float regularisationFloor() const { return tempering_.minAlpha; }
  void restoreRegularisationFloor(float minAlpha) { tempering_.minAlpha = minAlpha; }
  double temperature(int level) const { return temperatures_.empty() ? 1.0 : temperatures_[size_t(level)]; }
  // Whether samples of `level` estimate class n (c[level][n]).
  bool estimates(int level, int cls) const { return levels_[size_t(level)].estimates[size_t(cls)]; }
  const KelemenSizes& sizes(int level) const { return levels_[size_t(level)].sizes; }
  float largeStepProbability(int level) const { return levels_[size_t(level)].largeStepProbability; }
  const std::string& name(int level) const { return levels_[size_t(level)].name; }
  // The names of the levels `settings.leftOut` takes out of the full ladder, in ladder order.
  static std::vector<std::string> leftOutNames(const FamilySettings& settings);
  // Offsets and class weights, for stats.json.
  double offset(int level) const { return levels_[size_t(level)].offset; }

 private:
  struct Level {
    std::string name;
    double offset = 0.0;
    std::array<double, kPathClassCount> weight{};
    std::array<bool, kPathClassCount> estimates{};
    KelemenSizes sizes;
    float largeStepProbability = kDefaultLargeStepProbability;
  };
  void buildLadder(const FamilySettings& settings, double meanTarget);
  void leaveOut(uint64_t levels);

  FamilyKind kind_;
  std::vector<Level> levels_;
  std::vector<double> temperatures_;  // tempered only
  Tempering tempering_;
  double regularisation_ = 0.0, regularisationDecay_ = 0.0;
};

}  // namespace relt
