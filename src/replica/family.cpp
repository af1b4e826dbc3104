#include "replica/family.h"

#include <cmath>

namespace relt {

std::optional<FamilyKind> parseFamily(std::string_view name) {
  if (name == "kitaoka") return FamilyKind::Kitaoka;
  if (name == "relaxed") return FamilyKind::Relaxed;
  return std::nullopt;
}

const char* familyName(FamilyKind kind) { return kind == FamilyKind::Kitaoka ? "kitaoka" : "relaxed"; }

std::optional<ClassLuminance> classLuminance(const PathSample& sample) {
  ClassLuminance L{};
  for (const Splat& s : sample.splats) {
    if (!isFinite(s.value)) return std::nullopt;
    L[static_cast<size_t>(s.cls)] += luminance(s.value);
  }
  return L;
}

LevelFamily::LevelFamily(const FamilySettings& settings, double meanTarget) : kind_(settings.kind) {
  if (kind_ == FamilyKind::Kitaoka) {
    // Kitaoka et al.'s replicas (Sec. 4.2.3) from the most specific to the uniform one, so that
    // neighbours in the ladder are neighbours in their exchange order. Class L0 (implicit paths
    // with a specular bounce) is estimated by the specific replica alone (Sec. 5.1.4), every
    // other class by the other three. Their mutation sizes keep s2 = 16 s1 (Eq. 24); the specific
    // replica takes finer steps (s1 two thirds of the others'). Unlike the paper, the full level
    // keeps L1 (directly seen emitters), which otherwise only the uniform level would sample.
    const double d = settings.kitaokaDelta;
    const KelemenSizes normal{settings.sizes.s1, 16.0f * settings.sizes.s1};
    const KelemenSizes fine{settings.sizes.s1 * (2.0f / 3.0f), 16.0f * settings.sizes.s1 * (2.0f / 3.0f)};
    const float pl = settings.largeStepProbability;
    const std::array<bool, kPathClassCount> onlyL0{true, false, false, false, false, false};
    const std::array<bool, kPathClassCount> allButL0{false, true, true, true, true, true};
    levels_.push_back({"specific", 0.0, {1, 0, 0, 0, 0, d}, onlyL0, fine, pl});
    levels_.push_back({"indirect", 0.0, {1, 0, 0, 1, 1, 1}, allButL0, normal, pl});
    levels_.push_back({"full", 0.0, {1, 1, 1, 1, 1, 1}, allButL0, normal, pl});
    // q = 1, b = 1: independent uniform samples, so the ladder reaches every path.
    levels_.push_back({"uniform", 1.0, {0, 0, 0, 0, 0, 0}, allButL0, normal, 1.0f});
    return;
  }
  // Relaxed (Otsu et al.): q_k = I + eps_k, eps_0 = 0, eps_k = eps_1 ratio^(k-1) * mean I.
  for (int k = 0; k < settings.levels; ++k) {
    const double eps = k == 0 ? 0.0 : settings.relaxedEps1 * std::pow(settings.relaxedRatio, k - 1) * meanTarget;
    Level level{"eps=" + std::to_string(eps), eps, {1, 1, 1, 1, 1, 1}, {}, settings.sizes,
                settings.largeStepProbability};
    level.estimates.fill(true);
    levels_.push_back(level);
  }
}

void LevelFamily::targets(const ClassLuminance& L, double* q) const {
  for (size_t k = 0; k < levels_.size(); ++k) {
    double v = levels_[k].offset;
    for (size_t n = 0; n < L.size(); ++n) v += levels_[k].weight[n] * L[n];
    q[k] = v;
  }
}

}  // namespace relt
