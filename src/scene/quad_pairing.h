#pragma once
// Pairs triangles that share an edge into Embree quads. Embree intersects a quad (v0, v1, v2, v3) as
// the triangles (v0, v1, v3) and (v2, v3, v1) in one leaf test, which on this project's scenes is
// about a third faster per ray than two separate triangles. Hits are mapped back to the original
// triangle and its own barycentrics, so nothing outside the ray tracer sees the quads.
#include <array>
#include <cstdint>
#include <vector>

#include "scene/scene.h"

namespace relt {

struct QuadPrimitive {
  static constexpr uint32_t kNone = 0xffffffffu;
  std::array<uint32_t, 4> v{};                 // Embree vertex indices
  std::array<uint32_t, 2> tri{kNone, kNone};   // first and second triangle (kNone: v3 == v2, unpaired)
  std::array<uint8_t, 2> rot{0, 0};            // rotation of each triangle's vertices in the quad
};

// Every triangle of the scene appears in exactly one quad; unpaired ones as (v0, v1, v2, v2).
// Triangles pair only across an edge they share with opposite winding (a consistently oriented
// surface), coplanar neighbours first.
std::vector<QuadPrimitive> pairTriangles(const Scene& scene);

struct TriangleHit {
  uint32_t triangle;
  float b1, b2;  // barycentrics of the triangle's v[1] and v[2]
};

// Embree's hit (u, v) on a quad -> the original triangle and barycentrics. u and v follow Embree's
// quad parametrisation: p = v0 + u (v1 - v0) + v (v3 - v0) on the first triangle (u + v <= 1), and
// the second triangle's own (u', v') = (1 - u, 1 - v).
TriangleHit triangleHit(const QuadPrimitive& q, float u, float v);

}  // namespace relt
