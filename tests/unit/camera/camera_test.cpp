// Pinhole camera: film position <-> direction, frustum limits, direction density and importance.
#include <gtest/gtest.h>

#include <cmath>

#include "camera/camera.h"
#include "core/rng.h"
#include "core/sampling.h"

using namespace relt;

namespace {

constexpr int kWidth = 320, kHeight = 200;  // non-square: the aspect ratio comes from the resolution
constexpr float kYfov = 1.1f;               // wide, so cos^3 varies by ~60 % over the frame

// An oblique camera (no axis-aligned shortcuts): looks along normalize(1, -0.4, 0.6).
struct Rig {
  Vec3 forward = glm::normalize(Vec3(1.0f, -0.4f, 0.6f));
  Vec3 right = glm::normalize(glm::cross(forward, Vec3(0, 1, 0)));
  Vec3 up = glm::cross(right, forward);
  double tanY = std::tan(0.5 * kYfov);
  double tanX = tanY * kWidth / kHeight;
  double area = 4.0 * tanX * tanY;  // film plane at distance 1

  PerspectiveCamera desc() const {
    PerspectiveCamera d;
    d.position = Vec3(1.0f, 2.0f, 3.0f);
    d.toWorld = Mat3(right, up, -forward);  // columns: right, up, backward
    d.yfov = kYfov;
    return d;
  }
  // Direction through the point (a, b) of the film plane in units of its half extents (a right, b up).
  Vec3 through(double a, double b) const {
    return glm::normalize(forward + float(a * tanX) * right + float(b * tanY) * up);
  }
};

double cosAngle(const Vec3& a, const Vec3& b) { return glm::dot(a, b) / (glm::length(a) * glm::length(b)); }

// Solid angle of the spherical triangle spanned by unit vectors (Van Oosterom and Strackee 1983).
double solidAngle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  const double num = std::abs(glm::dot(a, glm::cross(b, c)));
  const double den = 1.0 + glm::dot(a, b) + glm::dot(b, c) + glm::dot(c, a);
  return 2.0 * std::atan2(num, den);
}

}  // namespace

TEST(Camera, KeepsPositionAndLooksDownMinusZOfItsFrame) {
  const Rig rig;
  const Camera cam(rig.desc(), kWidth, kHeight);
  EXPECT_EQ(cam.position(), Vec3(1.0f, 2.0f, 3.0f));
  EXPECT_NEAR(glm::distance(cam.forward(), rig.forward), 0.0f, 1e-6f);
  EXPECT_EQ(cam.width(), kWidth);
  EXPECT_EQ(cam.height(), kHeight);
}

TEST(Camera, FrameEdgesFollowYfovAndResolutionAspect) {
  // Analytic: the top edge's centre is yfov/2 above the axis; the left edge's centre is
  // atan(tan(yfov/2) * width/height) to the left. Tolerance: float trigonometry, ~1e-6.
  const Rig rig;
  const Camera cam(rig.desc(), kWidth, kHeight);
  const Vec3 centre = cam.direction(Vec2(kWidth / 2.0f, kHeight / 2.0f));
  EXPECT_NEAR(glm::distance(centre, rig.forward), 0.0f, 1e-6f);
  const Vec3 top = cam.direction(Vec2(kWidth / 2.0f, 0.0f));
  EXPECT_NEAR(std::acos(cosAngle(top, rig.forward)), 0.5 * kYfov, 1e-5);
  EXPECT_GT(glm::dot(top, rig.up), 0.0f);  // film y grows downwards
  const Vec3 left = cam.direction(Vec2(0.0f, kHeight / 2.0f));
  EXPECT_NEAR(std::acos(cosAngle(left, rig.forward)), std::atan(rig.tanX), 1e-5);
  EXPECT_LT(glm::dot(left, rig.right), 0.0f);  // film x grows to the right
  EXPECT_NEAR(glm::length(cam.direction(Vec2(3.0f, 150.0f))), 1.0f, 1e-6f);
}

TEST(Camera, FilmPositionInvertsDirection) {
  // 41 x 31 points spread over the film, including points 0.01 px inside every edge. Tolerance
  // 1e-3 px: float round-off of ~1e-6 relative in the plane coordinates, times ~300 px.
  const Rig rig;
  const Camera cam(rig.desc(), kWidth, kHeight);
  const int nx = 41, ny = 31;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const Vec2 p(0.01f + (kWidth - 0.02f) * i / (nx - 1), 0.01f + (kHeight - 0.02f) * j / (ny - 1));
      const std::optional<Vec2> back = cam.filmPosition(cam.direction(p));
      ASSERT_TRUE(back.has_value()) << p.x << "," << p.y;
      EXPECT_NEAR(back->x, p.x, 1e-3f);
      EXPECT_NEAR(back->y, p.y, 1e-3f);
    }
}

