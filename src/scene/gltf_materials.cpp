#include "scene/gltf_materials.h"

namespace relt::gltf {

namespace {

Color toColor(const std::vector<double>& v) {
  return Color(static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2]));
}

Microfacet parseMicrofacet(const Context& ctx, const Json& material, const std::string& element) {
  const Json* extras = getMember(ctx, material, "extras", element);
  if (!extras || !extras->is_object()) return Microfacet::GGX;  // extras are free-form in glTF
  const Json* v = getMember(ctx, *extras, "microfacet", element + ".extras");
  if (!v) return Microfacet::GGX;
  if (v->is_string() && v->get<std::string>() == "ggx") return Microfacet::GGX;
  if (v->is_string() && v->get<std::string>() == "beckmann") return Microfacet::Beckmann;
  ctx.fail(element + ".extras", "microfacet " + brief(*v) + " is not supported (use \"ggx\" or \"beckmann\")");
}

Material parseMaterial(Context& ctx, const Json& o, const std::string& element) {
  Material m;
  m.name = getString(ctx, o, "name", element).value_or("");
  m.doubleSided = getBool(ctx, o, "doubleSided", element, false);

  // glTF defaults: baseColorFactor 1, metallicFactor 1, roughnessFactor 1.
  Color baseColor(1.0f);
  double metallic = 1.0, roughness = 1.0;
  if (const Json* pbr = getObject(ctx, o, "pbrMetallicRoughness", element)) {
    const std::string pe = element + ".pbrMetallicRoughness";
    baseColor = toColor(getNumbers(ctx, *pbr, "baseColorFactor", pe, 4, {1, 1, 1, 1}, 0.0, 1.0));
    metallic = getNumber(ctx, *pbr, "metallicFactor", pe, 1.0, 0.0, 1.0);
    roughness = getNumber(ctx, *pbr, "roughnessFactor", pe, 1.0, 0.0, 1.0);
    if (getMember(ctx, *pbr, "baseColorTexture", pe)) ctx.warn("baseColor textures are ignored; using baseColorFactor");
  }
  m.baseColor = baseColor;
  m.alpha = static_cast<float>(roughness * roughness);
  m.distribution = parseMicrofacet(ctx, o, element);

  Color emissive = toColor(getNumbers(ctx, o, "emissiveFactor", element, 3, {0, 0, 0}, 0.0, 1.0));
  double strength = 1.0, transmission = 0.0, ior = 1.5;
  const Json* extensions = getObject(ctx, o, "extensions", element);
  if (extensions) {
    const std::string ee = element + ".extensions";
    if (const Json* e = getObject(ctx, *extensions, "KHR_materials_emissive_strength", ee))
      strength = getNumber(ctx, *e, "emissiveStrength", ee + ".KHR_materials_emissive_strength", 1.0, 0.0, INFINITY);
    if (const Json* e = getObject(ctx, *extensions, "KHR_materials_transmission", ee))
      transmission = getNumber(ctx, *e, "transmissionFactor", ee + ".KHR_materials_transmission", 0.0, 0.0, 1.0);
    if (const Json* e = getObject(ctx, *extensions, "KHR_materials_ior", ee)) {
      ior = getNumber(ctx, *e, "ior", ee + ".KHR_materials_ior", 1.5, 0.0, INFINITY);
      // KHR_materials_ior allows exactly 0 or values >= 1.
      if (ior != 0.0 && ior < 1.0)
        ctx.fail(ee + ".KHR_materials_ior", "ior " + brief(Json(ior)) + " must be 0 or at least 1");
    }
  }
  m.emission = emissive * static_cast<float>(strength);

  // Metal wins over transmission: glTF mixes the metal BRDF in with weight metallicFactor, so a
  // metallic surface transmits nothing (KHR_materials_transmission, "Metallic surfaces").
  if (metallic >= 0.5) {
    m.kind = MaterialKind::Conductor;
  } else if (transmission > 0.0) {
    if (ior == 0.0)
      ctx.fail(element + ".extensions.KHR_materials_ior", "ior 0 is not supported for transmissive materials");
    m.kind = MaterialKind::Dielectric;
    m.ior = static_cast<float>(ior);
  } else {
    m.kind = MaterialKind::Lambert;
  }
  return m;
}

}  // namespace

std::vector<Material> parseMaterials(Context& ctx, const Json& doc) {
  std::vector<Material> materials(arraySize(ctx, doc, "materials"));
  for (size_t i = 0; i < materials.size(); ++i)
    materials[i] = parseMaterial(ctx, arrayObject(ctx, doc, "materials", i), indexed("materials", i));
  return materials;
}

Material defaultMaterial() {
  Material m;
  m.name = "default";
  m.kind = MaterialKind::Lambert;
  m.baseColor = Color(0.8f);
  return m;
}

}  // namespace relt::gltf
