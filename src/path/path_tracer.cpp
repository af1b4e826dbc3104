#include "path/path_tracer.h"

#include "material/bsdf.h"

namespace relt {
namespace {

// Solid-angle density with which next-event estimation would have chosen this emitter point.
float lightPdfSolidAngle(const PathContext& ctx, const SurfacePoint& hit, const Vec3& wo, float dist) {
  const float cosL = std::abs(glm::dot(hit.ng, wo));
  if (cosL <= 0.0f) return 0.0f;
  const float pdfArea = ctx.lights.pdfPickTriangle(hit.triangle) / ctx.tracer.triangleArea(hit.triangle);
  return pdfArea * dist * dist / cosL;
}

float misWeight(float pdfA, float pdfB, MisHeuristic h) {
  const float a = misWeightTerm(pdfA, h), b = misWeightTerm(pdfB, h);
  return a > 0.0f ? a / (a + b) : 0.0f;
}

// Next-event estimation at a non-delta vertex: one light point and the shadow ray's segment (class
// L2). The contribution counts if the segment is not blocked; the caller traces it.
struct DirectLight {
  RayTracer::Segment& shadow;  // left inactive: nothing to add
  Color& value;
};

[[gnu::always_inline]] inline void sampleDirect(const PathContext& ctx, const SurfacePoint& hit, const Bsdf& bsdf,
                                                const Vec3& wo, SampleSource& source, DirectLight out) {
  const float uPick = source.next(SampleStream::Light);
  const Vec2 uPos = source.next2(SampleStream::Light);
  const LightPoint lp = ctx.lights.samplePoint(uPick, uPos);
  Vec3 wi = lp.sp.p - hit.p;
  const float dist2 = glm::dot(wi, wi);
  if (!(dist2 > 0.0f)) return;
  wi /= std::sqrt(dist2);

  Color li;
  float pdfLight;  // solid angle
  if (lp.delta) {
    li = ctx.lights.intensity(lp.light, -wi) / dist2;
    pdfLight = lp.pdfPick;
  } else {
    const float cosL = std::abs(glm::dot(lp.sp.ng, wi));
    li = ctx.lights.emitted(lp.sp, -wi);
    pdfLight = lp.pdfPick * lp.pdfPos * dist2 / cosL;
    if (!(cosL > 0.0f)) return;
  }
  if (isBlack(li)) return;
  const Bsdf::Value fv = bsdf.evaluate(wo, wi, TransportMode::Radiance);
  const Color f = fv.f * std::abs(glm::dot(hit.ns, wi));
  if (isBlack(f)) return;
  const float w = lp.delta ? 1.0f : misWeight(pdfLight, fv.pdf, ctx.settings.heuristic);
  // Member by member: GCC copies a whole temporary Segment through the stack with mixed-width
  // moves, and the reads that cannot be forwarded from those stores stall (measured: 4 % of pt).
  RayTracer::Segment& s = out.shadow;
  s.from = hit.p;
  s.fromNg = hit.ng;
  s.to = lp.sp.p;
  s.toNg = lp.sp.ng;
  s.toPoint = lp.delta;
  s.active = true;
  out.value = f * li * (w / pdfLight);
}

// One camera path between vertices.
struct PathState {
  Ray ray;
  Color beta{1.0f};
  Color byClass[3] = {Color(0.0f), Color(0.0f), Color(0.0f)};  // L0, L1, L2
  bool anySpecular = false, prevDelta = true;
  float prevPdf = 0.0f;
  int segments = 1;  // of the path so far, including the one `ray` starts
};

// Everything at the vertex `ray` reached: emission, next-event estimation (its shadow segment left
// to the caller, its value already scaled by the throughput), the next direction and roulette.
// False when the path ends here.
[[gnu::always_inline]] inline bool scatter(const PathContext& ctx, PathState& st, const SurfacePoint& hit, float dist, SampleSource& source,
             DirectLight direct) {
  const Vec3 wo = -st.ray.dir;
  const Color le = ctx.lights.emitted(hit, wo);
  if (!isBlack(le)) {
    // Emitters hit after a delta bounce (or seen directly) could not have been found by NEE.
    const float w =
        st.prevDelta ? 1.0f : misWeight(st.prevPdf, lightPdfSolidAngle(ctx, hit, wo, dist), ctx.settings.heuristic);
    st.byClass[st.anySpecular ? 0 : 1] += st.beta * le * w;
  }
  if (st.segments == ctx.settings.maxDepth) return false;

  const Material& material = ctx.scene.materials[hit.material];
  const Bsdf bsdf(material, hit.ns, hit.ng);
  if (!bsdf.isDelta() && !ctx.lights.empty()) {
    sampleDirect(ctx, hit, bsdf, wo, source, direct);
    direct.value *= st.beta;
  }

  const Vec2 u = source.next2(SampleStream::Camera);
  const float uLobe = source.next(SampleStream::Camera);
  const auto bs = bsdf.sample(wo, u, uLobe, TransportMode::Radiance);
  if (!bs || !(bs->pdf > 0.0f)) return false;
  st.beta *= bs->f * (std::abs(glm::dot(hit.ns, bs->wi)) / bs->pdf);
  st.prevPdf = bs->pdf;
  st.prevDelta = bs->delta;
  st.anySpecular |= bs->delta;

  // Russian roulette on the throughput once the path is a few segments long.
  const float uRR = source.next(SampleStream::Camera);
  if (st.segments >= ctx.settings.rrDepth) {
    const float q = std::min(1.0f, maxComponent(st.beta));
    if (!(uRR < q)) return false;
    st.beta /= q;
  }
  if (isBlack(st.beta)) return false;
  st.ray = ctx.tracer.spawn(hit, bs->wi);
  ++st.segments;
  return true;
}

void addDirect(PathState& st, const RayTracer::Segment& shadow, const Color& value, bool blocked) {
  if (shadow.active && !blocked) st.byClass[2] += value;
}

// The rest of a path, one ray at a time.
void continuePath(const PathContext& ctx, PathState& st, SampleSource& source) {
  for (;;) {
    SurfacePoint hit;
    float dist;
    if (!ctx.tracer.intersect(st.ray, hit, dist)) return;
    RayTracer::Segment shadow;
    Color direct(0.0f);
    const bool more = scatter(ctx, st, hit, dist, source, DirectLight{shadow, direct});
    addDirect(st, shadow, direct, shadow.active && ctx.tracer.occluded(shadow));
    if (!more) return;
  }
}

void finish(const PathState& st, const Vec2& film, PathSample& out) {
  out.add(film, st.byClass[0], PathClass::L0);
  out.add(film, st.byClass[1], PathClass::L1);
  out.add(film, st.byClass[2], PathClass::L2);
}

}  // namespace

void tracePath(const PathContext& ctx, const Vec2& film, SampleSource& source, PathSample& out) {
  PathState st;
  st.ray = Ray{ctx.camera.position(), ctx.camera.direction(film), INFINITY};
  continuePath(ctx, st, source);
  finish(st, film, out);
}

void tracePaths(const PathContext& ctx, int n, const Vec2* film, SampleSource* const* sources, PathSample* out) {
  constexpr int K = RayTracer::kPacketSize;
  for (int base = 0; base < n; base += K) {
    const int m = std::min(K, n - base);
    PathState st[K];
    Ray rays[K];
    for (int i = 0; i < m; ++i) rays[i] = st[i].ray = Ray{ctx.camera.position(), ctx.camera.direction(film[base + i]), INFINITY};
    SurfacePoint hits[K];
    float dist[K];
    bool found[K];
    ctx.tracer.intersect(rays, m, hits, dist, found);
    RayTracer::Segment shadows[K];
    Color direct[K] = {};
    bool more[K] = {};
    for (int i = 0; i < m; ++i)
      if (found[i]) more[i] = scatter(ctx, st[i], hits[i], dist[i], *sources[base + i], DirectLight{shadows[i], direct[i]});
    bool blocked[K];
    ctx.tracer.occluded(shadows, m, blocked);
    for (int i = 0; i < m; ++i) {
      addDirect(st[i], shadows[i], direct[i], blocked[i]);
      if (more[i]) continuePath(ctx, st[i], *sources[base + i]);
      finish(st[i], film[base + i], out[base + i]);
    }
  }
}

}  // namespace relt
