// Light sampling: pick by power, positions on the light, emission directions and their densities.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "core/rng.h"
#include "light/lights.h"
#include "scene/gltf_loader.h"
#include "test_support.h"

using namespace relt;

namespace {

// Mean and standard error of the mean of a Monte Carlo estimate, from n evaluations of f.
struct Estimate {
  double mean, stderror;
};
Estimate monteCarlo(int n, const std::function<double()>& f) {
  double sum = 0.0, sum2 = 0.0;
  for (int i = 0; i < n; ++i) {
    const double v = f();
    sum += v;
    sum2 += v * v;
  }
  const double mean = sum / n;
  return {mean, std::sqrt(std::max(0.0, sum2 / n - mean * mean) / n)};
}

glm::dvec3 corner(const Scene& s, uint32_t t, int k) { return glm::dvec3(s.positions[s.triangles[t].v[k]]); }
double areaOf(const Scene& s, uint32_t t) {
  return 0.5 * glm::length(glm::cross(corner(s, t, 1) - corner(s, t, 0), corner(s, t, 2) - corner(s, t, 0)));
}
// Power of an emitter as the documentation defines it, recomputed here in double precision.
double trianglePower(const Scene& s, uint32_t t) {
  const Material& m = s.materials[s.triangles[t].material];
  return kPi * areaOf(s, t) * luminance(m.emission) * (m.doubleSided ? 2.0 : 1.0);
}

// The Cornell box: one quad light (two triangles) facing down, one-sided.
struct Cornell : ::testing::Test {
  Scene scene = loadGltf(test::sourcePath("scenes/cornell-box.gltf"));
  RayTracer tracer{scene};
  LightSampler lights{scene, tracer};
};

// A scene built in code: a one-sided and a double-sided emitter of different size and colour, a
// degenerate emitter (zero area), a grey wall, a point light and a soft spot light.
Scene mixedScene() {
  Scene s;
  s.file = "mixed";
  s.positions = {{0, 0, 0},  {1, 0, 0},  {0, 1, 0},  // one-sided, area 0.5, normal +z
                 {0, 0, 2},  {0, 2, 2},  {2, 0, 2},  // double-sided, area 2, normal -z
                 {5, 5, 5},  {6, 6, 6},  {7, 7, 7},  // collinear: zero area
                 {-3, 0, 0}, {-3, 1, 0}, {-3, 0, 1}};
  s.normals.assign(s.positions.size(), Vec3(0.0f));
  for (const Vec3& p : s.positions) s.bounds.extend(p);
  Material white, oneSided, twoSided;
  oneSided.emission = Color(1.0f, 2.0f, 0.5f);
  twoSided.emission = Color(3.0f, 0.5f, 0.25f);
  twoSided.doubleSided = true;
  s.materials = {white, oneSided, twoSided};
  s.triangles = {{{0, 1, 2}, 1}, {{3, 4, 5}, 2}, {{6, 7, 8}, 1}, {{9, 10, 11}, 0}};
  PunctualLight point, spot;
  point.position = Vec3(0, 3, 0);
  point.intensity = Color(2.0f, 2.0f, 2.0f);
  spot.position = Vec3(1, 1, 4);
  spot.direction = glm::normalize(Vec3(0.3f, -0.2f, -1.0f));
  spot.intensity = Color(5.0f, 4.0f, 3.0f);
  spot.spot = true;
  spot.cosInner = std::cos(0.3f);
  spot.cosOuter = std::cos(0.7f);
  s.punctualLights = {point, spot};
  return s;
}

struct Mixed : ::testing::Test {
  Scene scene = mixedScene();
  RayTracer tracer{scene};
  LightSampler lights{scene, tracer};
  // Index in the light list of each kind of light (order of the list is an implementation detail).
  uint32_t find(std::function<bool(const Light&)> pred) const {
    for (uint32_t i = 0; i < lights.size(); ++i)
      if (pred(lights.light(i))) return i;
    ADD_FAILURE() << "light not found";
    return 0;
  }
  uint32_t triangleLight(uint32_t t) const {
    return find([&](const Light& l) { return l.kind == Light::Kind::Triangle && l.index == t; });
  }
  uint32_t punctual(uint32_t i) const {
    return find([&](const Light& l) { return l.kind == Light::Kind::Point && l.index == i; });
  }
  // A light point to emit from: sampled position for triangles, the light's position otherwise.
  LightPoint pointOn(uint32_t light) const {
    for (int i = 0; i < 10000; ++i) {
      const LightPoint lp = lights.samplePoint((i + 0.5f) / 10000.0f, Vec2(0.3f, 0.4f));
      if (lp.light == light) return lp;
    }
    ADD_FAILURE() << "light " << light << " never picked";
    return {};
  }
};

}  // namespace

