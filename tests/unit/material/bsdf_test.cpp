// Statistical and analytic checks of the BSDFs (pbrt/Mitsuba style).
//
// Significance: every chi-square case uses a fixed seed, so the suite is deterministic. The cases
// share one family-wise significance level of 1% with the Sidak correction (as pbrt does): a case
// fails when p < 1 - 0.99^(1/cases). A wrong sampler or pdf gives p-values many orders of magnitude
// below that (see the negative controls).
#include "material/bsdf.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "chi_square.h"
#include "core/rng.h"
#include "core/sampling.h"
#include "material/fresnel.h"

using namespace relt;
using relt::test::ChiSquareResult;
using relt::test::SphereHistogram;

namespace {

constexpr int kThetaBins = 10, kPhiBins = 20;
constexpr int kChiSquareSamples = 400000;
constexpr double kFamilySignificance = 0.01;

// A tilted normal, so that the tests exercise the world <-> local frame plumbing.
const Vec3 kNormal = glm::normalize(Vec3(0.3f, -0.5f, 0.8f));

Material lambert(Color albedo = Color(0.8f)) {
  Material m;
  m.kind = MaterialKind::Lambert;
  m.baseColor = albedo;
  return m;
}
Material conductor(float alpha, Microfacet d, Color f0 = Color(0.9f, 0.6f, 0.3f)) {
  Material m;
  m.kind = MaterialKind::Conductor;
  m.baseColor = f0;
  m.alpha = alpha;
  m.distribution = d;
  return m;
}
Material dielectric(float alpha, Microfacet d, float ior, Color tint = Color(1.0f)) {
  Material m;
  m.kind = MaterialKind::Dielectric;
  m.baseColor = tint;
  m.alpha = alpha;
  m.distribution = d;
  m.ior = ior;
  return m;
}

// World direction at polar angle thetaDeg from the normal of `frame` (> 90 = below / inside).
Vec3 direction(const Frame& frame, float thetaDeg, float phiDeg = 30.0f) {
  const float t = thetaDeg * kPi / 180.0f, p = phiDeg * kPi / 180.0f;
  return glm::normalize(frame.toWorld(Vec3(std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t))));
}

const char* name(Microfacet d) { return d == Microfacet::GGX ? "GGX" : "Beckmann"; }
const char* name(MaterialKind k) {
  return k == MaterialKind::Lambert ? "Lambert" : k == MaterialKind::Conductor ? "Conductor" : "Dielectric";
}

// FNV-1a: a seed per case that does not depend on the standard library's std::hash.
uint64_t seedOf(const std::string& s) {
  uint64_t h = 1469598103934665603ull;
  for (char ch : s) h = (h ^ uint8_t(ch)) * 1099511628211ull;
  return h;
}

double relativeDifference(const Color& a, const Color& b) {
  const float scale = std::max(maxComponent(glm::abs(a)), maxComponent(glm::abs(b)));
  return scale == 0.0f ? 0.0 : maxComponent(glm::abs(a - b)) / scale;
}

// Integral over the sphere of fn(world direction), on the same grid as the chi-square bins.
double integrateSphere(const Frame& frame, const std::function<double(const Vec3&)>& fn) {
  double sum = 0.0;
  for (int t = 0; t < kThetaBins; ++t)
    for (int p = 0; p < kPhiBins; ++p)
      sum += test::integrateSphereRegion([&](const Vec3& w) { return fn(frame.toWorld(w)); }, M_PI * t / kThetaBins,
                                         M_PI * (t + 1) / kThetaBins, 2 * M_PI * p / kPhiBins,
                                         2 * M_PI * (p + 1) / kPhiBins);
  return sum;
}

struct Case {
  std::string label;
  Material material;
  float thetaDeg;  // polar angle of wo from the geometric normal; > 90 is below / inside
  TransportMode mode = TransportMode::Radiance;
  Vec3 shadingNormal{0.0f};  // zero: same as the geometric normal
};

