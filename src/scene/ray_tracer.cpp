#include "scene/ray_tracer.h"

#include <embree3/rtcore.h>

#include <cmath>
#include <stdexcept>
#include <string>

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

}  // namespace

RayTracer::RayTracer(const Scene& scene) : scene_(scene) {
  // One thread per rank: MPI provides the parallelism, so Embree must not spread over the cores.
  device_ = rtcNewDevice("threads=1,set_affinity=0");
  if (!device_) throw std::runtime_error("cannot create the Embree device");
  rtcSetDeviceErrorFunction(device_, embreeError, nullptr);

  const size_t nt = scene.triangles.size();
  ng_.resize(nt);
  area_.resize(nt);
  flatNs_.resize(nt);
  for (size_t i = 0; i < nt; ++i) {
    const Triangle& t = scene.triangles[i];
    const Vec3 c = glm::cross(scene.positions[t.v[1]] - scene.positions[t.v[0]],
                              scene.positions[t.v[2]] - scene.positions[t.v[0]]);
    const float len = glm::length(c);
    area_[i] = 0.5f * len;
    ng_[i] = len > 0.0f ? c / len : Vec3(0, 0, 1);
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
    RTCGeometry geom = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
    rtcSetGeometryBuildQuality(geom, RTC_BUILD_QUALITY_HIGH);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                          3 * sizeof(float), scene.positions.size()));
    for (size_t i = 0; i < scene.positions.size(); ++i) {
      v[3 * i + 0] = scene.positions[i].x;
      v[3 * i + 1] = scene.positions[i].y;
      v[3 * i + 2] = scene.positions[i].z;
    }
    auto* idx = static_cast<unsigned*>(
        rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), nt));
    for (size_t i = 0; i < nt; ++i)
      for (int k = 0; k < 3; ++k) idx[3 * i + k] = scene.triangles[i].v[k];
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

bool RayTracer::intersect(const Ray& ray, SurfacePoint& hit, float& distance) const {
  ++rays_;
  if (!traceableRay(ray.origin, ray.dir) || std::isnan(ray.tMax)) return false;
  RTCIntersectContext ctx;
  rtcInitIntersectContext(&ctx);
  RTCRayHit rh;
  rh.ray.org_x = ray.origin.x;
  rh.ray.org_y = ray.origin.y;
  rh.ray.org_z = ray.origin.z;
  rh.ray.dir_x = ray.dir.x;
  rh.ray.dir_y = ray.dir.y;
  rh.ray.dir_z = ray.dir.z;
  rh.ray.tnear = 0.0f;
  rh.ray.tfar = ray.tMax;
  rh.ray.time = 0.0f;
  rh.ray.mask = 0xffffffffu;
  rh.ray.id = 0;
  rh.ray.flags = 0;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(rtcScene_, &ctx, &rh);
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;
  distance = rh.ray.tfar;
  hit = surfacePoint(rh.hit.primID, rh.hit.u, rh.hit.v);
  return true;
}

namespace {
bool occludedRay(RTCScene scene, const Vec3& o, const Vec3& d, float tfar) {
  if (!traceableRay(o, d) || !(tfar >= 0.0f)) return true;
  RTCIntersectContext ctx;
  rtcInitIntersectContext(&ctx);
  RTCRay r;
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
  rtcOccluded1(scene, &ctx, &r);
  return r.tfar < 0.0f;
}
}  // namespace

bool RayTracer::occluded(const Vec3& from, const Vec3& fromNg, const Vec3& to, const Vec3& toNg) const {
  ++rays_;
  const Vec3 d0 = to - from;
  const Vec3 o = offsetOrigin(from, fromNg, d0);
  const Vec3 t = offsetOrigin(to, toNg, -d0);
  const Vec3 d = t - o;
  const float len = glm::length(d);
  if (!(len > 0.0f)) return false;
  return occludedRay(rtcScene_, o, d / len, len * (1.0f - 1e-4f));
}

bool RayTracer::occludedToPoint(const Vec3& from, const Vec3& fromNg, const Vec3& point) const {
  ++rays_;
  const Vec3 o = offsetOrigin(from, fromNg, point - from);
  const Vec3 d = point - o;
  const float len = glm::length(d);
  if (!(len > 0.0f)) return false;
  return occludedRay(rtcScene_, o, d / len, len * (1.0f - 1e-4f));
}

}  // namespace relt