TEST(Camera, DirectionsOutsideTheFrustumHaveNoFilmPosition) {
  const Rig rig;
  const Camera cam(rig.desc(), kWidth, kHeight);
  EXPECT_FALSE(cam.filmPosition(-rig.forward));
  EXPECT_FALSE(cam.filmPosition(rig.right));  // perpendicular to the axis
  EXPECT_FALSE(cam.filmPosition(rig.up));
  // 1 % beyond each edge and corner is out; 1 % inside is in (the frame ends exactly at tanX, tanY).
  for (const auto& [a, b] :
       {std::pair{1.01, 0.0}, {-1.01, 0.0}, {0.0, 1.01}, {0.0, -1.01}, {1.01, 1.01}, {-1.01, -0.5}})
    EXPECT_FALSE(cam.filmPosition(rig.through(a, b))) << a << "," << b;
  for (const auto& [a, b] :
       {std::pair{0.99, 0.0}, {-0.99, 0.0}, {0.0, 0.99}, {0.0, -0.99}, {0.99, 0.99}, {-0.99, -0.99}})
    EXPECT_TRUE(cam.filmPosition(rig.through(a, b))) << a << "," << b;
}

TEST(Camera, PdfDirectionIntegratesToOneOverTheFrustum) {
  // Monte Carlo over a cone that contains the frustum, with the frustum as indicator (filmPosition).
  // Fixed seed; tolerance 4 standard errors of the estimate (computed from the samples).
  const Rig rig;
  const Camera cam(rig.desc(), kWidth, kHeight);
  const float cosMax = 0.98f / std::sqrt(1.0f + float(rig.tanX * rig.tanX + rig.tanY * rig.tanY));  // past the corners
  const double coneSolidAngle = 2.0 * kPi * (1.0 - cosMax);
  const Frame frame(rig.forward);
  Rng rng(20240611);
  const int n = 200000;
  double sum = 0.0, sum2 = 0.0;
  for (int i = 0; i < n; ++i) {
    const Vec3 w = glm::normalize(frame.toWorld(uniformCone(Vec2(rng.uniform(), rng.uniform()), cosMax)));
    const double f = cam.filmPosition(w) ? cam.pdfDirection(w) * coneSolidAngle : 0.0;
    sum += f;
    sum2 += f * f;
  }
  const double mean = sum / n, stderror = std::sqrt((sum2 / n - mean * mean) / n);
  ASSERT_LT(stderror, 5e-3);  // the test has the power to see a wrong normalisation
  EXPECT_NEAR(mean, 1.0, 4.0 * stderror);
}

TEST(Camera, EveryPixelHasProbabilityOneOverPixelCount) {
  // The direction density times each pixel's exact solid angle (two spherical triangles through the
  // pixel corners) is 1 / (width x height). Deterministic; the 1e-3 relative tolerance covers the
  // midpoint rule across one pixel (~1e-4 here) and float corner directions.
  const Rig rig;
  const int w = 160, h = 100;
  const Camera cam(rig.desc(), w, h);
  double total = 0.0, worst = 0.0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const glm::dvec3 a(cam.direction(Vec2(x, y))), b(cam.direction(Vec2(x + 1, y)));
      const glm::dvec3 c(cam.direction(Vec2(x + 1, y + 1))), d(cam.direction(Vec2(x, y + 1)));
      const double omega = solidAngle(a, b, c) + solidAngle(a, c, d);
      const double p = cam.pdfDirection(cam.direction(Vec2(x + 0.5f, y + 0.5f))) * omega;
      total += p;
      worst = std::max(worst, std::abs(p * w * h - 1.0));
    }
  EXPECT_NEAR(total, 1.0, 1e-3);
  EXPECT_LT(worst, 1e-3);
}

TEST(Camera, ImportanceIsPdfOverCosine) {
  // Documented: We = 1 / (A cos^4), pdf = 1 / (A cos^3), A = 4 tan(xfov/2) tan(yfov/2).
  const Rig rig;
  const Camera cam(rig.desc(), kWidth, kHeight);
  EXPECT_NEAR(cam.importance(rig.forward), 1.0 / rig.area, 1e-5 / rig.area);
  EXPECT_NEAR(cam.pdfDirection(rig.forward), 1.0 / rig.area, 1e-5 / rig.area);
  Rng rng(7);
  for (int i = 0; i < 200; ++i) {
    const Vec3 w = cam.direction(Vec2(rng.uniform() * kWidth, rng.uniform() * kHeight));
    const double c = glm::dot(w, rig.forward);
    const double pdf = cam.pdfDirection(w), we = cam.importance(w);
    EXPECT_NEAR(we, pdf / c, 1e-5 * we);  // float round-off
    EXPECT_NEAR(pdf, 1.0 / (rig.area * c * c * c), 1e-5 * pdf);
  }
  // Behind the camera both vanish.
  const Vec3 behind = glm::normalize(rig.right - 0.1f * rig.forward);
  EXPECT_EQ(cam.importance(-rig.forward), 0.0f);
  EXPECT_EQ(cam.pdfDirection(-rig.forward), 0.0f);
  EXPECT_EQ(cam.importance(behind), 0.0f);
  EXPECT_EQ(cam.pdfDirection(behind), 0.0f);
}