std::vector<Case> chiSquareCases() {
  std::vector<Case> cases;
  auto add = [&](const std::string& label, const Material& m, std::initializer_list<float> thetas,
                 TransportMode mode = TransportMode::Radiance) {
    for (float t : thetas) cases.push_back({label + "_wo" + std::to_string(int(t)), m, t, mode});
  };
  add("Lambert", lambert(), {0.0f, 45.0f, 89.0f, 135.0f});
  for (Microfacet d : {Microfacet::GGX, Microfacet::Beckmann})
    for (float a : {0.05f, 0.3f, 0.8f})
      add(std::string("Conductor") + name(d) + "_a" + std::to_string(int(a * 100)), conductor(a, d),
          {0.0f, 45.0f, 80.0f, 89.0f, 120.0f});
  for (Microfacet d : {Microfacet::GGX, Microfacet::Beckmann})
    for (float a : {0.1f, 0.5f})
      for (float ior : {1.5f, 1.33f})
        add(std::string("Dielectric") + name(d) + "_a" + std::to_string(int(a * 100)) + "_ior" +
                std::to_string(int(ior * 100)),
            dielectric(a, d, ior), {10.0f, 60.0f, 85.0f, 170.0f, 135.0f, 100.0f});
  // Importance mode samples the same directions; shading normals that differ from ng exercise the
  // consistency of the rejection rules between sample() and pdf().
  add("DielectricImportanceGGX_a30", dielectric(0.3f, Microfacet::GGX, 1.5f), {30.0f, 150.0f},
      TransportMode::Importance);
  const Vec3 bent = glm::normalize(kNormal + Vec3(0.25f, 0.1f, -0.1f));
  for (const Material& m : {lambert(), conductor(0.3f, Microfacet::GGX), dielectric(0.3f, Microfacet::Beckmann, 1.5f)})
    for (float t : {40.0f, 80.0f, 140.0f}) {
      Case c{std::string("BentShadingNormal") + name(m.kind) + "_wo" + std::to_string(int(t)), m, t};
      c.shadingNormal = bent;
      cases.push_back(c);
    }
  return cases;
}

// Keeps gtest from hex-dumping the parameter.
void PrintTo(const Case& c, std::ostream* os) { *os << c.label; }

class BsdfChiSquare : public ::testing::TestWithParam<Case> {};

// The sampled directions follow pdf(): chi-square test over 10 x 20 (theta, phi) bins plus a cell
// for failed samples; pdf() integrated numerically over each bin. Also checks that every sample's f
// and pdf equal eval() and pdf() for its direction, and that pdf() integrates to at most one.
TEST_P(BsdfChiSquare, SamplesFollowPdf) {
  const Case& c = GetParam();
  const Frame frame(kNormal);
  const Vec3 ns = c.shadingNormal == Vec3(0.0f) ? kNormal : c.shadingNormal;
  const Bsdf bsdf(c.material, ns, kNormal);
  ASSERT_FALSE(bsdf.isDelta());
  const Vec3 wo = direction(frame, c.thetaDeg);

  SphereHistogram histogram(kThetaBins, kPhiBins);
  Rng rng(seedOf(c.label));
  int checked = 0;
  for (int i = 0; i < kChiSquareSamples; ++i) {
    const Vec2 u(rng.uniform(), rng.uniform());
    const auto s = bsdf.sample(wo, u, rng.uniform(), c.mode);
    if (!s) {
      histogram.addFailure();
      continue;
    }
    histogram.add(frame.toLocal(s->wi));
    if (checked < 2000) {
      ++checked;
      ASSERT_FALSE(s->delta);
      ASSERT_NEAR(glm::length(s->wi), 1.0f, 1e-4f);
      const Color f = bsdf.eval(wo, s->wi, c.mode);
      const float pdf = bsdf.pdf(wo, s->wi);
      ASSERT_LT(relativeDifference(s->f, f), 1e-3) << "sample " << i;
      ASSERT_NEAR(s->pdf, pdf, 1e-3f * pdf) << "sample " << i;
    }
  }
  auto pdf = [&](const Vec3& local) { return double(bsdf.pdf(wo, frame.toWorld(local))); };
  const std::vector<double> expected = histogram.expectedCounts(pdf);
  double integral = 0.0;
  for (size_t i = 0; i + 1 < expected.size(); ++i) integral += expected[i];
  integral /= histogram.draws();
  EXPECT_LE(integral, 1.0 + 2e-3) << "pdf integrates to more than one";  // 2e-3: cubature error

  const ChiSquareResult r = histogram.test(expected);
  const double cases = double(chiSquareCases().size());
  const double significance = 1.0 - std::pow(1.0 - kFamilySignificance, 1.0 / cases);
  EXPECT_TRUE(r.passes(significance)) << r.describe();
  RecordProperty("p_value", std::to_string(r.pValue));
}

