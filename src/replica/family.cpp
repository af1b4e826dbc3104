#include "replica/family.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace relt {

std::optional<FamilyKind> parseFamily(std::string_view name) {
  for (FamilyKind kind : {FamilyKind::Kitaoka, FamilyKind::Relaxed, FamilyKind::Tempered})
    if (name == familyName(kind)) return kind;
  return std::nullopt;
}

const char* familyName(FamilyKind kind) {
  switch (kind) {
    case FamilyKind::Kitaoka: return "kitaoka";
    case FamilyKind::Relaxed: return "relaxed";
    case FamilyKind::Tempered: return "tempered";
  }
  return "?";
}

std::optional<ClassLuminance> classLuminance(const PathSample& sample) {
  ClassLuminance L{};
  for (const Splat& s : sample.splats) {
    if (!isFinite(s.value)) return std::nullopt;
    L[static_cast<size_t>(s.cls)] += luminance(s.value);
  }
  return L;
}

uint64_t idleLevels(const FamilySettings& settings, const std::vector<double>& bootstrap) {
  if (settings.kind == FamilyKind::Tempered) return 0;
  FamilySettings full = settings;
  full.leftOut = 0;
  const double meanTarget = LevelFamily::meanTarget(full, bootstrap);
  if (!(meanTarget > 0.0)) return 0;  // a black bootstrap: nothing to choose by
  const LevelFamily family(full, meanTarget);
  const size_t m = size_t(family.levels()), n = size_t(kPathClassCount);
  std::vector<double> target(m, 0.0), q(m);
  std::array<double, kPathClassCount> cls{};
  for (size_t i = 0; i + n <= bootstrap.size(); i += n) {
    family.targets(bootstrap.data() + i, q.data());
    for (size_t k = 0; k < m; ++k) target[k] += q[k];
    for (size_t c = 0; c < n; ++c) cls[c] += bootstrap[i + c];
  }
  uint64_t idle = 0;
  for (size_t k = 0; k < m; ++k) {
    bool estimatesSome = false;
    for (size_t c = 0; c < n; ++c) estimatesSome = estimatesSome || (family.estimates(int(k), int(c)) && cls[c] > 0.0);
    if (!(target[k] > 0.0) || !estimatesSome) idle |= uint64_t(1) << k;
  }
  return idle == (uint64_t(1) << m) - 1 ? 0 : idle;
}

LevelFamily::LevelFamily(const FamilySettings& settings, double meanTarget) : kind_(settings.kind) {
  buildLadder(settings, meanTarget);
  leaveOut(settings.leftOut);
}

std::vector<std::string> LevelFamily::leftOutNames(const FamilySettings& settings) {
  FamilySettings full = settings;
  full.leftOut = 0;
  const LevelFamily family(full, 1.0);
  std::vector<std::string> names;
  for (int k = 0; k < family.levels(); ++k)
    if (settings.leftOut >> k & 1) names.push_back(family.name(k));
  return names;
}

// Without the given levels. A class none of the rest estimated goes to each remaining level whose
// target is positive wherever that class is (an offset, or a weight on the class), so the levels
// that estimate it still cover it; for kitaoka that is all three.
void LevelFamily::leaveOut(uint64_t out) {
  if (!out) return;
  if (kind_ == FamilyKind::Tempered) throw std::invalid_argument("tempered levels are never left out");
  std::array<bool, kPathClassCount> covered{}, orphaned{};
  std::vector<Level> kept;
  for (size_t k = 0; k < levels_.size(); ++k) {
    const bool leave = k < 64 && (out >> k & 1);
    for (size_t n = 0; n < kPathClassCount; ++n) (leave ? orphaned : covered)[n] |= levels_[k].estimates[n];
    if (!leave) kept.push_back(levels_[k]);
  }
  if (kept.empty()) throw std::invalid_argument("every level of the ladder left out");
  for (size_t n = 0; n < kPathClassCount; ++n) {
    if (!orphaned[n] || covered[n]) continue;
    for (Level& level : kept) {
      level.estimates[n] = level.offset > 0.0 || level.weight[n] > 0.0;
      covered[n] = covered[n] || level.estimates[n];
    }
    if (!covered[n]) throw std::invalid_argument("no level that remains reaches a class of the left-out ones");
  }
  levels_ = std::move(kept);
}

void LevelFamily::buildLadder(const FamilySettings& settings, double meanTarget) {
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
  if (kind_ == FamilyKind::Tempered) {
    // Every level estimates every class; its target comes from the path builder.
    temperatures_ = geometricTemperatures(settings.levels, settings.temperatureMax);
    for (double t : temperatures_) {
      char name[32];
      std::snprintf(name, sizeof name, "T=%.4g", t);
      Level level{name, 0.0, {}, {}, settings.sizes, settings.largeStepProbability};
      level.estimates.fill(true);
      levels_.push_back(level);
      tempering_.scale.push_back(static_cast<float>(std::sqrt(t)));
    }
    regularisation_ = settings.regularisation;
    regularisationDecay_ = settings.regularisationDecay;
    setRegularisationStep(0);
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

int LevelFamily::featureCount(const FamilySettings& settings) {
  return settings.kind == FamilyKind::Tempered ? settings.levels : kPathClassCount;
}

double LevelFamily::meanTarget(const FamilySettings& settings, const std::vector<double>& features) {
  const size_t n = size_t(featureCount(settings)), samples = features.size() / n;
  double sum = 0.0;
  for (size_t i = 0; i < samples; ++i) {
    if (settings.kind == FamilyKind::Tempered) {
      sum += features[i * n];  // level 0: T = 1
    } else {
      for (size_t c = 0; c < n; ++c) sum += features[i * n + c];
    }
  }
  return samples ? sum / double(samples) : 0.0;
}

bool LevelFamily::features(const PathSample& sample, std::span<const double> levelTargets, double* f) const {
  const std::optional<ClassLuminance> L = classLuminance(sample);
  if (kind_ != FamilyKind::Tempered) {
    if (L) std::copy(L->begin(), L->end(), f);
    else std::fill_n(f, kPathClassCount, 0.0);
    return L.has_value();
  }
  for (int k = 0; k < levels(); ++k) {
    const double q = L && size_t(k) < levelTargets.size() ? levelTargets[size_t(k)] : 0.0;
    f[k] = std::isfinite(q) && q > 0.0 ? q : 0.0;  // a non-finite tempered value only loses that level
  }
  return L.has_value();
}

void LevelFamily::targets(const double* f, double* q) const {
  if (kind_ == FamilyKind::Tempered) {
    std::copy_n(f, levels_.size(), q);
    return;
  }
  for (size_t k = 0; k < levels_.size(); ++k) {
    double v = levels_[k].offset;
    for (size_t n = 0; n < kPathClassCount; ++n) v += levels_[k].weight[n] * f[n];
    q[k] = v;
  }
}

bool LevelFamily::setRegularisationStep(uint64_t n) {
  if (!(regularisation_ > 0.0)) return false;
  const float reg = float(regularisation_ * std::pow(1.0 + double(n), -regularisationDecay_));
  if (n > 0 && std::abs(reg - tempering_.minAlpha) < 0.01f * tempering_.minAlpha) return false;
  tempering_.minAlpha = reg;
  return n > 0;
}

}  // namespace relt
