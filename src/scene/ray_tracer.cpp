#include "scene/ray_tracer.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace relt {
namespace {

void embreeError(void*, RTCError code, const char* message) {
  throw std::runtime_error(std::string("Embree error ") + std::to_string(static_cast<int>(code)) + ": " +
                           (message ? message : ""));
}

// Embree requires rays it calls valid (RayK::valid: every origin and direction component finite
// and within 1.8e18; Debian's build asserts it). The loader keeps the scene within 1e15, so only a
// degenerate sample (a NaN or infinite number) makes another one: it hits nothing and its shadow
// ray is blocked, so the sample contributes nothing instead of ending the process.
bool traceableRay(const Vec3& o, const Vec3& d) {
  constexpr float kLarge = 1.8e18f;
  auto within = [](const Vec3& v) {  // false for NaN too
    return std::abs(v.x) <= kLarge && std::abs(v.y) <= kLarge && std::abs(v.z) <= kLarge;
  };
  return within(o) && within(d);
}

// A single ray from o along the unit direction d up to tfar, every field set.
void setRay(RTCRay& r, const Vec3& o, const Vec3& d, float tfar) {
  r.org_x = o.x;
  r.org_y = o.y;
  r.org_z = o.z;
  r.dir_x = d.x;
  r.dir_y = d.y;
  r.dir_z = d.z;
  r.tnear = 0.0f;
  r.tfar = tfar;
  r.time = 0.0f;
  r.mask = 0xffffffffu;
  r.id = 0;
  r.flags = 0;
}

// Vectors whose dot products with (p - p0) give the barycentrics (b1, b2) of a point p in the
// triangle's plane: the dual basis of the edges p1 - p0 and p2 - p0. Zero for a degenerate one.
// In double: |n|^2 grows with the fourth power of the edges and would leave float's range for
// edges beyond about 1e9 or below 1e-10 (the loader allows coordinates up to 1e15).
RayTracer::BarycentricAxes barycentricAxes(const Vec3& p0, const Vec3& p1, const Vec3& p2) {
  const glm::dvec3 e1 = glm::dvec3(p1) - glm::dvec3(p0), e2 = glm::dvec3(p2) - glm::dvec3(p0), n = glm::cross(e1, e2);
  const double n2 = glm::dot(n, n);
  if (!(n2 > 0.0)) return {Vec3(0.0f), Vec3(0.0f)};
  return {Vec3(glm::cross(e2, n) / n2), Vec3(glm::cross(n, e1) / n2)};
}

}  // namespace

RayTracer::RayTracer(const Scene& scene) : scene_(scene) {
  // One thread per rank: MPI provides the parallelism, so Embree must not spread over the cores.
  device_ = rtcNewDevice("threads=1,set_affinity=0");
  if (!device_) throw std::runtime_error("cannot create the Embree device");
  rtcSetDeviceErrorFunction(device_, embreeError, nullptr);
  // Packets only where the ISA runs them natively (otherwise Embree splits them into single rays).
  packetWidth_ = rtcGetDeviceProperty(device_, RTC_DEVICE_PROPERTY_NATIVE_RAY16_SUPPORTED)  ? 16
                 : rtcGetDeviceProperty(device_, RTC_DEVICE_PROPERTY_NATIVE_RAY8_SUPPORTED) ? 8
                 : rtcGetDeviceProperty(device_, RTC_DEVICE_PROPERTY_NATIVE_RAY4_SUPPORTED) ? 4
                                                                                            : 1;

  const size_t nt = scene.triangles.size();
  ng_.resize(nt);
  area_.resize(nt);
  flatNs_.resize(nt);
  baryAxes_.resize(nt);
  for (size_t i = 0; i < nt; ++i) {
    const Triangle& t = scene.triangles[i];
    const Vec3 c = glm::cross(scene.positions[t.v[1]] - scene.positions[t.v[0]],
                              scene.positions[t.v[2]] - scene.positions[t.v[0]]);
    const float len = glm::length(c);
    area_[i] = 0.5f * len;
    ng_[i] = len > 0.0f ? c / len : Vec3(0, 0, 1);
    baryAxes_[i] = barycentricAxes(scene.positions[t.v[0]], scene.positions[t.v[1]], scene.positions[t.v[2]]);
    // Equal (or missing) vertex normals: the shading normal is constant, no need to interpolate.
    const Vec3 &n0 = scene.normals[t.v[0]], &n1 = scene.normals[t.v[1]], &n2 = scene.normals[t.v[2]];
    const float len2 = glm::dot(n0, n0);
    flatNs_[i] = n0 != n1 || n0 != n2 ? Vec3(0.0f) : len2 > 1e-12f ? n0 / std::sqrt(len2) : ng_[i];
  }
  const Vec3 ext = glm::max(glm::abs(scene.bounds.lo), glm::abs(scene.bounds.hi));
  const float scale = scene.bounds.empty() ? 1.0f : std::max(1.0f, std::max(ext.x, std::max(ext.y, ext.z)));
  epsilonFloor_ = std::max(1.0f, 0.01f * scale);

  rtcScene_ = rtcNewScene(device_);
  rtcSetSceneBuildQuality(rtcScene_, RTC_BUILD_QUALITY_HIGH);
  if (nt > 0) {
    quads_ = pairTriangles(scene.triangles, scene.positions);
    RTCGeometry geom = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_QUAD);
    rtcSetGeometryBuildQuality(geom, RTC_BUILD_QUALITY_HIGH);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                          3 * sizeof(float), scene.positions.size()));
    for (size_t i = 0; i < scene.positions.size(); ++i) {
      v[3 * i + 0] = scene.positions[i].x;
      v[3 * i + 1] = scene.positions[i].y;
      v[3 * i + 2] = scene.positions[i].z;
    }
    auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT4,
                                                               4 * sizeof(unsigned), quads_.size()));
    for (size_t i = 0; i < quads_.size(); ++i)
      for (int k = 0; k < 4; ++k) idx[4 * i + k] = quads_[i].v[k];
    rtcCommitGeometry(geom);
    rtcAttachGeometry(rtcScene_, geom);
    rtcReleaseGeometry(geom);
  }
  rtcCommitScene(rtcScene_);
}