INSTANTIATE_TEST_SUITE_P(AllRoughBsdfs, BsdfChiSquare, ::testing::ValuesIn(chiSquareCases()),
                         [](const ::testing::TestParamInfo<Case>& param) { return param.param.label; });

// ---- Negative controls: the chi-square machinery must be able to fail. ----

TEST(BsdfChiSquareControl, RejectsLambertSamplesAgainstUniformHemispherePdf) {
  const Frame frame(kNormal);
  const Material m = lambert();
  const Bsdf bsdf(m, kNormal, kNormal);
  const Vec3 wo = direction(frame, 30.0f);
  SphereHistogram histogram(kThetaBins, kPhiBins);
  Rng rng(7);
  for (int i = 0; i < 100000; ++i) {
    const auto s = bsdf.sample(wo, Vec2(rng.uniform(), rng.uniform()), rng.uniform(), TransportMode::Radiance);
    s ? histogram.add(frame.toLocal(s->wi)) : histogram.addFailure();
  }
  const ChiSquareResult wrong = histogram.test([](const Vec3& w) { return w.z > 0.0f ? double(kInv2Pi) : 0.0; });
  EXPECT_LT(wrong.pValue, 1e-10) << wrong.describe();
  const ChiSquareResult right = histogram.test([](const Vec3& w) { return double(cosineHemispherePdf(w.z)); });
  EXPECT_GT(right.pValue, 0.01) << right.describe();
}

TEST(BsdfChiSquareControl, RejectsGgxSamplesAgainstBeckmannPdf) {
  const Frame frame(kNormal);
  const Material ggx = conductor(0.3f, Microfacet::GGX), beckmann = conductor(0.3f, Microfacet::Beckmann);
  const Bsdf sampler(ggx, kNormal, kNormal), wrongPdf(beckmann, kNormal, kNormal);
  const Vec3 wo = direction(frame, 45.0f);
  SphereHistogram histogram(kThetaBins, kPhiBins);
  Rng rng(8);
  for (int i = 0; i < 100000; ++i) {
    const auto s = sampler.sample(wo, Vec2(rng.uniform(), rng.uniform()), rng.uniform(), TransportMode::Radiance);
    s ? histogram.add(frame.toLocal(s->wi)) : histogram.addFailure();
  }
  const ChiSquareResult r = histogram.test([&](const Vec3& w) { return double(wrongPdf.pdf(wo, frame.toWorld(w))); });
  EXPECT_LT(r.pValue, 1e-6) << r.describe();
}

// ---- Energy (white furnace): integral over wi of f |cos wi|. ----

double albedo(const Bsdf& bsdf, const Vec3& wo, TransportMode mode) {
  const Frame frame(kNormal);
  const Vec3 ns = bsdf.frame().n;
  return integrateSphere(
      frame, [&](const Vec3& wi) { return double(luminance(bsdf.eval(wo, wi, mode))) * std::abs(glm::dot(wi, ns)); });
}

TEST(BsdfEnergy, WhiteLambertReflectsEverything) {
  const Frame frame(kNormal);
  const Material m = lambert(Color(1.0f));
  const Bsdf bsdf(m, kNormal, kNormal);
  for (float t : {0.0f, 60.0f, 150.0f})
    EXPECT_NEAR(albedo(bsdf, direction(frame, t), TransportMode::Radiance), 1.0, 1e-3);
}

// Tolerance 2e-3 covers the numerical integration; the height-correlated Smith model loses energy
// to the missing multiple scattering, more so for rough surfaces at grazing angles.
TEST(BsdfEnergy, RoughConductorWithUnitF0ConservesEnergy) {
  const Frame frame(kNormal);
  for (Microfacet d : {Microfacet::GGX, Microfacet::Beckmann})
    for (float a : {0.05f, 0.3f, 0.8f}) {
      const Material m = conductor(a, d, Color(1.0f));
      const Bsdf bsdf(m, kNormal, kNormal);
      for (float t : {0.0f, 45.0f, 80.0f, 89.0f}) {
        const double e = albedo(bsdf, direction(frame, t), TransportMode::Radiance);
        EXPECT_LE(e, 1.0 + 2e-3) << name(d) << " alpha " << a << " theta " << t;
        // Single scattering loses the energy of reflections below the horizon: at normal incidence
        // on GGX, 1 - 1 / (1 + alpha^2) of the visible normals tilt by more than 45 degrees.
        if (t <= 45.0f) {
          EXPECT_GT(e, a < 0.1f ? 0.97 : a < 0.5f ? 0.8 : 0.35) << name(d) << " alpha " << a << " theta " << t;
        }
      }
    }
}