// ---- Cornell box ------------------------------------------------------------------------------

TEST_F(Cornell, PickProbabilitiesSumToOneAndFollowPower) {
  ASSERT_EQ(lights.size(), scene.emissiveTriangleCount());
  ASSERT_EQ(lights.size(), 2u);
  double totalPower = 0.0, sum = 0.0;
  for (uint32_t i = 0; i < lights.size(); ++i) totalPower += trianglePower(scene, lights.light(i).index);
  for (uint32_t i = 0; i < lights.size(); ++i) {
    const uint32_t t = lights.light(i).index;
    sum += lights.pdfPick(i);
    EXPECT_NEAR(lights.pdfPick(i), trianglePower(scene, t) / totalPower, 1e-6);  // float pmf
    EXPECT_EQ(lights.lightOfTriangle(t), i);
    EXPECT_EQ(lights.pdfPickTriangle(t), lights.pdfPick(i));
  }
  EXPECT_NEAR(sum, 1.0, 1e-6);
  for (uint32_t t = 0; t < scene.triangles.size(); ++t)
    if (!scene.materials[scene.triangles[t].material].isEmissive()) {
      EXPECT_EQ(lights.pdfPickTriangle(t), 0.0f);
    }
}

TEST_F(Cornell, PdfPositionIsOneOverArea) {
  for (uint32_t i = 0; i < lights.size(); ++i) {
    const double a = areaOf(scene, lights.light(i).index);
    EXPECT_NEAR(lights.pdfPosition(i), 1.0 / a, 1e-5 / a);  // float area
  }
}

TEST_F(Cornell, SampledPointsLieUniformlyOnTheLight) {
  // Every point is on its triangle (plane distance and barycentrics within float round-off, 1e-5 at
  // a scene scale of ~5), picks follow pdfPick, and the mean point is the centroid (uniform
  // density). Statistical checks: fixed seed, 4 standard errors, plus 1e-6 for float positions
  // (an axis along which the light is flat has zero spread but float-rounded coordinates).
  Rng rng(1234);
  const int n = 20000;
  std::vector<int> picks(lights.size(), 0);
  std::vector<glm::dvec3> sum(lights.size(), glm::dvec3(0.0)), sum2(lights.size(), glm::dvec3(0.0));
  for (int i = 0; i < n; ++i) {
    const LightPoint lp = lights.samplePoint(rng.uniform(), Vec2(rng.uniform(), rng.uniform()));
    ASSERT_LT(lp.light, lights.size());
    const uint32_t t = lights.light(lp.light).index;
    EXPECT_EQ(lp.sp.triangle, t);
    EXPECT_FALSE(lp.delta);
    EXPECT_EQ(lp.pdfPick, lights.pdfPick(lp.light));
    EXPECT_EQ(lp.pdfPos, lights.pdfPosition(lp.light));
    const glm::dvec3 p(lp.sp.p), a = corner(scene, t, 0), e1 = corner(scene, t, 1) - a, e2 = corner(scene, t, 2) - a;
    const glm::dvec3 nrm = glm::normalize(glm::cross(e1, e2));
    EXPECT_NEAR(glm::dot(p - a, nrm), 0.0, 1e-5);
    // Barycentrics by solving p - a = b1 e1 + b2 e2 in the plane.
    const double d11 = glm::dot(e1, e1), d12 = glm::dot(e1, e2), d22 = glm::dot(e2, e2);
    const double r1 = glm::dot(p - a, e1), r2 = glm::dot(p - a, e2), det = d11 * d22 - d12 * d12;
    const double b1 = (d22 * r1 - d12 * r2) / det, b2 = (d11 * r2 - d12 * r1) / det;
    EXPECT_GE(b1, -1e-5);
    EXPECT_GE(b2, -1e-5);
    EXPECT_LE(b1 + b2, 1.0 + 1e-5);
    EXPECT_NEAR(glm::distance(glm::dvec3(lp.sp.ng), nrm), 0.0, 1e-5);
    ++picks[lp.light];
    sum[lp.light] += p;
    sum2[lp.light] += p * p;
  }
  for (uint32_t l = 0; l < lights.size(); ++l) {
    const double pk = lights.pdfPick(l), m = picks[l];
    EXPECT_NEAR(m / n, pk, 4.0 * std::sqrt(pk * (1.0 - pk) / n));
    const uint32_t t = lights.light(l).index;
    const glm::dvec3 centroid = (corner(scene, t, 0) + corner(scene, t, 1) + corner(scene, t, 2)) / 3.0;
    const glm::dvec3 mean = sum[l] / m, se = glm::sqrt(glm::max(sum2[l] / m - mean * mean, 0.0) / m);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(mean[k], centroid[k], 4.0 * se[k] + 1e-6) << "light " << l << " axis " << k;
  }
}

