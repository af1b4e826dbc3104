#pragma once
// A surface material as read from the scene (DESIGN §5). BSDFs are built from it per hit.
#include <string>

#include "core/math.h"

namespace relt {

enum class MaterialKind : uint8_t { Lambert, Conductor, Dielectric };
enum class Microfacet : uint8_t { GGX, Beckmann };

struct Material {
  std::string name;
  MaterialKind kind = MaterialKind::Lambert;
  Color baseColor{0.8f};      // Lambert albedo, conductor F0 (Schlick), dielectric transmission tint
  float alpha = 0.0f;         // microfacet roughness alpha = r^2; 0 means perfectly smooth (delta)
  Microfacet distribution = Microfacet::GGX;
  float ior = 1.5f;           // dielectric index of refraction (outside medium is 1)
  Color emission{0.0f};       // emitted radiance: emissiveFactor x emissive strength
  bool doubleSided = false;   // emitters emit from both sides when set (glTF doubleSided)

  bool isEmissive() const { return emission.x > 0.0f || emission.y > 0.0f || emission.z > 0.0f; }
};

}  // namespace relt