TEST(BsdfEnergy, RoughDielectricInImportanceModeConservesEnergy) {
  const Frame frame(kNormal);
  for (Microfacet d : {Microfacet::GGX, Microfacet::Beckmann})
    for (float a : {0.1f, 0.5f})
      for (float ior : {1.5f, 1.33f}) {
        const Material m = dielectric(a, d, ior);
        const Bsdf bsdf(m, kNormal, kNormal);
        for (float t : {0.0f, 60.0f, 85.0f, 180.0f, 150.0f, 100.0f}) {
          const double e = albedo(bsdf, direction(frame, t), TransportMode::Importance);
          EXPECT_LE(e, 1.0 + 2e-3) << name(d) << " alpha " << a << " ior " << ior << " theta " << t;
          if (t == 0.0f || t == 180.0f) {
            EXPECT_GT(e, a < 0.3f ? 0.95 : 0.7) << name(d) << " alpha " << a << " ior " << ior;
          }
        }
      }
}

// The mean sampling weight f |cos| / pdf estimates the same integral.
TEST(BsdfEnergy, SamplingWeightsEstimateTheAlbedo) {
  const Frame frame(kNormal);
  const Material materials[] = {lambert(Color(0.5f)), conductor(0.3f, Microfacet::Beckmann, Color(1.0f)),
                                dielectric(0.5f, Microfacet::GGX, 1.5f)};
  Rng rng(11);
  for (const Material& m : materials) {
    const Bsdf bsdf(m, kNormal, kNormal);
    for (float t : {20.0f, 70.0f, 160.0f}) {
      const Vec3 wo = direction(frame, t);
      const int n = 200000;
      double sum = 0.0;
      for (int i = 0; i < n; ++i) {
        const auto s = bsdf.sample(wo, Vec2(rng.uniform(), rng.uniform()), rng.uniform(), TransportMode::Importance);
        if (s) sum += luminance(s->f) * std::abs(glm::dot(s->wi, kNormal)) / s->pdf;
      }
      EXPECT_NEAR(sum / n, albedo(bsdf, wo, TransportMode::Importance), 5e-3) << int(m.kind) << " theta " << t;
    }
  }
}

// ---- Reciprocity. ----

// Reflection: f(wo, wi) = f(wi, wo). Transmission in Radiance mode (Veach 1997 Eq. 5.14, light
// flowing from wi to wo): f(wo, wi) / eta_o^2 = f(wi, wo) / eta_i^2, eta_x the index on x's side.
// Importance mode is the adjoint: f_imp(wo, wi) = f_rad(wi, wo).
TEST(BsdfReciprocity, ReflectionIsSymmetricAndTransmissionObeysTheEtaSquaredRule) {
  const Frame frame(kNormal);
  std::vector<Material> materials = {lambert()};
  for (Microfacet d : {Microfacet::GGX, Microfacet::Beckmann})
    for (float a : {0.05f, 0.3f, 0.8f}) {
      materials.push_back(conductor(a, d));
      materials.push_back(dielectric(a, d, 1.5f, Color(0.9f, 0.8f, 0.7f)));
    }
  Rng rng(3);
  int transmissions = 0, reflections = 0;
  for (const Material& m : materials) {
    const Bsdf bsdf(m, kNormal, kNormal);
    for (int i = 0; i < 4000; ++i) {
      const Vec3 wo = uniformSphere(Vec2(rng.uniform(), rng.uniform()));
      const auto s = bsdf.sample(wo, Vec2(rng.uniform(), rng.uniform()), rng.uniform(), TransportMode::Radiance);
      if (!s) continue;
      const Vec3 wi = s->wi;
      const Color fwd = bsdf.eval(wo, wi, TransportMode::Radiance);
      const Color rev = bsdf.eval(wi, wo, TransportMode::Radiance);
      const float go = glm::dot(wo, kNormal), gi = glm::dot(wi, kNormal);
      if (go * gi > 0.0f) {
        ++reflections;
        ASSERT_LT(relativeDifference(fwd, rev), 1e-3) << "reflection, kind " << int(m.kind);
      } else {
        ++transmissions;
        const float etaO = go > 0.0f ? 1.0f : m.ior, etaI = gi > 0.0f ? 1.0f : m.ior;
        ASSERT_LT(relativeDifference(fwd / (etaO * etaO), rev / (etaI * etaI)), 1e-3) << "alpha " << m.alpha;
        ASSERT_LT(relativeDifference(bsdf.eval(wo, wi, TransportMode::Importance), rev), 1e-3);
        ASSERT_LT(relativeDifference(bsdf.eval(wi, wo, TransportMode::Importance), fwd), 1e-3);
      }
    }
  }
  EXPECT_GT(reflections, 10000);
  EXPECT_GT(transmissions, 5000);
}