RayTracer::~RayTracer() {
  if (rtcScene_) rtcReleaseScene(rtcScene_);
  if (device_) rtcReleaseDevice(device_);
}

Vec3 RayTracer::interpolatedNormal(const Triangle& tri, float b0, float b1, float b2, const Vec3& ng) const {
  const Vec3 n = b0 * scene_.normals[tri.v[0]] + b1 * scene_.normals[tri.v[1]] + b2 * scene_.normals[tri.v[2]];
  const float len2 = glm::dot(n, n);
  // Degenerate interpolated normals fall back to the geometric one (flat shading).
  return len2 > 1e-12f ? n / std::sqrt(len2) : ng;
}

// Out of line on purpose: single rays and packets must compute a hit's point with the same code.
[[gnu::noinline]] SurfacePoint RayTracer::hitPoint(uint32_t quad, float u, float v, const Vec3& origin, const Vec3& dir,
                                                   float distance) const {
  const uint32_t t = hitTriangle(quads_[quad], u, v);
  const Vec3 q = origin + distance * dir - scene_.positions[scene_.triangles[t].v[0]];
  const BarycentricAxes& a = baryAxes_[t];
  return surfacePoint(t, glm::dot(q, a.b1), glm::dot(q, a.b2));
}

bool RayTracer::intersect(const Ray& ray, SurfacePoint& hit, float& distance) const {
  rays_.add(1);
  if (!traceableRay(ray.origin, ray.dir) || std::isnan(ray.tMax)) return false;
  RTCIntersectContext ctx;
  rtcInitIntersectContext(&ctx);
  RTCRayHit rh;
  setRay(rh.ray, ray.origin, ray.dir, ray.tMax);
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(rtcScene_, &ctx, &rh);
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;
  distance = rh.ray.tfar;
  hit = hitPoint(rh.hit.primID, rh.hit.u, rh.hit.v, ray.origin, ray.dir, distance);
  return true;
}

struct RayTracer::ShadowRay {
  Vec3 o, d;  // origin (offset off the surface) and unit direction
  float tfar;
};

bool RayTracer::shadowRay(const Segment& seg, ShadowRay& ray, bool& blocked) const {
  Vec3 o, d;
  if (seg.toPoint) {
    o = offsetOrigin(seg.from, seg.fromNg, seg.to - seg.from);
    d = seg.to - o;
  } else {
    const Vec3 d0 = seg.to - seg.from;
    o = offsetOrigin(seg.from, seg.fromNg, d0);
    d = offsetOrigin(seg.to, seg.toNg, -d0) - o;
  }
  const float len = glm::length(d);
  blocked = false;
  if (!(len > 0.0f)) return false;
  ray = ShadowRay{o, d / len, len * (1.0f - 1e-4f)};
  // Embree must not see an untraceable ray (see traceableRay): treat it as blocked.
  blocked = !traceableRay(ray.o, ray.d) || !(ray.tfar >= 0.0f);
  return !blocked;
}

bool RayTracer::occluded(const Vec3& from, const Vec3& fromNg, const Vec3& to, const Vec3& toNg) const {
  return occluded(Segment{from, fromNg, to, toNg, false, true});
}

bool RayTracer::occludedToPoint(const Vec3& from, const Vec3& fromNg, const Vec3& point) const {
  return occluded(Segment{from, fromNg, point, Vec3(0.0f), true, true});
}

bool RayTracer::occluded(const Segment& seg) const {
  rays_.add(1);
  ShadowRay sr;
  bool blocked;
  if (!shadowRay(seg, sr, blocked)) return blocked;
  RTCIntersectContext ctx;
  rtcInitIntersectContext(&ctx);
  RTCRay r;
  setRay(r, sr.o, sr.d, sr.tfar);
  rtcOccluded1(rtcScene_, &ctx, &r);
  return r.tfar < 0.0f;
}

