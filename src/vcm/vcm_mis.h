#pragma once
// VCM's MIS (thesis digest §1.6): the recursive quantities dVCM, dVC, dVM a subpath carries, how
// each step of the subpath changes them, and the weight of every technique from the two subpaths'
// quantities. Pure functions of the vertices and directions, apart from sampling and visibility:
// tests check them against weights from every technique's explicit density.
//
// Densities are relt's film-wide ones (as Bdpt's): the camera's direction density is that of one
// sample over the whole film, and each camera sample has one light subpath to connect to, so light
// tracing splats count as BDPT's do. Area conversions use geometric normals and the segment
// between stored positions; Russian roulette by material, the same both ways.
#include <optional>
#include <string_view>

#include "light/lights.h"
#include "material/bsdf.h"
#include "path/path_context.h"

namespace relt {

enum class VcmMode : uint8_t {
  Vcm,  // every technique
  Bpt,  // connections only: bdpt's estimator
  Ppm,  // merging only at the first non-specular camera vertex: progressive photon mapping
};
std::optional<VcmMode> parseVcmMode(std::string_view name);
const char* vcmModeName(VcmMode mode);

// What the techniques of one iteration need to know.
struct VcmIteration {
  VcmMode mode = VcmMode::Vcm;
  float radius = 0.0f;      // merging radius r
  double lightPaths = 1.0;  // N_L, the light subpaths traced in the iteration
  // kappa: a factor on the densities of the techniques that use a light subpath (light tracing,
  // connections with s >= 2, merging) against next-event estimation and emission found (s = 0, 1).
  // 1 is plain VCM; meb's visibility chain draws light subpaths with density p / b_vis, so it
  // weighs them by 1 / b_vis (thesis digest §5.4). Any constant keeps the weights a partition of 1.
  double lightSubpathFactor = 1.0;
};

// The MIS state of a subpath while it is traced.
struct VcmSubpath {
  Vec3 origin{0.0f}, dir{0.0f}, last{0.0f};  // the next ray, and the last vertex's position
  Color beta{1.0f};
  float dVCM = 0.0f, dVC = 0.0f, dVM = 0.0f;
  int length = 0;
  bool specular = true;  // camera: every scattering so far was specular
};

// A stored vertex of a light subpath (non-specular surfaces only).
struct LightVertex {
  SurfacePoint sp;
  Vec3 wo{0.0f};     // towards the previous vertex of its subpath, along the traced ray
  Color beta{0.0f};  // throughput from the light to here
  float dVCM = 0.0f, dVC = 0.0f, dVM = 0.0f;
  int length = 0;  // segments from the light
};

// The weight of next-event estimation or emission found (the techniques without a light subpath)
// as 1 / (1 + other + kappa * light): `other`, the other one's term; `light`, the terms of every
// technique with a light subpath, which the light subpath factor kappa multiplies. Kept apart for
// meb, which learns kappa only after its camera subpaths are traced.
struct CameraTechniqueWeight {
  float other = 0.0f, light = 0.0f;
  bool possible = true;  // false: the technique cannot make this path (weight 0)
  float weight(float kappa) const { return possible ? 1.0f / (1.0f + other + kappa * light) : 0.0f; }
};

class VcmMis {
 public:
  VcmMis(const PathContext& ctx, const VcmIteration& iteration);

  bool connects() const { return mode_ != VcmMode::Ppm; }
  bool merges() const { return mode_ != VcmMode::Bpt; }
  VcmMode mode() const { return mode_; }
  double mergeNormalisation() const { return mergeNormalisation_; }  // 1 / (pi r^2 N_L)

  // A light subpath leaving lp along dir (pdfDir: that direction's density from lp; cosLight: at lp).
  void startLight(VcmSubpath& s, const LightPoint& lp, float pdfDir, float cosLight) const;
  // A camera subpath leaving the pinhole in a direction of density pdfCamera.
  void startCamera(VcmSubpath& s, float pdfCamera) const;
  // The subpath reached `hit` from s.last (segment length and cosine there); false if degenerate.
  bool arrive(VcmSubpath& s, const SurfacePoint& hit) const;
  // The subpath scattered at sp from wo (towards its previous vertex) into wi; false if the
  // BSDF's density there is zero.
  bool scatter(VcmSubpath& s, const Bsdf& bsdf, const SurfacePoint& sp, const Vec3& wo, const Vec3& wi) const;

  // Weights: the camera subpath found emission at hit (leaving towards wo); next-event estimation
  // from camera vertex x to light point lp; camera vertex x joined to light vertex y; light vertex
  // y seen by the camera; camera vertex at y's position merged with y.
  float emissionWeight(const VcmSubpath& s, const SurfacePoint& hit, const Vec3& wo) const {
    return emissionWeightParts(s, hit, wo).weight(kappa_);
  }
  float nextEventWeight(const VcmSubpath& s, const SurfacePoint& x, const Vec3& wo, const Bsdf& bsdf,
                        const LightPoint& lp) const {
    return nextEventWeightParts(s, x, wo, bsdf, lp).weight(kappa_);
  }
  CameraTechniqueWeight emissionWeightParts(const VcmSubpath& s, const SurfacePoint& hit, const Vec3& wo) const;
  CameraTechniqueWeight nextEventWeightParts(const VcmSubpath& s, const SurfacePoint& x, const Vec3& wo,
                                             const Bsdf& bsdf, const LightPoint& lp) const;
  // Mis(kappa): what CameraTechniqueWeight::weight takes.
  float lightSubpathTerm() const { return kappa_; }
  float connectWeight(const VcmSubpath& s, const SurfacePoint& x, const Vec3& wo, const Bsdf& bsdf,
                      const LightVertex& y, const Bsdf& atY) const;
  float lightTracingWeight(const LightVertex& y, const Bsdf& atY) const;
  float mergeWeight(const VcmSubpath& s, const Vec3& wo, const Bsdf& bsdf, const LightVertex& y) const;

 private:
  float mis(float v) const { return misWeightTerm(v, ctx_.settings.heuristic); }

  const PathContext& ctx_;
  VcmMode mode_;
  float vmWeight_ = 0.0f, vcWeight_ = 0.0f;  // Mis(eta) and Mis(1 / eta), eta = pi r^2 N_L
  float kappa_ = 1.0f;                       // Mis(lightSubpathFactor)
  double mergeNormalisation_ = 0.0;
};

}  // namespace relt