// ---- Smooth (delta) lobes. ----

TEST(SmoothConductor, SamplesTheMirrorDirectionWithSchlickWeight) {
  const Frame frame(kNormal);
  const Material m = conductor(0.0f, Microfacet::GGX, Color(0.9f, 0.6f, 0.3f));
  const Bsdf bsdf(m, kNormal, kNormal);
  EXPECT_TRUE(bsdf.isDelta());
  for (float t : {0.0f, 50.0f, 85.0f, 130.0f}) {
    const Vec3 wo = direction(frame, t);
    const auto s = bsdf.sample(wo, Vec2(0.3f, 0.7f), 0.5f, TransportMode::Radiance);
    ASSERT_TRUE(s);
    EXPECT_TRUE(s->delta);
    EXPECT_EQ(s->pdf, 1.0f);
    const Vec3 mirror = 2.0f * glm::dot(wo, kNormal) * kNormal - wo;
    EXPECT_NEAR(glm::distance(s->wi, mirror), 0.0f, 1e-5f);
    const float cosI = std::abs(glm::dot(s->wi, kNormal));
    EXPECT_LT(relativeDifference(s->f * cosI, fresnelSchlick(m.baseColor, cosI)), 1e-5);
    EXPECT_EQ(bsdf.eval(wo, s->wi, TransportMode::Radiance), Color(0.0f));
    EXPECT_EQ(bsdf.pdf(wo, s->wi), 0.0f);
  }
}

TEST(SmoothDielectric, ReflectsWithProbabilityFAndRefractsBySnellsLaw) {
  const Frame frame(kNormal);
  const float ior = 1.5f;
  const Color tint(0.9f, 0.8f, 0.7f);
  const Material m = dielectric(0.0f, Microfacet::GGX, ior, tint);
  const Bsdf bsdf(m, kNormal, kNormal);
  EXPECT_TRUE(bsdf.isDelta());
  EXPECT_NEAR(fresnelDielectric(1.0f, ior), 0.04f, 1e-6f);
  for (float t : {0.0f, 30.0f, 70.0f, 89.0f}) {
    const Vec3 wo = direction(frame, t);
    const float cosO = std::cos(t * kPi / 180.0f);
    const float F = fresnelDielectric(cosO, ior);
    // Reflection for uLobe < F.
    const auto r = bsdf.sample(wo, Vec2(0.5f), 0.999f * F, TransportMode::Radiance);
    ASSERT_TRUE(r);
    EXPECT_TRUE(r->delta);
    EXPECT_NEAR(r->pdf, F, 1e-6f);
    EXPECT_NEAR(glm::distance(r->wi, 2.0f * cosO * kNormal - wo), 0.0f, 1e-5f);
    EXPECT_NEAR(luminance(r->f) * std::abs(glm::dot(r->wi, kNormal)), F, 1e-5f);
    // Refraction for uLobe >= F: sin(theta_t) = sin(theta_o) / ior, in the plane of incidence.
    for (TransportMode mode : {TransportMode::Radiance, TransportMode::Importance}) {
      const auto s = bsdf.sample(wo, Vec2(0.5f), std::min(F * 1.001f + 1e-4f, 0.9999f), mode);
      ASSERT_TRUE(s);
      EXPECT_TRUE(s->delta);
      EXPECT_NEAR(s->pdf, 1.0f - F, 1e-6f);
      const float cosT = std::sqrt(1.0f - (1.0f - cosO * cosO) / (ior * ior));
      const Vec3 expected = -wo / ior + (cosO / ior - cosT) * kNormal;
      EXPECT_NEAR(glm::distance(s->wi, expected), 0.0f, 1e-5f) << "theta " << t;
      EXPECT_NEAR(glm::dot(s->wi, kNormal), -cosT, 1e-5f);
      // Weight f |cos| / pdf: the tint, over eta^2 for radiance entering the denser medium.
      const Color weight = s->f * cosT / s->pdf;
      const Color want = mode == TransportMode::Radiance ? tint / (ior * ior) : tint;
      EXPECT_LT(relativeDifference(weight, want), 1e-4) << "theta " << t;
      EXPECT_LT(relativeDifference(s->f * cosT, want * (1.0f - F)), 1e-4);
    }
  }
}