TEST_F(Cornell, CeilingLightFacesDownAndEmitsFromItsFrontOnly) {
  const Material& m = scene.materials[scene.triangles[lights.light(0).index].material];
  const LightPoint lp = lights.samplePoint(0.25f, Vec2(0.3f, 0.6f));
  EXPECT_NEAR(lp.sp.ng.y, -1.0f, 1e-6f);  // scenes/README: ceiling lights face down
  const Vec3 front = glm::normalize(lp.sp.ng + Vec3(0.3f, 0.0f, 0.2f));
  EXPECT_EQ(lights.emitted(lp.sp, front), m.emission);
  EXPECT_EQ(lights.emitted(lp.sp, -front), Color(0.0f));
  EXPECT_EQ(lights.emitted(lp.sp, -lp.sp.ng), Color(0.0f));
  // A Lambert wall emits nothing in any direction.
  for (uint32_t t = 0; t < scene.triangles.size(); ++t)
    if (!scene.materials[scene.triangles[t].material].isEmissive()) {
      const SurfacePoint wall = tracer.surfacePoint(t, 0.2f, 0.3f);
      EXPECT_EQ(lights.emitted(wall, wall.ng), Color(0.0f));
      EXPECT_EQ(lights.emitted(wall, -wall.ng), Color(0.0f));
      break;
    }
}

TEST_F(Cornell, SampledDirectionDensityMatchesPdfDirection) {
  // Tolerance: sampleDirection gets the cosine from the local frame, pdfDirection from a dot product
  // of the normalised world direction; they agree to float round-off (1e-6 absolute on ~0.3).
  Rng rng(99);
  for (int i = 0; i < 2000; ++i) {
    const LightPoint lp = lights.samplePoint(rng.uniform(), Vec2(rng.uniform(), rng.uniform()));
    const LightSampler::Emission e = lights.sampleDirection(lp, Vec2(rng.uniform(), rng.uniform()));
    EXPECT_NEAR(glm::length(e.dir), 1.0f, 1e-6f);
    EXPECT_GE(glm::dot(e.dir, lp.sp.ng), 0.0f);  // one-sided: into the front hemisphere
    EXPECT_NEAR(e.pdfDir, lights.pdfDirection(lp.light, lp.sp, e.dir), 1e-6f);
    EXPECT_NEAR(e.pdfDir, glm::dot(e.dir, lp.sp.ng) * kInvPi, 1e-6f);  // cosine-weighted
  }
}

TEST_F(Cornell, PdfDirectionIntegratesToOneOverTheSphere) {
  // 4 pi E[pdf(w)] for uniform w; fixed seed, tolerance 4 standard errors (about 0.016).
  const LightPoint lp = lights.samplePoint(0.7f, Vec2(0.5f, 0.2f));
  Rng rng(4242);
  const Estimate est = monteCarlo(100000, [&] {
    return 4.0 * kPi * lights.pdfDirection(lp.light, lp.sp, uniformSphere(Vec2(rng.uniform(), rng.uniform())));
  });
  ASSERT_LT(est.stderror, 0.01);
  EXPECT_NEAR(est.mean, 1.0, 4.0 * est.stderror);
  EXPECT_EQ(lights.pdfDirection(lp.light, lp.sp, -lp.sp.ng), 0.0f);
}

// ---- Mixed lights built in code --------------------------------------------------------------

TEST_F(Mixed, SkipsZeroAreaEmittersAndNonEmitters) {
  EXPECT_EQ(lights.size(), 4u);  // two triangles, point, spot
  EXPECT_EQ(lights.pdfPickTriangle(2), 0.0f);
  EXPECT_EQ(lights.pdfPickTriangle(3), 0.0f);
}

