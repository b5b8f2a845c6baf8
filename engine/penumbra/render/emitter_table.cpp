#include "penumbra/render/emitter_table.h"

#include "penumbra/render/gpu_vectors.h"
#include "penumbra/render/scene_textures.h"

namespace penumbra::render {

EmitterSource emitterSource(const scene::Scene& scene, const scene::Instance& instance) {
  const auto& mesh = scene.meshes[instance.mesh];
  const auto& material = scene.materials[mesh.material];
  EmitterSource source;
  source.objectToWorld = instance.transform;
  source.mirrored = glm::determinant(glm::dmat3(instance.transform)) < 0.0;
  const bool textured = material.emissiveTexture != scene::Material::kNoTexture;
  const scene::TextureRef* emissionRef =
      textured ? &scene.textureRefs[material.emissiveTexture] : nullptr;
  const glm::vec3 meanEmission =
      textured ? material.emission * meanLinearColor(scene.textures[emissionRef->texture])
               : material.emission;
  source.luminance = 0.2126 * meanEmission.x + 0.7152 * meanEmission.y + 0.0722 * meanEmission.z;
  source.emission = material.emission;
  source.emissionTexture = textured ? material.emissiveTexture : PT_NO_TEXTURE;
  const auto& uvSet = emissionRef && emissionRef->texCoord == 1 ? mesh.uv1 : mesh.uv0;
  for (uint32_t vertex : mesh.indices) {
    source.positions.push_back(mesh.positions[vertex]);
    source.uvs.push_back(uvSet.empty() ? glm::vec2(0.0f) : uvSet[vertex]);
  }
  return source;
}

EmitterTable placeEmitters(const std::vector<EmitterSource>& sources,
                           const glm::dmat4& toRenderSpace) {
  EmitterTable table;
  auto& emissive = table.triangles;
  std::vector<double> power;
  for (const EmitterSource& source : sources) {
    const glm::dmat4 objectToRender = toRenderSpace * source.objectToWorld;
    for (size_t t = 0; t + 2 < source.positions.size(); t += 3) {
      glm::vec3 p[3];
      glm::vec2 uv[3];
      for (size_t k = 0; k < 3; ++k) {
        p[k] = glm::vec3(objectToRender * glm::dvec4(glm::dvec3(source.positions[t + k]), 1.0));
        uv[k] = source.uvs[t + k];
      }
      // A mirroring transform reverses the winding of the placed corners;
      // swapping two keeps the emitting side the mesh's front.
      if (source.mirrored) {
        std::swap(p[1], p[2]);
        std::swap(uv[1], uv[2]);
      }
      const float area = 0.5f * glm::length(glm::cross(p[1] - p[0], p[2] - p[0]));
      gpu::EmissiveTriangle& tri = emissive.emplace_back();
      tri.p0 = toFloat3(p[0]);
      tri.p1 = toFloat3(p[1]);
      tri.area = area;
      tri.p2 = toFloat3(p[2]);
      tri.emissionTexture = source.emissionTexture;
      tri.radiance = toFloat3(source.emission);
      tri.uv0 = toFloat2(uv[0]);
      tri.uv1 = toFloat2(uv[1]);
      tri.uv2 = toFloat2(uv[2]);
      power.push_back(area > 0.0f ? area * source.luminance : 0.0);
    }
  }
  double totalPower = 0;
  for (double p : power) totalPower += p;
  double cumulative = 0;
  for (size_t i = 0; i < emissive.size(); ++i) {
    const double pmf = totalPower > 0 ? power[i] / totalPower : 0.0;
    cumulative += pmf;
    emissive[i].probability = float(pmf);
    emissive[i].cumulativeProbability = float(cumulative);
  }
  if (!emissive.empty() && totalPower > 0) {
    for (size_t i = emissive.size(); i-- > 0;) {
      if (emissive[i].probability > 0) {
        emissive[i].cumulativeProbability = 1.0f;
        for (size_t j = i + 1; j < emissive.size(); ++j) emissive[j].cumulativeProbability = 1.0f;
        break;
      }
    }
  }
  table.sampledCount = totalPower > 0 ? uint32_t(emissive.size()) : 0;
  return table;
}

}  // namespace penumbra::render