TEST(SmoothDielectric, FromInsideRefractsOutWithEtaSquaredGainOrReflectsTotally) {
  const Frame frame(kNormal);
  const float ior = 1.5f;
  const Material m = dielectric(0.0f, Microfacet::GGX, ior);
  const Bsdf bsdf(m, kNormal, kNormal);
  const float critical = std::asin(1.0f / ior) * 180.0f / kPi;  // 41.8 degrees
  // Below the critical angle: refraction out, radiance weight (1 - F) eta^2 / (1 - F) = eta^2.
  {
    const float t = 20.0f;
    const Vec3 wo = direction(frame, 180.0f - t);
    const float cosO = std::cos(t * kPi / 180.0f);
    const float F = fresnelDielectric(-cosO, ior);
    EXPECT_NEAR(F, fresnelDielectric(cosO, 1.0f / ior), 1e-6f);
    const auto s = bsdf.sample(wo, Vec2(0.5f), 0.99f, TransportMode::Radiance);
    ASSERT_TRUE(s);
    const float sinT = std::sin(t * kPi / 180.0f) * ior;
    EXPECT_NEAR(glm::dot(s->wi, kNormal), std::sqrt(1.0f - sinT * sinT), 1e-5f);
    EXPECT_NEAR(s->pdf, 1.0f - F, 1e-6f);
    EXPECT_NEAR(luminance(s->f) * glm::dot(s->wi, kNormal) / s->pdf, ior * ior, 1e-4f);
  }
  // Beyond it: total internal reflection whatever uLobe is.
  for (float t : {critical + 0.5f, 60.0f, 89.0f}) {
    const Vec3 wo = direction(frame, 180.0f - t);
    EXPECT_EQ(fresnelDielectric(-std::cos(t * kPi / 180.0f), ior), 1.0f);
    for (float uLobe : {0.0f, 0.5f, 0.99999f}) {
      const auto s = bsdf.sample(wo, Vec2(0.5f), uLobe, TransportMode::Radiance);
      ASSERT_TRUE(s);
      EXPECT_EQ(s->pdf, 1.0f);
      EXPECT_LT(glm::dot(s->wi, kNormal), 0.0f);
      EXPECT_NEAR(glm::distance(s->wi, 2.0f * glm::dot(wo, kNormal) * kNormal - wo), 0.0f, 1e-5f);
    }
  }
}

// Fresnel transmittance is the same for light going either way through the interface.
TEST(Fresnel, TransmittanceIsReciprocal) {
  for (float ior : {1.33f, 1.5f, 2.4f})
    for (float t = 0.0f; t < 89.0f; t += 7.0f) {
      const float cosO = std::cos(t * kPi / 180.0f);
      const float cosT = std::sqrt(1.0f - (1.0f - cosO * cosO) / (ior * ior));
      EXPECT_NEAR(fresnelDielectric(cosO, ior), fresnelDielectric(-cosT, ior), 1e-5f);
    }
}

// ---- Roughness override (tempering). ----