namespace {

// Embree's packet types and calls by width (4, 8 or 16).
template <int K>
struct Packet {
  using RayHit = std::conditional_t<K == 4, RTCRayHit4, std::conditional_t<K == 8, RTCRayHit8, RTCRayHit16>>;
  using Ray = std::conditional_t<K == 4, RTCRay4, std::conditional_t<K == 8, RTCRay8, RTCRay16>>;
  static void intersect(const int* v, RTCScene s, RTCIntersectContext* c, RayHit* r) {
    if constexpr (K == 4) rtcIntersect4(v, s, c, r);
    else if constexpr (K == 8) rtcIntersect8(v, s, c, r);
    else rtcIntersect16(v, s, c, r);
  }
  static void occluded(const int* v, RTCScene s, RTCIntersectContext* c, Ray* r) {
    if constexpr (K == 4) rtcOccluded4(v, s, c, r);
    else if constexpr (K == 8) rtcOccluded8(v, s, c, r);
    else rtcOccluded16(v, s, c, r);
  }
};

template <class RayK>
void setLane(RayK& r, int i, const Vec3& o, const Vec3& d, float tfar) {
  r.org_x[i] = o.x;
  r.org_y[i] = o.y;
  r.org_z[i] = o.z;
  r.dir_x[i] = d.x;
  r.dir_y[i] = d.y;
  r.dir_z[i] = d.z;
  r.tnear[i] = 0.0f;
  r.tfar[i] = tfar;
  r.time[i] = 0.0f;
  r.mask[i] = 0xffffffffu;
  r.id[i] = 0;
  r.flags[i] = 0;
}

}  // namespace

template <int K>
void RayTracer::intersectPackets(const Ray* rays, int n, SurfacePoint* hits, float* distance, bool* found) const {
  for (int base = 0; base < n; base += K) {
    const int m = std::min(K, n - base);
    alignas(64) int valid[K] = {};
    alignas(64) typename Packet<K>::RayHit rh;
    bool any = false;
    for (int i = 0; i < m; ++i) {
      const Ray& r = rays[base + i];
      found[base + i] = false;
      if (!traceableRay(r.origin, r.dir) || std::isnan(r.tMax)) continue;
      setLane(rh.ray, i, r.origin, r.dir, r.tMax);
      rh.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
      rh.hit.instID[0][i] = RTC_INVALID_GEOMETRY_ID;
      valid[i] = -1;
      any = true;
    }
    rays_.add(static_cast<uint64_t>(m));
    if (!any) continue;
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    Packet<K>::intersect(valid, rtcScene_, &ctx, &rh);
    for (int i = 0; i < m; ++i) {
      if (!valid[i] || rh.hit.geomID[i] == RTC_INVALID_GEOMETRY_ID) continue;
      found[base + i] = true;
      distance[base + i] = rh.ray.tfar[i];
      hits[base + i] = hitPoint(rh.hit.primID[i], rh.hit.u[i], rh.hit.v[i], rays[base + i].origin, rays[base + i].dir,
                                distance[base + i]);
    }
  }
}

template <int K>
void RayTracer::occludedPackets(const Segment* segs, int n, bool* blocked) const {
  for (int base = 0; base < n; base += K) {
    const int m = std::min(K, n - base);
    alignas(64) int valid[K] = {};
    alignas(64) typename Packet<K>::Ray r;
    bool any = false;
    for (int i = 0; i < m; ++i) {
      blocked[base + i] = false;
      if (!segs[base + i].active) continue;
      rays_.add(1);
      ShadowRay sr;
      if (!shadowRay(segs[base + i], sr, blocked[base + i])) continue;
      setLane(r, i, sr.o, sr.d, sr.tfar);
      valid[i] = -1;
      any = true;
    }
    if (!any) continue;
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    Packet<K>::occluded(valid, rtcScene_, &ctx, &r);
    for (int i = 0; i < m; ++i)
      if (valid[i]) blocked[base + i] = r.tfar[i] < 0.0f;
  }
}

void RayTracer::intersect(const Ray* rays, int n, SurfacePoint* hits, float* distance, bool* found) const {
  switch (packetWidth_) {
    case 16: return intersectPackets<16>(rays, n, hits, distance, found);
    case 8: return intersectPackets<8>(rays, n, hits, distance, found);
    case 4: return intersectPackets<4>(rays, n, hits, distance, found);
    default:
      for (int i = 0; i < n; ++i) found[i] = intersect(rays[i], hits[i], distance[i]);
  }
}

void RayTracer::occluded(const Segment* segs, int n, bool* blocked) const {
  if (n > 1 && packetWidth_ > 1) {
    switch (packetWidth_) {
      case 16: return occludedPackets<16>(segs, n, blocked);
      case 8: return occludedPackets<8>(segs, n, blocked);
      default: return occludedPackets<4>(segs, n, blocked);
    }
  }
  for (int i = 0; i < n; ++i) blocked[i] = segs[i].active && occluded(segs[i]);
}

}  // namespace relt
