#include "scene/quad_pairing.h"

#include <unordered_map>

namespace relt {
namespace {

uint64_t edgeKey(uint32_t a, uint32_t b) { return (static_cast<uint64_t>(a) << 32) | b; }

Vec3 triangleNormal(const Scene& s, const Triangle& t) {
  const Vec3 c = glm::cross(s.positions[t.v[1]] - s.positions[t.v[0]], s.positions[t.v[2]] - s.positions[t.v[0]]);
  const float len = glm::length(c);
  return len > 0.0f ? c / len : Vec3(0.0f);
}

}  // namespace

std::vector<QuadPrimitive> pairTriangles(const Scene& scene) {
  const auto& tris = scene.triangles;
  const uint32_t n = static_cast<uint32_t>(tris.size());
  // Directed edge (v[i] -> v[i+1]) -> triangle * 3 + i.
  std::unordered_map<uint64_t, uint32_t> edges;
  edges.reserve(3 * static_cast<size_t>(n));
  for (uint32_t t = 0; t < n; ++t)
    for (uint32_t i = 0; i < 3; ++i) edges.emplace(edgeKey(tris[t].v[i], tris[t].v[(i + 1) % 3]), 3 * t + i);

  std::vector<bool> used(n, false);
  std::vector<QuadPrimitive> quads;
  quads.reserve(n / 2 + 1);
  for (uint32_t t = 0; t < n; ++t) {
    if (used[t]) continue;
    used[t] = true;
    const Triangle& a = tris[t];
    const Vec3 na = triangleNormal(scene, a);
    // Best neighbour across one of t's edges: the most coplanar unused one.
    uint32_t best = QuadPrimitive::kNone, bestEdge = 0, bestOther = 0;
    float bestDot = -2.0f;
    for (uint32_t i = 0; i < 3; ++i) {
      const auto it = edges.find(edgeKey(a.v[(i + 1) % 3], a.v[i]));
      if (it == edges.end()) continue;
      const uint32_t u = it->second / 3;
      if (used[u]) continue;
      const float d = glm::dot(na, triangleNormal(scene, tris[u]));
      if (d > bestDot) {
        bestDot = d;
        best = u;
        bestEdge = i;
        bestOther = it->second % 3;
      }
    }
    QuadPrimitive q;
    q.tri[0] = t;
    if (best == QuadPrimitive::kNone) {
      q.v = {a.v[0], a.v[1], a.v[2], a.v[2]};
      quads.push_back(q);
      continue;
    }
    used[best] = true;
    // t rotated to (p, q, r) with the shared edge q -> r; the neighbour rotated to (s, r, q).
    const uint32_t k1 = (bestEdge + 2) % 3, k2 = (bestOther + 2) % 3;
    const Triangle& b = tris[best];
    q.tri[1] = best;
    q.rot = {static_cast<uint8_t>(k1), static_cast<uint8_t>(k2)};
    q.v = {a.v[k1], a.v[(k1 + 1) % 3], b.v[k2], a.v[(k1 + 2) % 3]};
    quads.push_back(q);
  }
  return quads;
}

TriangleHit triangleHit(const QuadPrimitive& q, float u, float v) {
  // Weights of the rotated triangle's vertices (x[k], x[k+1], x[k+2]).
  const bool second = u + v > 1.0f && q.tri[1] != QuadPrimitive::kNone;
  const float w[3] = {second ? u + v - 1.0f : 1.0f - u - v, second ? 1.0f - u : u, second ? 1.0f - v : v};
  const uint32_t k = q.rot[second ? 1 : 0];
  float original[3];
  for (uint32_t m = 0; m < 3; ++m) original[(k + m) % 3] = w[m];
  return {q.tri[second ? 1 : 0], original[1], original[2]};
}

}  // namespace relt