TEST(BsdfRoughnessOverride, SmoothGlassWithTinyBeckmannAlphaIsAMicrofacetLobe) {
  const Frame frame(kNormal);
  const Material m = dielectric(0.0f, Microfacet::GGX, 1.5f);
  const Bsdf bsdf(m, kNormal, kNormal, Roughness{1e-4f, Microfacet::Beckmann});
  EXPECT_FALSE(bsdf.isDelta());
  EXPECT_EQ(bsdf.roughness().distribution, Microfacet::Beckmann);
  const Vec3 wo = direction(frame, 40.0f);
  const float cosO = std::cos(40.0f * kPi / 180.0f);
  const float F = fresnelDielectric(cosO, 1.5f);
  Rng rng(5);
  int reflected = 0, n = 20000;
  for (int i = 0; i < n; ++i) {
    const auto s = bsdf.sample(wo, Vec2(rng.uniform(), rng.uniform()), rng.uniform(), TransportMode::Radiance);
    ASSERT_TRUE(s);
    EXPECT_FALSE(s->delta);
    ASSERT_TRUE(std::isfinite(s->pdf) && isFinite(s->f));
    const bool isReflection = glm::dot(s->wi, kNormal) > 0.0f;
    reflected += isReflection;
    const float cosT = std::sqrt(1.0f - (1.0f - cosO * cosO) / 2.25f);
    const Vec3 specular = isReflection ? 2.0f * cosO * kNormal - wo : -wo / 1.5f + (cosO / 1.5f - cosT) * kNormal;
    ASSERT_LT(glm::distance(s->wi, specular), 2e-3f);
    ASSERT_GT(luminance(bsdf.eval(wo, s->wi, TransportMode::Radiance)), 0.0f);
    // Near-specular weights match smooth glass: 1 for reflection, 1 / eta^2 for radiance entering.
    const float weight = luminance(s->f) * std::abs(glm::dot(s->wi, kNormal)) / s->pdf;
    ASSERT_NEAR(weight, isReflection ? 1.0f : 1.0f / 2.25f, 1e-3f);
  }
  EXPECT_NEAR(reflected / double(n), F, 4.0 * std::sqrt(F * (1 - F) / n));
}

TEST(BsdfRoughnessOverride, RoughensConductorsAndIsIgnoredByLambert) {
  const Material mirror = conductor(0.0f, Microfacet::GGX);
  EXPECT_TRUE(Bsdf(mirror, kNormal, kNormal).isDelta());
  const Bsdf rough(mirror, kNormal, kNormal, Roughness{0.5f, Microfacet::GGX});
  EXPECT_FALSE(rough.isDelta());
  const Frame frame(kNormal);
  EXPECT_GT(luminance(rough.eval(direction(frame, 30.0f), direction(frame, 50.0f, 200.0f), TransportMode::Radiance)),
            0.0f);
  const Material diffuse = lambert();
  const Bsdf l(diffuse, kNormal, kNormal, Roughness{0.0f, Microfacet::Beckmann});
  EXPECT_FALSE(l.isDelta());
  EXPECT_LT(relativeDifference(l.eval(direction(frame, 30.0f), direction(frame, 60.0f), TransportMode::Radiance),
                               diffuse.baseColor * kInvPi),
            1e-6);
}

// ---- Geometry and robustness. ----

TEST(BsdfGeometry, OpaqueMaterialsAreTwoSidedAndDoNotTransmit) {
  const Frame frame(kNormal);
  for (const Material& m : {lambert(), conductor(0.3f, Microfacet::GGX)}) {
    const Bsdf bsdf(m, kNormal, kNormal);
    const Vec3 a = direction(frame, 30.0f), b = direction(frame, 60.0f, 200.0f);
    const Color front = bsdf.eval(a, b, TransportMode::Radiance);
    EXPECT_GT(luminance(front), 0.0f);
    // The same configuration seen from the back side.
    const Vec3 ra = direction(frame, 150.0f), rb = direction(frame, 120.0f, 200.0f);
    EXPECT_LT(relativeDifference(bsdf.eval(ra, rb, TransportMode::Radiance), front), 1e-4);
    EXPECT_EQ(bsdf.eval(a, rb, TransportMode::Radiance), Color(0.0f));
    EXPECT_EQ(bsdf.pdf(a, rb), 0.0f);
  }
}

// Reflection per ng but opposite hemispheres per the shading normal: zero (and vice versa).
TEST(BsdfGeometry, ShadingAndGeometricNormalsMustAgree) {
  const Vec3 ng(0.0f, 0.0f, 1.0f), ns = glm::normalize(Vec3(0.6f, 0.0f, 0.8f));
  const Vec3 wo = glm::normalize(Vec3(0.2f, 0.1f, 0.9f));
  const Vec3 wi = glm::normalize(Vec3(-0.95f, 0.0f, 0.1f));  // above ng, below the shading plane
  ASSERT_GT(glm::dot(wi, ng), 0.0f);
  ASSERT_LT(glm::dot(wi, ns), 0.0f);
  for (const Material& m : {lambert(), conductor(0.5f, Microfacet::GGX), dielectric(0.5f, Microfacet::GGX, 1.5f)}) {
    const Bsdf bsdf(m, ns, ng);
    EXPECT_EQ(bsdf.eval(wo, wi, TransportMode::Radiance), Color(0.0f)) << int(m.kind);
    EXPECT_EQ(bsdf.pdf(wo, wi), 0.0f);
  }
}

