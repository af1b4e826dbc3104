#include "path/bdpt.h"

#include <algorithm>

namespace relt {
namespace {

// bsdf: replaces the vertex's own (a hook's, at a connection vertex).
Color surfaceF(const PathVertex& v, const Vec3& w, TransportMode mode, const Bsdf* bsdf = nullptr) {
  Color f = (bsdf ? *bsdf : *v.bsdf).eval(v.wo, w, mode);
  if (mode == TransportMode::Importance) f *= shadingCorrection(v.sp, v.wo, w);
  return f;
}

// Cosine at a vertex for the geometry term (shading normal on surfaces, as the BSDF frame).
float cosAt(const PathVertex& v, const Vec3& w) {
  if (v.type == PathVertex::Type::Surface) return std::abs(glm::dot(v.sp.ns, w));
  return v.hasNormal() ? std::abs(glm::dot(v.sp.ng, w)) : 1.0f;
}

float remap0(float pdf) { return pdf != 0.0f ? pdf : 1.0f; }

// Area density with which vertex `from`, reached from direction `arrive` (unit, towards the vertex
// before it in the generating direction), generates vertex `to`. bsdf: replaces from's own.
float pdfGenerate(const PathContext& ctx, const PathVertex& from, const Vec3& arrive, const PathVertex& to,
                  bool roulette, const Bsdf* bsdf = nullptr) {
  const Vec3 w = glm::normalize(to.sp.p - from.sp.p);
  float pdfW = 0.0f;
  switch (from.type) {
    case PathVertex::Type::Camera: pdfW = ctx.camera.pdfDirection(w); break;
    case PathVertex::Type::Light: pdfW = ctx.lights.pdfDirection(from.light, from.sp, w); break;
    case PathVertex::Type::Surface:
      pdfW = (bsdf ? *bsdf : *from.bsdf).pdf(arrive, w) *
             (roulette ? continuationProbability(from.bsdf->material()) : 1.0f);
      break;
  }
  return solidAngleToArea(pdfW, from, to);
}

// First vertex of a light subpath (or the light end of an s = 1 connection).
PathVertex lightVertex(const LightPoint& lp) {
  PathVertex l;
  l.type = PathVertex::Type::Light;
  l.delta = lp.delta;
  l.sp = lp.sp;
  l.light = lp.light;
  l.pdfFwd = lp.pdfPick * lp.pdfPos;
  l.beta = Color(1.0f / l.pdfFwd);
  return l;
}

bool anyDelta(std::span<const PathVertex> vertices) {
  for (const PathVertex& v : vertices)
    if (v.isSurface() && v.delta) return true;
  return false;
}

}  // namespace

// MIS densities are evaluated along the directions between stored vertex positions (toPrev), not
// along the traced rays (which start from an offset origin): the weights are then a function of the
// path's vertices alone and sum to exactly 1 over the strategies that can make it. The BSDF is
// sampled and evaluated with the traced direction (wo): at a smooth dielectric the Fresnel branch
// follows it, and a direction tilted by the offset biased glass on a floor by 1 %.
void Bdpt::randomWalk(Ray ray, Color beta, TransportMode mode, size_t maxVertices, SampleSource& source,
                      SampleStream stream, std::vector<PathVertex>& path) const {
  while (path.size() < maxVertices) {
    SurfacePoint hit;
    float dist;
    if (!ctx_.tracer.intersect(ray, hit, dist)) return;
    {
      PathVertex& prev = path.back();
      PathVertex v;
      v.type = PathVertex::Type::Surface;
      v.sp = hit;
      v.wo = -ray.dir;
      v.toPrev = glm::normalize(prev.sp.p - hit.p);
      v.beta = beta;
      v.pdfFwd = pdfGenerate(ctx_, prev, prev.toPrev, v, roulette_);
      if (path.size() >= 2) {
        PathVertex& prevPrev = path[path.size() - 2];
        prevPrev.pdfRev = pdfGenerate(ctx_, prev, -v.toPrev, prevPrev, roulette_);
      }
      v.bsdf.emplace(ctx_.scene.materials[hit.material], hit.ns, hit.ng);
      v.delta = v.bsdf->isDelta();
      path.push_back(v);
    }
    if (path.size() >= maxVertices) return;
    PathVertex& cur = path.back();
    const Vec2 u = source.next2(stream);
    const float uLobe = source.next(stream);
    const float uRR = source.next(stream);
    const auto bs = cur.bsdf->sample(cur.wo, u, uLobe, mode);
    if (!bs || !(bs->pdf > 0.0f)) return;
    const float q = roulette_ ? continuationProbability(cur.bsdf->material()) : 1.0f;
    if (!(uRR < q)) return;
    float scale = std::abs(glm::dot(cur.sp.ns, bs->wi)) / (bs->pdf * q);
    if (mode == TransportMode::Importance) scale *= shadingCorrection(cur.sp, cur.wo, bs->wi);
    beta *= bs->f * scale;
    if (isBlack(beta) || !isFinite(beta)) return;
    ray = ctx_.tracer.spawn(cur.sp, bs->wi);
  }
}

void Bdpt::generateCameraSubpath(const Vec2& film, SampleSource& source, size_t maxVertices) {
  camera_.clear();
  PathVertex c;
  c.type = PathVertex::Type::Camera;
  c.sp.p = ctx_.camera.position();
  c.sp.ng = c.sp.ns = ctx_.camera.forward();
  c.pdfFwd = 1.0f;
  camera_.push_back(c);
  const Vec3 dir = ctx_.camera.direction(film);
  randomWalk(Ray{c.sp.p, dir, INFINITY}, Color(1.0f), TransportMode::Radiance, maxVertices, source,
             SampleStream::Camera, camera_);
  countSubpathVertices(ctx_, camera_.size() - 1);
}

void Bdpt::generateLightSubpath(SampleSource& source, size_t maxVertices) {
  light_.clear();
  const float uPick = source.next(SampleStream::Light);
  const Vec2 uPos = source.next2(SampleStream::Light);
  const Vec2 uDir = source.next2(SampleStream::Light);
  if (ctx_.lights.empty()) return;
  const LightPoint lp = ctx_.lights.samplePoint(uPick, uPos);
  const PathVertex& l = light_.emplace_back(lightVertex(lp));

  const auto em = ctx_.lights.sampleDirection(lp, uDir);
  if (!(em.pdfDir > 0.0f)) return;
  const Color le = lp.delta ? ctx_.lights.intensity(lp.light, em.dir) : ctx_.lights.emitted(lp.sp, em.dir);
  if (isBlack(le)) return;
  const Color beta = le * (cosAt(l, em.dir) / (l.pdfFwd * em.pdfDir));
  const Vec3 origin = lp.delta ? lp.sp.p : ctx_.tracer.offsetOrigin(lp.sp.p, lp.sp.ng, em.dir);
  randomWalk(Ray{origin, em.dir, INFINITY}, beta, TransportMode::Importance, maxVertices, source,
             SampleStream::Light, light_);
  countSubpathVertices(ctx_, light_.size() - 1);
}

void Bdpt::trace(const Vec2& film, SampleSource& source, PathSample& out) {
  generateCameraSubpath(film, source, static_cast<size_t>(ctx_.settings.maxDepth) + 1);
  generateLightSubpath(source, static_cast<size_t>(ctx_.settings.maxDepth));
  if (hook_ != nullptr) hook_->beginPath();
  const int maxDepth = ctx_.settings.maxDepth;
  // Emission found at camera vertex t - 1 after specular vertices only (t <= firstSmooth + 1) is
  // left to the pass apart, when it is.
  const int leftOut = ctx_.settings.specularChainsApart ? firstSmoothCameraVertex() + 1 : 1;
  for (int t = 1; t <= static_cast<int>(camera_.size()); ++t)
    for (int s = 0; s <= static_cast<int>(light_.size()); ++s) {
      // (1,1) would need the light vertex itself to be seen by the pinhole; (0,2) covers it.
      if (s + t - 1 > maxDepth || (s == 1 && t == 1) || (s == 0 && t <= leftOut)) continue;
      connect(s, t, film, source, out);
    }
}

int Bdpt::firstSmoothCameraVertex() const {
  int k = 1;
  while (k < static_cast<int>(camera_.size()) && camera_[size_t(k)].isSurface() && camera_[size_t(k)].delta) ++k;
  return k;
}

bool Bdpt::traceStrategy(int s, int t, const Vec2& film, SampleSource& source, PathSample& out) {
  if (t < 1 || s < 0 || (s == 1 && t == 1) || s + t - 1 < 1) return false;
  generateCameraSubpath(film, source, static_cast<size_t>(t));
  if (static_cast<int>(camera_.size()) < t) return false;
  light_.clear();
  if (s > 0) {
    generateLightSubpath(source, static_cast<size_t>(s));
    if (static_cast<int>(light_.size()) < s) return false;
  }
  const size_t before = out.splats.size();
  connect(s, t, film, source, out);
  return out.splats.size() > before;
}

// One strategy's connection: everything but the end BSDFs (front), the ends and the directions
// they are evaluated towards, where it splats, and its light and camera vertices (for s = 1 the
// light point sampled, held here).
struct BdptConnection {
  Color front{0.0f};
  const PathVertex *lightEnd = nullptr, *cameraEnd = nullptr;
  Vec3 wL{0.0f}, wC{0.0f};
  Vec2 splatFilm{0.0f};
  PathClass cls{};
  PathVertex sampled;
  LightPoint lp;
  std::span<PathVertex> lightSpan, cameraSpan;
};

namespace {

// t = 1: light vertex l seen through the camera, splatted where it lands on the film.
bool joinCamera(const PathContext& ctx, bool smoothToo, const PathVertex& l, BdptConnection& c) {
  if (!smoothToo && l.isSurface() && l.delta) return false;
  const Vec3 toCam = ctx.camera.position() - l.sp.p;
  const float dist2 = glm::dot(toCam, toCam);
  if (!(dist2 > 0.0f)) return false;
  const Vec3 w = toCam / std::sqrt(dist2);
  const auto fp = ctx.camera.filmPosition(-w);
  if (!fp) return false;
  const float cosCam = glm::dot(ctx.camera.forward(), -w);
  c.front = l.beta * (cosAt(l, w) * cosCam / dist2 * ctx.camera.importance(-w));
  if (l.isSurface()) {
    c.lightEnd = &l;
    c.wL = w;
  } else {
    c.front *= l.delta ? ctx.lights.intensity(l.light, w) : ctx.lights.emitted(l.sp, w);
  }
  c.splatFilm = *fp;
  c.cls = PathClass::L4;
  return true;
}

// s = 1: a light point sampled for camera vertex v (next-event estimation).
bool joinLightSample(const PathContext& ctx, bool smoothToo, const PathVertex& v, SampleSource& source,
                     BdptConnection& c) {
  if (!smoothToo && v.delta) return false;
  const float uPick = source.next(SampleStream::Connection);
  const Vec2 uPos = source.next2(SampleStream::Connection);
  c.lp = ctx.lights.samplePoint(uPick, uPos);
  c.sampled = lightVertex(c.lp);
  const Vec3 d = c.sampled.sp.p - v.sp.p;
  const float dist2 = glm::dot(d, d);
  if (!(dist2 > 0.0f)) return false;
  const Vec3 w = d / std::sqrt(dist2);
  const Color le = c.lp.delta ? ctx.lights.intensity(c.lp.light, -w) : ctx.lights.emitted(c.lp.sp, -w);
  c.front = v.beta * le * c.sampled.beta * (cosAt(v, w) * cosAt(c.sampled, w) / dist2);
  c.cameraEnd = &v;
  c.wC = w;
  c.lightSpan = std::span<PathVertex>(&c.sampled, 1);
  c.cls = PathClass::L2;
  return true;
}

// The geometry of strategy (s, t) without its end BSDFs: s = 0 the camera subpath hit an emitter,
// t = 1 a light vertex seen by the camera, s = 1 a light point sampled for the camera end, else
// the two subpaths' ends joined. False when it cannot contribute. smoothToo: also join at smooth
// (delta) vertices, whose own contribution is zero (a hook may give them one).
bool joinEnds(const PathContext& ctx, bool smoothToo, std::span<PathVertex> light, std::span<PathVertex> camera,
              const Vec2& film, SampleSource& source, BdptConnection& c) {
  const int s = int(light.size()), t = int(camera.size());
  c.splatFilm = film;
  c.lightSpan = light;
  c.cameraSpan = camera;
  if (s == 0) {
    const PathVertex& v = camera[t - 1];
    if (!v.isSurface()) return false;
    c.front = v.beta * ctx.lights.emitted(v.sp, v.wo);
    c.cls = anyDelta(camera.subspan(1, t - 2)) ? PathClass::L0 : PathClass::L1;
    return true;
  }
  if (t == 1) return joinCamera(ctx, smoothToo, light[s - 1], c);
  if (s == 1) return joinLightSample(ctx, smoothToo, camera[t - 1], source, c);
  const PathVertex& l = light[s - 1];
  const PathVertex& v = camera[t - 1];
  if (!smoothToo && (l.delta || v.delta)) return false;
  const Vec3 d = v.sp.p - l.sp.p;
  const float dist2 = glm::dot(d, d);
  if (!(dist2 > 0.0f)) return false;
  const Vec3 w = d / std::sqrt(dist2);
  c.front = l.beta * v.beta * (cosAt(l, w) * cosAt(v, w) / dist2);
  c.lightEnd = &l;
  c.cameraEnd = &v;
  c.wL = w;
  c.wC = -w;
  c.cls = PathClass::L5;
  return true;
}

// front * f_L * f_C, with the given BSDFs at the ends (null: the vertex's own).
inline Color endsValue(const BdptConnection& c, const Bsdf* bL, const Bsdf* bC) {
  Color v = c.front;
  if (c.lightEnd) v *= surfaceF(*c.lightEnd, c.wL, TransportMode::Importance, bL);
  if (c.cameraEnd && !isBlack(v)) v *= surfaceF(*c.cameraEnd, c.wC, TransportMode::Radiance, bC);
  return v;
}

// One visibility ray for the path's own contribution and a hook's (s = light vertices).
bool connectionBlocked(const PathContext& ctx, int s, const BdptConnection& c) {
  if (s == 0) return false;  // the camera subpath found the emitter itself
  if (c.cameraSpan.size() == 1) {
    const PathVertex& l = c.lightSpan.back();
    return ctx.tracer.occludedToPoint(l.sp.p, l.sp.ng, ctx.camera.position());
  }
  if (s == 1)
    return c.lp.delta ? ctx.tracer.occludedToPoint(c.cameraEnd->sp.p, c.cameraEnd->sp.ng, c.lp.sp.p)
                      : ctx.tracer.occluded(c.cameraEnd->sp.p, c.cameraEnd->sp.ng, c.lp.sp.p, c.lp.sp.ng);
  return ctx.tracer.occluded(c.lightEnd->sp.p, c.lightEnd->sp.ng, c.cameraEnd->sp.p, c.cameraEnd->sp.ng);
}

}  // namespace

namespace {

// A connection shown to a hook: its ends and their re-evaluation with other BSDFs.
class HookedConnection final : public ConnectionEnds {
 public:
  HookedConnection(const Bdpt& bdpt, const BdptConnection& c) : bdpt_(bdpt), c_(c) {}
  const PathVertex* lightEnd() const override { return c_.lightEnd; }
  const PathVertex* cameraEnd() const override { return c_.cameraEnd; }
  Color value(const Bsdf* atLight, const Bsdf* atCamera) const override { return endsValue(c_, atLight, atCamera); }
  float misWeight(const Bsdf* atLight, const Bsdf* atCamera) const override {
    return bdpt_.misWeight(c_.lightSpan, c_.cameraSpan, atLight, atCamera);
  }

