// Properties of the microfacet distributions on their own, independent of the BSDFs built on them.
#include "material/microfacet.h"

#include <gtest/gtest.h>

#include <cmath>

#include "chi_square.h"
#include "core/rng.h"

using namespace relt;

namespace {

double hemisphereIntegral(const std::function<double(const Vec3&)>& fn) {
  test::QuadratureTolerance tol;
  tol.initialSplits = 8;
  return test::integrateSphereRegion(fn, 0.0, M_PI / 2, 0.0, 2 * M_PI, tol);
}

Vec3 polar(float thetaDeg, float phiDeg = 20.0f) {
  const float t = thetaDeg * kPi / 180.0f, p = phiDeg * kPi / 180.0f;
  return Vec3(std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t));
}

// The projected microfacet area equals the macro-surface area: integral of D(m) m.z = 1.
TEST(Microfacet, ProjectedAreaOfMicrofacetsIsOne) {
  for (Microfacet type : {Microfacet::GGX, Microfacet::Beckmann})
    for (float alpha : {0.02f, 0.1f, 0.5f, 1.0f}) {
      const MicrofacetDistribution d(type, alpha);
      EXPECT_NEAR(hemisphereIntegral([&](const Vec3& m) { return double(d.D(m)) * m.z; }), 1.0, 2e-3)
          << int(type) << " alpha " << alpha;
    }
}

// Smith's Lambda is tied to D: the visible normals seen from any direction form a density
// (integral of G1(w) max(0, w.m) D(m) / w.z = 1), which fails if Lambda and D disagree.
TEST(Microfacet, VisibleNormalDensityIntegratesToOne) {
  for (Microfacet type : {Microfacet::GGX, Microfacet::Beckmann})
    for (float alpha : {0.05f, 0.3f, 1.0f})
      for (float theta : {0.0f, 40.0f, 75.0f, 88.0f}) {
        const MicrofacetDistribution d(type, alpha);
        const Vec3 w = polar(theta);
        EXPECT_NEAR(hemisphereIntegral([&](const Vec3& m) { return double(d.pdfVisible(w, m)); }), 1.0, 2e-3)
            << int(type) << " alpha " << alpha << " theta " << theta;
      }
}

TEST(Microfacet, ShadowingIsOneAtNormalIncidenceAndFallsToZeroAtTheHorizon) {
  for (Microfacet type : {Microfacet::GGX, Microfacet::Beckmann}) {
    const MicrofacetDistribution d(type, 0.4f);
    EXPECT_EQ(d.G1(Vec3(0, 0, 1)), 1.0f);
    EXPECT_EQ(d.G1(Vec3(1, 0, 0)), 0.0f);
    EXPECT_GT(d.G1(polar(45.0f)), d.G1(polar(80.0f)));
    EXPECT_EQ(d.lambda(polar(60.0f)), d.lambda(-polar(60.0f)));  // either side of the surface
    EXPECT_LE(d.G2(polar(30.0f), polar(70.0f)), d.G1(polar(30.0f)));
  }
}

TEST(Microfacet, TinyAlphaStaysFinite) {
  for (Microfacet type : {Microfacet::GGX, Microfacet::Beckmann}) {
    const MicrofacetDistribution d(type, 1e-4f);
    EXPECT_NEAR(d.D(Vec3(0, 0, 1)), 1.0f / (kPi * 1e-8f), 1e-3f / (kPi * 1e-8f));
    EXPECT_TRUE(std::isfinite(d.D(polar(0.001f))));
    if (type == Microfacet::Beckmann) {
      EXPECT_EQ(d.D(polar(10.0f)), 0.0f);
    }
    EXPECT_LT(d.D(polar(10.0f)), 1e-5f);  // GGX keeps its long tail
    const Vec3 m = d.sampleVisible(polar(60.0f), Vec2(0.3f, 0.9f));
    EXPECT_GT(m.z, 0.9999f);
  }
}

TEST(Microfacet, ErfInvInvertsErf) {
  for (float x = -0.999f; x < 1.0f; x += 0.0037f) EXPECT_NEAR(std::erf(erfInv(x)), x, 2e-6f) << x;
  for (float x : {1e-6f, 0.999999f, -0.9999f}) EXPECT_NEAR(std::erf(erfInv(x)), x, 2e-6f) << x;
  EXPECT_EQ(erfInv(0.0f), 0.0f);
}

// sampleVisible draws from pdfVisible (chi-square over normals; p > 1e-3 per case, fixed seeds).
TEST(Microfacet, VisibleNormalSamplingMatchesItsDensity) {
  for (Microfacet type : {Microfacet::GGX, Microfacet::Beckmann})
    for (float alpha : {0.1f, 0.6f})
      for (float theta : {0.0f, 60.0f, 87.0f}) {
        const MicrofacetDistribution d(type, alpha);
        const Vec3 w = polar(theta);
        test::SphereHistogram h(10, 20);
        Rng rng(hashKey(int(type), uint64_t(alpha * 100), uint64_t(theta)));
        for (int i = 0; i < 100000; ++i) {
          const Vec3 m = d.sampleVisible(w, Vec2(rng.uniform(), rng.uniform()));
          ASSERT_NEAR(glm::length(m), 1.0f, 1e-5f);
          h.add(m);
        }
        const test::ChiSquareResult r = h.test([&](const Vec3& m) { return double(d.pdfVisible(w, m)); });
        EXPECT_TRUE(r.passes(1e-3)) << int(type) << " alpha " << alpha << " theta " << theta << ": " << r.describe();
      }
}

}  // namespace
