#pragma once
// Target families of a ladder (DESIGN §3.1): level k's unnormalised target q_k(u) as a function of
// one traced path, and which levels estimate which path class (the MIS matrix c of DESIGN §3.3).
//
// Both families here are linear in the class luminances L_0..L_5 of the path's splats,
//   q_k(u) = offset_k + sum_n d_{k,n} L_n(u),
// so one traced path gives every level's target with no extra work.
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "path/splat.h"
#include "pss/kelemen.h"

namespace relt {

enum class FamilyKind : uint8_t {
  Kitaoka,  // seed 000: specific, indirect, full and uniform replicas
  Relaxed,  // seed 001: q_k = I + eps_k
};
std::optional<FamilyKind> parseFamily(std::string_view name);
const char* familyName(FamilyKind kind);

using ClassLuminance = std::array<double, kPathClassCount>;
// L_n(u): luminance of the class-n splats of one path; nothing if any splat is not finite.
std::optional<ClassLuminance> classLuminance(const PathSample& sample);

struct FamilySettings {
  FamilyKind kind = FamilyKind::Kitaoka;  // the default: see docs/BENCHMARKS.md (relt equal time)
  int levels = 8;              // relaxed (kitaoka always has 4)
  double relaxedEps1 = 0.01;   // eps_1 as a multiple of the bootstrap mean of I
  double relaxedRatio = 10.0;  // eps_{k+1} / eps_k
  double kitaokaDelta = 0.01;  // weight of L5 in the specific replica
  KelemenSizes sizes;          // the chains' small-step sizes (kitaoka scales them per level)
  float largeStepProbability = 0.3f;
};

class LevelFamily {
 public:
  // `meanTarget` is the bootstrap mean of I(u) = sum_n L_n: relaxed levels scale eps with it so
  // that the ladder does not depend on the scene's brightness.
  LevelFamily(const FamilySettings& settings, double meanTarget);

  FamilyKind kind() const { return kind_; }
  int levels() const { return static_cast<int>(levels_.size()); }
  // q_0..q_{M-1} of a path with class luminances L.
  void targets(const ClassLuminance& L, double* q) const;
  // Whether samples of `level` estimate class n (c[level][n]).
  bool estimates(int level, int cls) const { return levels_[size_t(level)].estimates[size_t(cls)]; }
  const KelemenSizes& sizes(int level) const { return levels_[size_t(level)].sizes; }
  float largeStepProbability(int level) const { return levels_[size_t(level)].largeStepProbability; }
  const std::string& name(int level) const { return levels_[size_t(level)].name; }
  // Offsets and class weights, for stats.json.
  double offset(int level) const { return levels_[size_t(level)].offset; }

 private:
  struct Level {
    std::string name;
    double offset = 0.0;
    std::array<double, kPathClassCount> weight{};
    std::array<bool, kPathClassCount> estimates{};
    KelemenSizes sizes;
    float largeStepProbability = 0.3f;
  };
  FamilyKind kind_;
  std::vector<Level> levels_;
};

}  // namespace relt
