#include "scene/quad_pairs.h"

#include <algorithm>
#include <array>
#include <bit>
#include <unordered_map>

namespace relt {
namespace {

bool distinctCorners(const Vec3 (&p)[3]) { return p[0] != p[1] && p[1] != p[2] && p[2] != p[0]; }

// Triangles a and b as one quad, if they share exactly one edge.
bool tryPair(const std::vector<Triangle>& tris, const std::vector<Vec3>& pos, uint32_t a, uint32_t b, QuadPrim& q) {
  const Triangle &ta = tris[a], &tb = tris[b];
  const Vec3 pa[3] = {pos[ta.v[0]], pos[ta.v[1]], pos[ta.v[2]]};
  const Vec3 pb[3] = {pos[tb.v[0]], pos[tb.v[1]], pos[tb.v[2]]};
  if (!distinctCorners(pa) || !distinctCorners(pb)) return false;
  int shared = 0, oa = -1, ob = -1;
  for (int k = 0; k < 3; ++k) {
    const bool inB = pa[k] == pb[0] || pa[k] == pb[1] || pa[k] == pb[2];
    shared += inB;
    if (!inB) oa = k;
    if (pb[k] != pa[0] && pb[k] != pa[1] && pb[k] != pa[2]) ob = k;
  }
  if (shared != 2) return false;
  // Quad (a's lone corner, the next two of a's corners around a, b's lone corner in between):
  // its first half (v0, v1, v3) is a, its second (v2, v3, v1) is b.
  q.v[0] = ta.v[oa];
  q.v[1] = ta.v[(oa + 1) % 3];
  q.v[2] = tb.v[ob];
  q.v[3] = ta.v[(oa + 2) % 3];
  q.triangle[0] = a;
  q.triangle[1] = b;
  return true;
}

// Each triangle's edges keyed by the welded ids of their corners (equal positions, equal id),
// sorted so the triangles around an edge are neighbours.
struct EdgeEntry {
  uint64_t key;
  uint32_t triangle;
  bool operator<(const EdgeEntry& o) const { return key != o.key ? key < o.key : triangle < o.triangle; }
};

// The edges of the triangles `which`; only their corners are welded (a mesh's leftovers are few).
std::vector<EdgeEntry> edgeTable(const std::vector<Triangle>& triangles, const std::vector<Vec3>& positions,
                                 const std::vector<uint32_t>& which) {
  auto bits = [](float f) { return uint64_t(std::bit_cast<uint32_t>(f == 0.0f ? 0.0f : f)); };  // -0 == +0
  struct Hash {
    size_t operator()(const std::array<uint64_t, 2>& k) const { return std::hash<uint64_t>()(k[0] * 0x9e3779b97f4a7c15ull ^ k[1]); }
  };
  std::unordered_map<std::array<uint64_t, 2>, uint64_t, Hash> ids;
  auto weld = [&](uint32_t vertex) {
    const Vec3& p = positions[vertex];
    return ids.try_emplace({bits(p.x) << 32 | bits(p.y), bits(p.z)}, uint64_t(ids.size())).first->second;
  };
  std::vector<EdgeEntry> edges;
  edges.reserve(3 * which.size());
  for (uint32_t t : which) {
    const uint64_t c[3] = {weld(triangles[t].v[0]), weld(triangles[t].v[1]), weld(triangles[t].v[2])};
    for (int k = 0; k < 3; ++k) edges.push_back({std::min(c[k], c[(k + 1) % 3]) << 32 | std::max(c[k], c[(k + 1) % 3]), t});
  }
  std::sort(edges.begin(), edges.end());
  return edges;
}

}  // namespace

std::vector<QuadPrim> pairTriangles(const std::vector<Triangle>& triangles, const std::vector<Vec3>& positions) {
  const uint32_t n = static_cast<uint32_t>(triangles.size());
  std::vector<QuadPrim> quads;
  quads.reserve(n);
  std::vector<bool> paired(n, false);
  auto pair = [&](uint32_t a, uint32_t b) {
    QuadPrim q;
    if (paired[a] || paired[b] || !tryPair(triangles, positions, a, b, q)) return false;
    quads.push_back(q);
    paired[a] = paired[b] = true;
    return true;
  };
  // Consecutive triangles first: exporters write a quad's two halves one after the other.
  for (uint32_t i = 0; i + 1 < n; ++i)
    if (pair(i, i + 1)) ++i;
  // Then any two left over that share an edge (edges in the order of their welded corners).
  std::vector<uint32_t> leftover;
  for (uint32_t i = 0; i < n; ++i)
    if (!paired[i]) leftover.push_back(i);
  const std::vector<EdgeEntry> edges = edgeTable(triangles, positions, leftover);
  for (size_t e = 0; e < edges.size();) {
    size_t end = e + 1;
    while (end < edges.size() && edges[end].key == edges[e].key) ++end;
    for (size_t i = e; i < end; ++i)
      for (size_t j = i + 1; j < end && !paired[edges[i].triangle]; ++j) pair(edges[i].triangle, edges[j].triangle);
    e = end;
  }
  for (uint32_t i = 0; i < n; ++i) {
    if (paired[i]) continue;
    const Triangle& t = triangles[i];
    quads.push_back(QuadPrim{{t.v[0], t.v[1], t.v[2], t.v[2]}, {i, QuadPrim::kNone}});
  }
  return quads;
}

}  // namespace relt
