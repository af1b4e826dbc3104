#pragma once
// Vector types and small geometric helpers shared by every part of the renderer.
#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace relt {

using Vec2 = glm::vec2;
using Vec3 = glm::vec3;
using Mat3 = glm::mat3;
using Mat4 = glm::mat4;
using Color = glm::vec3;  // linear RGB

inline constexpr float kPi = 3.14159265358979323846f;
inline constexpr float kInvPi = 1.0f / kPi;
inline constexpr float kInv2Pi = 0.5f / kPi;
inline constexpr float kInv4Pi = 0.25f / kPi;
// Offset applied along the geometric normal when spawning rays, relative to scene scale 1.
inline constexpr float kRayEpsilon = 1e-4f;

// Rec. 709 luminance: the scalar target of the Markov chains.
inline float luminance(const Color& c) { return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z; }
inline bool isBlack(const Color& c) { return c.x <= 0.0f && c.y <= 0.0f && c.z <= 0.0f; }
inline bool isFinite(const Color& c) { return std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z); }
inline float maxComponent(const Color& c) { return std::max(c.x, std::max(c.y, c.z)); }
inline float safeSqrt(float x) { return std::sqrt(std::max(0.0f, x)); }

// Orthonormal basis around a unit normal (Duff et al. 2017, branchless).
struct Frame {
  Vec3 s, t, n;
  Frame() : s(1, 0, 0), t(0, 1, 0), n(0, 0, 1) {}
  explicit Frame(const Vec3& normal) : n(normal) {
    const float sign = std::copysign(1.0f, n.z);
    const float a = -1.0f / (sign + n.z);
    const float b = n.x * n.y * a;
    s = Vec3(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
    t = Vec3(b, sign + n.y * n.y * a, -n.y);
  }
  Vec3 toLocal(const Vec3& v) const { return Vec3(glm::dot(v, s), glm::dot(v, t), glm::dot(v, n)); }
  Vec3 toWorld(const Vec3& v) const { return s * v.x + t * v.y + n * v.z; }
};

struct Bounds3 {
  Vec3 lo{INFINITY}, hi{-INFINITY};
  void extend(const Vec3& p) { lo = glm::min(lo, p); hi = glm::max(hi, p); }
  bool empty() const { return lo.x > hi.x; }
  Vec3 diagonal() const { return empty() ? Vec3(0) : hi - lo; }
};

}  // namespace relt