TEST_F(Mixed, PickProbabilitiesSumToOneAndFollowPower) {
  // Exact powers: Lambertian triangle pi A L (x2 double-sided), isotropic point 4 pi I; the spot's
  // by integrating its intensity. Pick ratios must match the power ratios.
  double sum = 0.0;
  for (uint32_t i = 0; i < lights.size(); ++i) sum += lights.pdfPick(i);
  EXPECT_NEAR(sum, 1.0, 1e-6);
  const uint32_t a = triangleLight(0), b = triangleLight(1), p = punctual(0);
  const double powerA = trianglePower(scene, 0), powerB = trianglePower(scene, 1);
  const double powerP = 4.0 * kPi * luminance(scene.punctualLights[0].intensity);
  EXPECT_NEAR(lights.pdfPick(b) / lights.pdfPick(a), powerB / powerA, 1e-5 * powerB / powerA);
  EXPECT_NEAR(lights.pdfPick(p) / lights.pdfPick(a), powerP / powerA, 1e-5 * powerP / powerA);
  // The spot's power: its intensity integrated over the sphere (Monte Carlo, fixed seed, 4 SE).
  Rng rng(2024);
  const Estimate spotPower = monteCarlo(200000, [&] {
    const Vec3 w = uniformSphere(Vec2(rng.uniform(), rng.uniform()));
    return 4.0 * kPi * luminance(lights.intensity(punctual(1), w));
  });
  ASSERT_LT(spotPower.stderror, 0.02 * spotPower.mean);
  const double ratio = lights.pdfPick(punctual(1)) / lights.pdfPick(a);
  EXPECT_NEAR(ratio, spotPower.mean / powerA, 4.0 * spotPower.stderror / powerA);
  EXPECT_NEAR(lights.pdfPosition(a), 2.0f, 1e-6f);  // area 0.5
  EXPECT_NEAR(lights.pdfPosition(b), 0.5f, 1e-6f);  // area 2
  EXPECT_EQ(lights.pdfPosition(p), 1.0f);
}

TEST_F(Mixed, PunctualLightsAreSampledAtTheirPositionAsDeltas) {
  for (uint32_t i = 0; i < 2; ++i) {
    const LightPoint lp = pointOn(punctual(i));
    EXPECT_TRUE(lp.delta);
    EXPECT_EQ(lp.sp.p, scene.punctualLights[i].position);
    EXPECT_EQ(lp.pdfPos, 1.0f);
    EXPECT_EQ(lp.pdfPick, lights.pdfPick(punctual(i)));
  }
}

TEST_F(Mixed, DoubleSidedEmitterEmitsFromBothSides) {
  const LightPoint lp = pointOn(triangleLight(1));
  EXPECT_EQ(lights.emitted(lp.sp, lp.sp.ng), Color(3.0f, 0.5f, 0.25f));
  EXPECT_EQ(lights.emitted(lp.sp, -lp.sp.ng), Color(3.0f, 0.5f, 0.25f));
  const LightPoint one = pointOn(triangleLight(0));
  EXPECT_EQ(lights.emitted(one.sp, -one.sp.ng), Color(0.0f));
}

TEST_F(Mixed, SampledDirectionDensityMatchesPdfDirectionForEveryKind) {
  // Same float round-off tolerance as for the Cornell light; relative for the larger spot density.
  Rng rng(5);
  int frontB = 0;
  const int n = 4000;
  for (uint32_t l = 0; l < lights.size(); ++l) {
    const LightPoint lp = pointOn(l);
    for (int i = 0; i < n; ++i) {
      const LightSampler::Emission e = lights.sampleDirection(lp, Vec2(rng.uniform(), rng.uniform()));
      const float pdf = lights.pdfDirection(l, lp.sp, e.dir);
      EXPECT_NEAR(glm::length(e.dir), 1.0f, 1e-6f);
      EXPECT_GT(pdf, 0.0f);
      EXPECT_NEAR(e.pdfDir, pdf, 1e-6f + 1e-6f * pdf) << "light " << l;
      if (l == triangleLight(1)) frontB += glm::dot(e.dir, lp.sp.ng) > 0.0f;
      if (l == punctual(1)) {
        EXPECT_GT(glm::dot(e.dir, scene.punctualLights[1].direction), scene.punctualLights[1].cosOuter);
      }
    }
  }
  // The double-sided emitter picks each side with probability 1/2 (binomial, 4 standard errors).
  EXPECT_NEAR(frontB / double(n), 0.5, 4.0 * std::sqrt(0.25 / n));
}

