#include "path/bdpt.h"

namespace relt {
namespace {

// Veach 1997 §5.3: with shading normals the adjoint BSDF needs this factor on light subpaths.
float shadingCorrection(const SurfacePoint& sp, const Vec3& wo, const Vec3& wi) {
  const float den = std::abs(glm::dot(wo, sp.ng)) * std::abs(glm::dot(wi, sp.ns));
  return den > 0.0f ? std::abs(glm::dot(wo, sp.ns)) * std::abs(glm::dot(wi, sp.ng)) / den : 0.0f;
}

Color surfaceF(const PathVertex& v, const Vec3& w, TransportMode mode) {
  Color f = v.bsdf->eval(v.wo, w, mode);
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
// before it in the generating direction), generates vertex `to`.
float pdfGenerate(const PathContext& ctx, const PathVertex& from, const Vec3& arrive, const PathVertex& to,
                  bool roulette) {
  const Vec3 w = glm::normalize(to.sp.p - from.sp.p);
  float pdfW = 0.0f;
  switch (from.type) {
    case PathVertex::Type::Camera: pdfW = ctx.camera.pdfDirection(w); break;
    case PathVertex::Type::Light: pdfW = ctx.lights.pdfDirection(from.light, from.sp, w); break;
    case PathVertex::Type::Surface:
      pdfW = from.bsdf->pdf(arrive, w) * (roulette ? continuationProbability(from.bsdf->material()) : 1.0f);
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

// Densities are evaluated along the directions between stored vertex positions, not along the
// sampled ray directions (which start from an offset origin): the MIS weights are then a function
// of the path's vertices alone and sum to exactly 1 over the strategies that can make it.
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
      v.wo = glm::normalize(prev.sp.p - hit.p);
      v.beta = beta;
      v.pdfFwd = pdfGenerate(ctx_, prev, prev.wo, v, roulette_);
      if (path.size() >= 2) {
        PathVertex& prevPrev = path[path.size() - 2];
        prevPrev.pdfRev = pdfGenerate(ctx_, prev, -v.wo, prevPrev, roulette_);
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
}

void Bdpt::trace(const Vec2& film, SampleSource& source, PathSample& out) {
  generateCameraSubpath(film, source, static_cast<size_t>(ctx_.settings.maxDepth) + 1);
  generateLightSubpath(source, static_cast<size_t>(ctx_.settings.maxDepth));
  const int maxDepth = ctx_.settings.maxDepth;
  for (int t = 1; t <= static_cast<int>(camera_.size()); ++t)
    for (int s = 0; s <= static_cast<int>(light_.size()); ++s) {
      const int segments = s + t - 1;
      // (1,1) would need the light vertex itself to be seen by the pinhole; (0,2) covers it.
      if (segments < 1 || segments > maxDepth || (s == 1 && t == 1)) continue;
      connect(s, t, film, source, out);
    }
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

void Bdpt::connect(int s, int t, const Vec2& film, SampleSource& source, PathSample& out) {
  Color contrib(0.0f);
  Vec2 splatFilm = film;
  PathClass cls;
  PathVertex sampled;
  std::span<PathVertex> lightSpan(light_.data(), static_cast<size_t>(s));
  std::span<PathVertex> cameraSpan(camera_.data(), static_cast<size_t>(t));

  if (s == 0) {
    const PathVertex& c = camera_[t - 1];
    if (!c.isSurface()) return;
    contrib = c.beta * ctx_.lights.emitted(c.sp, c.wo);
    if (isBlack(contrib)) return;
    cls = anyDelta(cameraSpan.subspan(1, t - 2)) ? PathClass::L0 : PathClass::L1;
  } else if (t == 1) {
    const PathVertex& l = light_[s - 1];
    if (l.isSurface() && l.delta) return;
    const Vec3 toCam = ctx_.camera.position() - l.sp.p;
    const float dist2 = glm::dot(toCam, toCam);
    if (!(dist2 > 0.0f)) return;
    const Vec3 w = toCam / std::sqrt(dist2);
    const auto fp = ctx_.camera.filmPosition(-w);
    if (!fp) return;
    const Color f = l.isSurface() ? surfaceF(l, w, TransportMode::Importance)
                    : l.delta     ? ctx_.lights.intensity(l.light, w)
                                  : ctx_.lights.emitted(l.sp, w);
    const float cosCam = glm::dot(ctx_.camera.forward(), -w);
    contrib = l.beta * f * (cosAt(l, w) * cosCam / dist2 * ctx_.camera.importance(-w));
    if (isBlack(contrib) || ctx_.tracer.occludedToPoint(l.sp.p, l.sp.ng, ctx_.camera.position())) return;
    splatFilm = *fp;
    cls = PathClass::L4;
  } else if (s == 1) {
    const PathVertex& c = camera_[t - 1];
    if (c.delta) return;
    const float uPick = source.next(SampleStream::Connection);
    const Vec2 uPos = source.next2(SampleStream::Connection);
    const LightPoint lp = ctx_.lights.samplePoint(uPick, uPos);
    sampled = lightVertex(lp);
    const Vec3 d = sampled.sp.p - c.sp.p;
    const float dist2 = glm::dot(d, d);
    if (!(dist2 > 0.0f)) return;
    const Vec3 w = d / std::sqrt(dist2);
    const Color le = lp.delta ? ctx_.lights.intensity(lp.light, -w) : ctx_.lights.emitted(lp.sp, -w);
    contrib = c.beta * surfaceF(c, w, TransportMode::Radiance) * le * sampled.beta *
              (cosAt(c, w) * cosAt(sampled, w) / dist2);
    if (isBlack(contrib)) return;
    const bool blocked = lp.delta ? ctx_.tracer.occludedToPoint(c.sp.p, c.sp.ng, lp.sp.p)
                                  : ctx_.tracer.occluded(c.sp.p, c.sp.ng, lp.sp.p, lp.sp.ng);
    if (blocked) return;
    lightSpan = std::span<PathVertex>(&sampled, 1);
    cls = PathClass::L2;
  } else {
    const PathVertex& l = light_[s - 1];
    const PathVertex& c = camera_[t - 1];
    if (l.delta || c.delta) return;
    const Vec3 d = c.sp.p - l.sp.p;
    const float dist2 = glm::dot(d, d);
    if (!(dist2 > 0.0f)) return;
    const Vec3 w = d / std::sqrt(dist2);
    contrib = l.beta * surfaceF(l, w, TransportMode::Importance) * surfaceF(c, -w, TransportMode::Radiance) *
              c.beta * (cosAt(l, w) * cosAt(c, w) / dist2);
    if (isBlack(contrib) || ctx_.tracer.occluded(l.sp.p, l.sp.ng, c.sp.p, c.sp.ng)) return;
    cls = PathClass::L5;
  }

  const float weight = misWeight(lightSpan, cameraSpan);
  out.add(splatFilm, contrib * weight, cls);
  if (observer_) observer_(lightSpan, cameraSpan, weight, contrib);
}


float Bdpt::misWeight(std::span<PathVertex> light, std::span<PathVertex> camera) const {
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
  const PathVertex* ls = s > 0 ? &light[s - 1] : nullptr;
  const PathVertex* lsPrev = s > 1 ? &light[s - 2] : nullptr;
  const PathVertex& ct = camera[t - 1];
  const PathVertex* ctPrev = t > 1 ? &camera[t - 2] : nullptr;

  // Densities that change because the subpaths are now joined (the four vertices at the seam).
  if (ls) {
    const Vec3 toLs = glm::normalize(ls->sp.p - ct.sp.p);
    fromCamera[s - 1] = pdfGenerate(ctx_, ct, ct.wo, *ls, roulette_);
    if (lsPrev) fromCamera[s - 2] = pdfGenerate(ctx_, *ls, -toLs, *lsPrev, roulette_);
    fromLight[s] = pdfGenerate(ctx_, *ls, ls->wo, ct, roulette_);
    if (ctPrev) fromLight[s + 1] = pdfGenerate(ctx_, ct, toLs, *ctPrev, roulette_);
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