TEST(BsdfGeometry, DielectricOutsideIsWhereTheGeometricNormalPoints) {
  // Same glass, geometric normal flipped: the roles of the two sides swap.
  const Vec3 n(0.0f, 0.0f, 1.0f);
  const Material m = dielectric(0.0f, Microfacet::GGX, 1.5f);
  const Vec3 wo = glm::normalize(Vec3(0.8f, 0.0f, 0.6f));  // 53 degrees: TIR only if inside
  const auto fromOutside = Bsdf(m, n, n).sample(wo, Vec2(0.5f), 0.99f, TransportMode::Radiance);
  const auto fromInside = Bsdf(m, n, -n).sample(wo, Vec2(0.5f), 0.99f, TransportMode::Radiance);
  ASSERT_TRUE(fromOutside && fromInside);
  EXPECT_LT(fromOutside->wi.z, 0.0f);  // refracted
  EXPECT_GT(fromInside->wi.z, 0.0f);   // totally reflected
  EXPECT_EQ(fromInside->pdf, 1.0f);
}

TEST(BsdfRobustness, NeverProducesNanOrInfAndEvaluateMatchesEvalAndPdf) {
  std::vector<Material> materials = {lambert(), conductor(0.0f, Microfacet::GGX),
                                     dielectric(0.0f, Microfacet::GGX, 1.5f)};
  for (Microfacet d : {Microfacet::GGX, Microfacet::Beckmann})
    for (float a : {1e-4f, 0.01f, 0.3f, 1.0f}) {
      materials.push_back(conductor(a, d));
      materials.push_back(dielectric(a, d, 1.5f));
      materials.push_back(dielectric(a, d, 1.0001f));
    }
  const Vec3 n(0.0f, 0.0f, 1.0f);
  const Vec3 special[] = {Vec3(1, 0, 0),
                          Vec3(0, 0, 1),
                          Vec3(0, 0, -1),
                          glm::normalize(Vec3(1, 0, 1e-7f)),
                          glm::normalize(Vec3(1, 0, -1e-7f)),
                          glm::normalize(Vec3(0.6f, 0.0f, 0.8f)),
                          glm::normalize(Vec3(-0.6f, 0.0f, -0.8f))};
  Rng rng(9);
  for (const Material& m : materials) {
    const Bsdf bsdf(m, n, n);
    auto check = [&](const Vec3& wo, const Vec3& wi) {
      for (TransportMode mode : {TransportMode::Radiance, TransportMode::Importance}) {
        const Color f = bsdf.eval(wo, wi, mode);
        ASSERT_TRUE(isFinite(f) && f.x >= 0.0f && f.y >= 0.0f && f.z >= 0.0f) << int(m.kind) << " " << m.alpha;
        const float p = bsdf.pdf(wo, wi);
        ASSERT_TRUE(std::isfinite(p) && p >= 0.0f);
        const Bsdf::Value v = bsdf.evaluate(wo, wi, mode);  // the fused call agrees exactly
        ASSERT_EQ(v.f, f);
        ASSERT_EQ(v.pdf, p);
      }
    };
    for (const Vec3& a : special)
      for (const Vec3& b : special) check(a, b);
    for (int i = 0; i < 20000; ++i) {
      const Vec3 wo = i % 2 ? uniformSphere(Vec2(rng.uniform(), rng.uniform())) : special[i / 2 % 7];
      const Vec2 u(i % 5 == 0 ? 0.0f : rng.uniform(), i % 7 == 0 ? 0.99999994f : rng.uniform());
      const auto s = bsdf.sample(wo, u, rng.uniform(), i % 3 ? TransportMode::Radiance : TransportMode::Importance);
      if (s) {
        ASSERT_TRUE(isFinite(s->f) && std::isfinite(s->pdf) && s->pdf > 0.0f) << int(m.kind) << " " << m.alpha;
        ASSERT_TRUE(std::isfinite(s->wi.x) && std::isfinite(s->wi.y) && std::isfinite(s->wi.z));
      }
      check(wo, uniformSphere(Vec2(rng.uniform(), rng.uniform())));
    }
  }
}

}  // namespace