TEST_F(Mixed, PdfDirectionIntegratesToOneOverTheSphereForEveryKind) {
  // 4 pi E[pdf(w)] for uniform w, fixed seed, tolerance 4 standard errors.
  Rng rng(77);
  for (uint32_t l = 0; l < lights.size(); ++l) {
    const LightPoint lp = pointOn(l);
    const Estimate est = monteCarlo(100000, [&] {
      return 4.0 * kPi * lights.pdfDirection(l, lp.sp, uniformSphere(Vec2(rng.uniform(), rng.uniform())));
    });
    ASSERT_LT(est.stderror, 0.02) << "light " << l;
    EXPECT_NEAR(est.mean, 1.0, 4.0 * est.stderror + 1e-6) << "light " << l;  // + round-off for the constant point pdf
  }
}

TEST_F(Mixed, SpotIntensityFallsOffBetweenTheCones) {
  // glTF KHR_lights_punctual: full inside the inner cone, zero outside the outer one, and
  // ((cos - cosOuter) / (cosInner - cosOuter))^2 in between.
  const PunctualLight& s = scene.punctualLights[1];
  const uint32_t l = punctual(1);
  const Frame frame(s.direction);
  auto at = [&](float angle) { return frame.toWorld(Vec3(std::sin(angle), 0.0f, std::cos(angle))); };
  EXPECT_EQ(lights.intensity(l, s.direction), s.intensity);
  EXPECT_EQ(lights.intensity(l, at(0.25f)), s.intensity);
  EXPECT_EQ(lights.intensity(l, at(0.75f)), Color(0.0f));
  const float x = (std::cos(0.5f) - s.cosOuter) / (s.cosInner - s.cosOuter);
  EXPECT_NEAR(lights.intensity(l, at(0.5f)).x, s.intensity.x * x * x, 1e-4f);  // float cosines
  EXPECT_EQ(lights.intensity(punctual(0), Vec3(0, -1, 0)), scene.punctualLights[0].intensity);
}

TEST(LightTable, SampledPointsEqualTheTracersSurfacePoints) {
  // The sampler keeps its own copy of each emissive triangle; points drawn from it must be the
  // ray tracer's surface points bit for bit, on a flat triangle whose shading normal is tilted off
  // its geometric one (equal vertex normals) and on one with varying normals.
  Scene scene = mixedScene();
  for (int v = 0; v < 3; ++v) scene.normals[v] = glm::normalize(Vec3(0.3f, -0.2f, 1.0f));
  scene.normals[3] = glm::normalize(Vec3(0.2f, 0.0f, -1.0f));
  scene.normals[4] = glm::normalize(Vec3(0.0f, 0.3f, -1.0f));
  scene.normals[5] = Vec3(0.0f, 0.0f, -1.0f);
  const RayTracer tracer(scene);
  const LightSampler lights(scene, tracer);
  Rng rng(3);
  int triangles = 0, smooth = 0;
  for (int i = 0; i < 2000; ++i) {
    const float uPick = rng.uniform();
    const Vec2 uPos(rng.uniform(), rng.uniform());
    const LightPoint lp = lights.samplePoint(uPick, uPos);
    EXPECT_EQ(lp.pdfPick, lights.pdfPick(lp.light));
    EXPECT_EQ(lp.pdfPos, lights.pdfPosition(lp.light));
    if (lights.light(lp.light).kind != Light::Kind::Triangle) continue;
    ++triangles;
    const uint32_t t = lights.light(lp.light).index;
    smooth += t == 1;
    const Vec2 b = uniformTriangle(uPos);
    const SurfacePoint sp = tracer.surfacePoint(t, b.x, b.y);
    EXPECT_EQ(lp.sp.p, sp.p);
    EXPECT_EQ(lp.sp.ng, sp.ng);
    EXPECT_EQ(lp.sp.ns, sp.ns);
    EXPECT_EQ(lp.sp.triangle, t);
    EXPECT_EQ(lp.sp.material, sp.material);
  }
  EXPECT_GT(smooth, 100);
  EXPECT_GT(triangles - smooth, 100);
}
