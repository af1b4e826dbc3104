// Triangles paired into Embree quads: every triangle in exactly one quad, each quad half made of
// its triangle's corners, which halves pair and which do not, and how a hit finds its triangle.
#include <gtest/gtest.h>

#include <algorithm>

#include "scene/gltf_loader.h"
#include "scene/quad_pairs.h"
#include "test_support.h"

using namespace relt;

namespace {

// The three corner positions, sorted, so two triangles compare as point sets.
std::array<Vec3, 3> cornerSet(const Vec3& a, const Vec3& b, const Vec3& c) {
  std::array<Vec3, 3> s{a, b, c};
  std::sort(s.begin(), s.end(), [](const Vec3& x, const Vec3& y) {
    return x.x != y.x ? x.x < y.x : x.y != y.y ? x.y < y.y : x.z < y.z;
  });
  return s;
}

// Every triangle in exactly one quad; the quad's halves (v0, v1, v3) and (v2, v3, v1) are its
// triangles' corners. Returns how many triangles were paired.
size_t checkQuads(const std::vector<Triangle>& tris, const std::vector<Vec3>& pos, const std::vector<QuadPrim>& quads) {
  std::vector<int> seen(tris.size(), 0);
  size_t paired = 0;
  for (const QuadPrim& q : quads) {
    const Vec3 v0 = pos[q.v[0]], v1 = pos[q.v[1]], v2 = pos[q.v[2]], v3 = pos[q.v[3]];
    const uint32_t t0 = q.triangle[0], t1 = q.triangle[1];
    EXPECT_LT(t0, tris.size());
    if (t0 >= tris.size()) continue;
    ++seen[t0];
    const Triangle& a = tris[t0];
    EXPECT_EQ(cornerSet(v0, v1, v3), cornerSet(pos[a.v[0]], pos[a.v[1]], pos[a.v[2]])) << "triangle " << t0;
    if (t1 == QuadPrim::kNone) {
      EXPECT_EQ(q.v[3], q.v[2]) << "a lone triangle repeats its last vertex";
      continue;
    }
    EXPECT_LT(t1, tris.size());
    if (t1 >= tris.size()) continue;
    ++seen[t1];
    paired += 2;
    const Triangle& b = tris[t1];
    EXPECT_EQ(cornerSet(v2, v3, v1), cornerSet(pos[b.v[0]], pos[b.v[1]], pos[b.v[2]])) << "triangle " << t1;
  }
  for (size_t t = 0; t < tris.size(); ++t) EXPECT_EQ(seen[t], 1) << "triangle " << t;
  return paired;
}

}  // namespace

TEST(QuadPairs, EveryTriangleOfTheSuiteIsInOneQuad) {
  for (const char* name : {"cornell-box", "ring", "water-box", "furnace", "mirror-balls"}) {
    const Scene s = loadGltf(test::sourcePath(std::string("scenes/") + name + ".gltf"));
    const std::vector<QuadPrim> quads = pairTriangles(s.triangles, s.positions);
    const size_t paired = checkQuads(s.triangles, s.positions, quads);
    // Box and ring meshes are quads split in two; the spheres' poles leave a few fans unpaired.
    const double share = double(paired) / double(s.triangles.size());
    EXPECT_GE(share, std::string(name) == "furnace" || std::string(name) == "mirror-balls" ? 0.85 : 1.0) << name;
  }
}

TEST(QuadPairs, PairsByPositionInEitherWindingAndOnlyAcrossOneEdge) {
  // 0-1-2-3 a unit square, 4 and 5 repeat corners 2 and 0 (an unindexed copy), 6-8 lie elsewhere.
  const std::vector<Vec3> pos = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {1, 1, 0},
                                 {0, 0, 0}, {5, 5, 5}, {6, 5, 5}, {5, 6, 5}};
  struct Case {
    const char* what;
    std::vector<Triangle> tris;
    size_t paired;
  };
  const Case cases[] = {
      {"same winding", {{{0, 1, 2}, 0}, {{0, 2, 3}, 0}}, 2},
      {"opposite winding", {{{0, 1, 2}, 0}, {{0, 3, 2}, 0}}, 2},
      {"shared corners as separate vertices", {{{0, 1, 2}, 0}, {{5, 4, 3}, 1}}, 2},
      {"not consecutive", {{{0, 1, 2}, 0}, {{6, 7, 8}, 0}, {{3, 0, 2}, 0}}, 2},
      {"one shared corner only", {{{0, 1, 2}, 0}, {{2, 6, 3}, 0}}, 0},
      {"the same triangle twice", {{{0, 1, 2}, 0}, {{2, 1, 0}, 0}}, 0},
      {"a triangle with two equal corners", {{{0, 2, 4}, 0}, {{0, 2, 3}, 0}}, 0},
  };
  for (const Case& c : cases) {
    const std::vector<QuadPrim> quads = pairTriangles(c.tris, pos);
    EXPECT_EQ(checkQuads(c.tris, pos, quads), c.paired) << c.what;
  }
}

TEST(QuadPairs, AHitFindsItsHalf) {
  const QuadPrim pair{{0, 1, 2, 3}, {7, 9}}, lone{{0, 1, 2, 2}, {7, QuadPrim::kNone}};
  EXPECT_EQ(hitTriangle(pair, 0.2f, 0.3f), 7u);
  EXPECT_EQ(hitTriangle(pair, 0.0f, 0.0f), 7u);
  EXPECT_EQ(hitTriangle(pair, 0.8f, 0.7f), 9u);
  EXPECT_EQ(hitTriangle(pair, 1.0f, 1.0f), 9u);
  EXPECT_EQ(hitTriangle(lone, 0.2f, 0.3f), 7u);
  EXPECT_EQ(hitTriangle(lone, 0.6f, 0.5f), 7u);  // rounding past the diagonal stays on the triangle
}