 private:
  const Bdpt& bdpt_;
  const BdptConnection& c_;
};

}  // namespace

// A strategy's contribution is front * f_L * f_C: f_L, f_C are the BSDFs of the surface vertices
// the connection joins (absent at a light or camera end) and front everything else. A hook
// re-evaluates only those two BSDFs and the MIS weight.
void Bdpt::connect(int s, int t, const Vec2& film, SampleSource& source, PathSample& out) {
  BdptConnection c;
  const std::span<PathVertex> light(light_.data(), size_t(s)), camera(camera_.data(), size_t(t));
  if (!joinEnds(ctx_, hook_ != nullptr, light, camera, film, source, c) || isBlack(c.front)) return;
  const bool smoothEnd = (c.lightEnd && c.lightEnd->delta) || (c.cameraEnd && c.cameraEnd->delta);
  const Color contrib = smoothEnd ? Color(0.0f) : endsValue(c, nullptr, nullptr);
  bool any = !isBlack(contrib);
  if (hook_ != nullptr) any |= hook_->prepare(HookedConnection(*this, c));
  if (!any || connectionBlocked(ctx_, s, c)) return;

  float weight = 0.0f;
  if (!isBlack(contrib)) {
    weight = misWeight(c.lightSpan, c.cameraSpan);
    out.add(c.splatFilm, contrib * weight, c.cls);
    if (observer_) observer_(c.lightSpan, c.cameraSpan, weight, contrib);
  }
  if (hook_ != nullptr) hook_->add(HookedConnection(*this, c), luminance(contrib * weight));
}

float Bdpt::misWeight(std::span<PathVertex> light, std::span<PathVertex> camera, const Bsdf* lightEnd,
                      const Bsdf* cameraEnd) const {
  const int s = static_cast<int>(light.size()), t = static_cast<int>(camera.size()), n = s + t;
  if (n == 2) return 1.0f;
  // Full path x_0 (light end) .. x_{n-1} (camera). fromLight[i] / fromCamera[i]: area density of
  // x_i when generated from the light / camera end (Veach 1997 §10.2).
  float fromLight[2 * 256 + 4], fromCamera[2 * 256 + 4];
  bool delta[2 * 256 + 4];
  for (int i = 0; i < n; ++i) {
    const PathVertex& v = i < s ? light[i] : camera[n - 1 - i];
    fromLight[i] = i < s ? v.pdfFwd : v.pdfRev;
    fromCamera[i] = i < s ? v.pdfRev : v.pdfFwd;
    delta[i] = v.isSurface() && v.delta;
  }
  if (lightEnd) delta[s - 1] = lightEnd->isDelta();
  if (cameraEnd) delta[s] = cameraEnd->isDelta();
  const PathVertex* ls = s > 0 ? &light[s - 1] : nullptr;
  const PathVertex* lsPrev = s > 1 ? &light[s - 2] : nullptr;
  const PathVertex& ct = camera[t - 1];
  const PathVertex* ctPrev = t > 1 ? &camera[t - 2] : nullptr;

  // Densities that change because the subpaths are now joined (the four vertices at the seam).
  if (ls) {
    const Vec3 toLs = glm::normalize(ls->sp.p - ct.sp.p);
    fromCamera[s - 1] = pdfGenerate(ctx_, ct, ct.toPrev, *ls, roulette_, cameraEnd);
    if (lsPrev) fromCamera[s - 2] = pdfGenerate(ctx_, *ls, -toLs, *lsPrev, roulette_, lightEnd);
    fromLight[s] = pdfGenerate(ctx_, *ls, ls->toPrev, ct, roulette_, lightEnd);
    if (ctPrev) fromLight[s + 1] = pdfGenerate(ctx_, ct, toLs, *ctPrev, roulette_, cameraEnd);
  } else {
    // s = 0: the camera subpath ended on an emitter; the light end would have chosen it by power.
    const uint32_t tri = ct.sp.triangle;
    fromLight[0] = ctx_.lights.pdfPickTriangle(tri) / ctx_.tracer.triangleArea(tri);
    if (ctPrev) {
      const Vec3 w = glm::normalize(ctPrev->sp.p - ct.sp.p);
      fromLight[1] = solidAngleToArea(ctx_.lights.pdfDirection(ctx_.lights.lightOfTriangle(tri), ct.sp, w), ct, *ctPrev);
    }
  }
  const bool deltaLight = s > 0 && light[0].type == PathVertex::Type::Light && light[0].delta;
  const MisHeuristic h = ctx_.settings.heuristic;

  float sum = 0.0f, r = 1.0f;
  // Strategies with more light vertices: x_k moves from the camera to the light subpath.
  for (int k = s; k <= n - 2; ++k) {
    r *= remap0(fromLight[k]) / remap0(fromCamera[k]);
    if (!delta[k] && !delta[k + 1]) sum += misWeightTerm(r, h);
  }
  // Strategies with fewer light vertices: x_k moves to the camera subpath.
  r = 1.0f;
  for (int k = s - 1; k >= 0; --k) {
    r *= remap0(fromCamera[k]) / remap0(fromLight[k]);
    const bool prevDelta = k > 0 ? delta[k - 1] : deltaLight;
    if (!delta[k] && !prevDelta) sum += misWeightTerm(r, h);
  }
  return 1.0f / (1.0f + sum);
}

}  // namespace relt
