#include "penumbra/render/gpu_scene.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>
#include <map>
#include <tuple>

#include "path_tracer_shared.h"
#include "penumbra/render/effect_set.h"
#include "penumbra/render/emitter_table.h"
#include "penumbra/render/environment_map.h"
#include "penumbra/render/gpu_vectors.h"
#include "penumbra/render/scene_textures.h"
#include "penumbra/render/sheen_albedo_table.h"
#include "penumbra/util/error.h"

namespace penumbra::render {
namespace {

template <class Matrix>  // glm::mat4 or glm::dmat4
rhi::rt::AffineTransform toAffine(const Matrix& m) {
  rhi::rt::AffineTransform t{};
  for (int row = 0; row < 3; ++row)
    for (int col = 0; col < 4; ++col) t[row * 4 + col] = float(m[col][row]);  // glm is column-major
  return t;
}

// InstanceData for a mesh instance: the TLAS transform and its inverse (in
// double, so the inverse is as exact as float storage allows), as rows.
void placeInstance(gpu::InstanceData& d, const glm::dmat4& objectToWorld) {
  const glm::dmat4 inverse = glm::inverse(objectToWorld);
  gpu::float4* forward[3] = {&d.objectToWorld0, &d.objectToWorld1, &d.objectToWorld2};
  gpu::float4* backward[3] = {&d.worldToObject0, &d.worldToObject1, &d.worldToObject2};
  for (int row = 0; row < 3; ++row) {  // glm is column-major: m[column][row]
    *forward[row] = {float(objectToWorld[0][row]), float(objectToWorld[1][row]),
                     float(objectToWorld[2][row]), float(objectToWorld[3][row])};
    *backward[row] = {float(inverse[0][row]), float(inverse[1][row]), float(inverse[2][row]),
                      float(inverse[3][row])};
  }
}

gpu::InstanceData instanceData(uint32_t firstIndex, uint32_t firstVertex, uint32_t material,
                               uint32_t firstEmissiveTriangle, const glm::dmat4& objectToWorld) {
  gpu::InstanceData d{};
  d.firstIndex = firstIndex;
  d.firstVertex = firstVertex;
  d.materialIndex = material;
  d.firstEmissiveTriangle = firstEmissiveTriangle;
  placeInstance(d, objectToWorld);
  return d;
}

// The order of the instances on the GPU (InstanceData, TLAS instance IDs):
// first the merge groups, each a run of instances whose meshes are drawn
// once and lie in one cell of a 64 m grid, which share one BLAS (one
// geometry each, its transform applied when the BLAS is built, about the
// group's centre); then every other instance, one TLAS instance each over
// its mesh's BLAS. A TLAS instance costs traversal a ray transform and a
// second hierarchy; most scenes draw most meshes once (the Cornell box: 8
// instances, one BLAS). Instanced meshes keep their own BLAS so their
// triangles are stored once. A group's floats are precise to its extent
// (about 8 um within two cells), so a mesh larger than a cell, or far from
// the others, is not merged: a 0.1 mm part keeps its precision beside a
// 10 km terrain.
struct MergeGroup {
  uint32_t first = 0, count = 0;  // GPU instance indices
  glm::dvec3 centre{0.0};         // of the group's world bounds: its BLAS's origin
};

struct MeshInstanceOrder {
  std::vector<uint32_t> sceneInstance;  // GPU instance index -> scene instance index
  std::vector<MergeGroup> groups;
  uint32_t merged = 0;  // the first `merged` GPU instances are in groups
};

MeshInstanceOrder meshInstanceOrder(const scene::Scene& scene) {
  constexpr double kCell = 64.0;
  std::vector<uint32_t> uses(scene.meshes.size(), 0);
  for (const auto& inst : scene.instances) ++uses[inst.mesh];
  struct Bounds {
    glm::dvec3 lo{std::numeric_limits<double>::max()}, hi{-std::numeric_limits<double>::max()};
  };
  struct Cell {
    std::vector<uint32_t> members;  // scene instance indices
    Bounds bounds;
  };
  std::map<std::tuple<int64_t, int64_t, int64_t>, Cell> cells;
  std::vector<bool> grouped(scene.instances.size(), false);
  for (uint32_t i = 0; i < scene.instances.size(); ++i) {
    const auto& inst = scene.instances[i];
    if (uses[inst.mesh] != 1 || scene.meshes[inst.mesh].positions.empty()) continue;
    Bounds b;
    for (const glm::vec3& p : scene.meshes[inst.mesh].positions) {
      const glm::dvec3 w(inst.transform * glm::dvec4(glm::dvec3(p), 1.0));
      b.lo = glm::min(b.lo, w);
      b.hi = glm::max(b.hi, w);
    }
    const glm::dvec3 extent = b.hi - b.lo;
    if (std::max({extent.x, extent.y, extent.z}) > kCell) continue;
    const glm::dvec3 cell = glm::floor(0.5 * (b.lo + b.hi) / kCell);
    const auto key = std::make_tuple(int64_t(cell.x), int64_t(cell.y), int64_t(cell.z));
    Cell& c = cells[key];
    c.members.push_back(i);
    c.bounds.lo = glm::min(c.bounds.lo, b.lo);
    c.bounds.hi = glm::max(c.bounds.hi, b.hi);
    grouped[i] = true;
  }
  MeshInstanceOrder order;
  for (const auto& [key, c] : cells) {
    order.groups.push_back({uint32_t(order.sceneInstance.size()), uint32_t(c.members.size()),
                            0.5 * (c.bounds.lo + c.bounds.hi)});
    order.sceneInstance.insert(order.sceneInstance.end(), c.members.begin(), c.members.end());
  }
  order.merged = uint32_t(order.sceneInstance.size());
  for (uint32_t i = 0; i < scene.instances.size(); ++i)
    if (!grouped[i]) order.sceneInstance.push_back(i);
  return order;
}

template <class T>
rhi::BufferHandle makeStorageBuffer(rhi::IDevice& device, const std::vector<T>& data,
                                    rhi::BufferUsage extra, const char* name) {
  rhi::BufferDesc desc;
  // At least one element: an empty structured buffer has no valid view.
  desc.byteSize = std::max<uint64_t>(data.size(), 1) * sizeof(T);
  desc.usage = rhi::BufferUsage::StorageBuffer | extra;
  desc.debugName = name;
  return device.createBuffer(desc);
}

// Render space's origin for a camera at `position`: the nearest point of a
// 64 m grid. Within 64 m, floats resolve 4 um (the Cornell box's light hangs
// 100 um under its ceiling); on a grid, cameras that move a little keep the
// origin and render exactly what they rendered, and a scene near the world's
// origin renders in world space.
constexpr double kRenderOriginGrid = 64.0;

gpu::PointLight packPointLight(const scene::PointLight& l, const glm::dvec3& renderOrigin) {
  gpu::PointLight p{};
  const bool directional = l.type == scene::LightType::Directional;
  const bool spot = l.type == scene::LightType::Spot;
  p.position = toFloat3(directional ? glm::vec3(0.0f) : glm::vec3(l.position - renderOrigin));
  p.cosInner =
      directional && l.angularRadiusDegrees <= 0.0f
          ? 1.0f
          : std::cos(glm::radians(directional ? l.angularRadiusDegrees
                                              : std::min(l.innerConeDegrees, l.outerConeDegrees)));
  p.intensity = toFloat3(l.intensity);
  p.range = directional ? 0.0f : l.range;
  p.direction = toFloat3(glm::normalize(l.direction));
  p.cosOuter = spot ? std::cos(glm::radians(l.outerConeDegrees)) : 0.0f;
  p.type = directional ? PT_LIGHT_DIRECTIONAL : spot ? PT_LIGHT_SPOT : PT_LIGHT_POINT;
  return p;
}

// The whole of `values` into `buffer`; nothing for an empty list.
template <class T>
void writeAll(rhi::ICommandList& cmd, const rhi::BufferHandle& buffer,
              const std::vector<T>& values) {
  if (!values.empty()) cmd.writeBuffer(buffer.get(), values.data(), values.size() * sizeof(T));
}

}  // namespace

glm::dvec3 renderOriginNear(const glm::dvec3& position) {
  return glm::round(position / kRenderOriginGrid) * kRenderOriginGrid;
}

gpu::MaterialData packMaterial(const scene::Material& m) {
  gpu::MaterialData d{};
  d.baseColor = toFloat3(m.baseColor);
  d.emission = toFloat3(m.emission);
  d.metallic = m.metallic;
  d.roughness = m.roughness;
  d.anisotropic = m.anisotropic;
  d.specular = m.specular;
  d.specularTint = m.specularTint;
  d.specularColor = toFloat3(m.specularColor);
  d.specularF90 = m.model == scene::MaterialModel::Phong ? 1.0f : m.specularF90;
  d.sheen = m.sheen;
  d.sheenTint = m.sheenTint;
  d.sheenColor = toFloat3(m.sheenColor);
  d.sheenRoughness = m.sheenRoughness;
  d.clearcoat = m.clearcoat;
  d.clearcoatGloss = m.clearcoatGloss;
  d.specTrans = m.specTrans;
  d.ior = m.ior;
  d.subsurface = m.subsurface;
  d.ks = m.ks;
  d.phongExponent = m.exponent;
  d.reflectivity = m.reflectivity;
  d.transparency = m.transparency;
  d.model = m.model == scene::MaterialModel::Phong   ? MATERIAL_MODEL_PHONG
            : m.model == scene::MaterialModel::Unlit ? MATERIAL_MODEL_UNLIT
                                                     : MATERIAL_MODEL_DISNEY;
  d.flags = 0;
  if (m.thin) d.flags |= MATERIAL_FLAG_THIN;
  if (m.model == scene::MaterialModel::Lambert)
    d.flags |= MATERIAL_FLAG_LAMBERT_DIFFUSE | MATERIAL_FLAG_GGX_COAT | MATERIAL_FLAG_CHARLIE_SHEEN;
  d.baseColorTexture = m.baseColorTexture;
  d.metallicRoughnessTexture = m.metallicRoughnessTexture;
  d.normalTexture = m.normalTexture;
  d.emissionTexture = m.emissiveTexture;
  d.occlusionTexture = m.occlusionTexture;
  d.clearcoatTexture = m.clearcoatTexture;
  d.clearcoatRoughnessTexture = m.clearcoatRoughnessTexture;
  d.transmissionTexture = m.transmissionTexture;
  d.sheenColorTexture = m.sheenColorTexture;
  d.sheenRoughnessTexture = m.sheenRoughnessTexture;
  d.specularTexture = m.specularTexture;
  d.specularColorTexture = m.specularColorTexture;
  d.anisotropyTexture = m.anisotropyTexture;
  d.clearcoatNormalTexture = m.clearcoatNormalTexture;
  d.clearcoatNormalScale = m.clearcoatNormalScale;
  // Phong has no diffuse lobe to share (the effect bit is not derived for it).
  d.diffuseTransmission = m.model == scene::MaterialModel::Phong ? 0.0f : m.diffuseTransmission;
  d.diffuseTransmissionColor = toFloat3(m.diffuseTransmissionColor);
  d.diffuseTransmissionTexture = m.diffuseTransmissionTexture;
  d.diffuseTransmissionColorTexture = m.diffuseTransmissionColorTexture;
  // Phong has no specular layer of its own to colour (no effect bit either).
  d.iridescence = m.model == scene::MaterialModel::Phong ? 0.0f : m.iridescence;
  d.iridescenceIor = m.iridescenceIor;
  d.iridescenceThickness = {m.iridescenceThicknessMinimum, m.iridescenceThicknessMaximum};
  d.iridescenceTexture = m.iridescenceTexture;
  d.iridescenceThicknessTexture = m.iridescenceThicknessTexture;
  d.dispersion = m.model == scene::MaterialModel::Phong ? 0.0f : m.dispersion;
  // Only the Disney lobes have it: a Phong material mapped onto Disney in
  // the path tracer (material.hlsli) has no tangent frame to stretch along,
  // and the effect bit that holds the code is not derived for Phong.
  d.anisotropyStrength = m.model == scene::MaterialModel::Phong ? 0.0f : m.anisotropyStrength;
  d.anisotropyDirection = {std::cos(m.anisotropyRotation), std::sin(m.anisotropyRotation)};
  d.alphaMode = m.alphaMode == scene::AlphaMode::Mask    ? MATERIAL_ALPHA_MASK
                : m.alphaMode == scene::AlphaMode::Blend ? MATERIAL_ALPHA_BLEND
                                                         : MATERIAL_ALPHA_OPAQUE;
  d.normalScale = m.normalScale;
  d.occlusionStrength = m.occlusionStrength;
  d.alpha = m.alpha;
  d.alphaCutoff = m.alphaCutoff;
  // sigma = -ln(colour) / distance, so exp(-sigma distance) = colour; a
  // black colour absorbs everything within a millionth of the distance.
  glm::vec3 sigma(0.0f);
  if (std::isfinite(m.attenuationDistance) && !m.thin)
    for (int k = 0; k < 3; ++k)
      sigma[k] = -std::log(std::max(m.attenuationColor[k], 1e-6f)) / m.attenuationDistance;
  d.absorption = toFloat3(sigma);
  return d;
}

struct GpuScene::Buffers {
  rhi::BufferHandle vertices, indices, instances, materials, emissive, pointLights;
  rhi::BufferHandle normals, tangents, texcoords, colors;
  SceneTextures textures;
  rhi::BufferHandle textureRefs;
  rhi::BufferHandle environmentInfo, environmentTexels, environmentCdf;
  rhi::BufferHandle sheenAlbedo;  // the glTF sheen's albedo table, the same for every scene
  std::vector<rhi::rt::AccelStructHandle> mergedBottomLevels;  // one per MergeGroup
  rhi::BufferHandle
      mergedTransforms;  // their geometries' transforms, 3x4 rows, in GPU instance order
  std::vector<rhi::rt::AccelStructHandle> bottomLevels;  // per instanced mesh; null for the others
  rhi::rt::AccelStructHandle topLevel;
  rhi::BufferHandle implicits, implicitAabbs;
  std::vector<rhi::rt::AccelStructHandle> implicitBottomLevels;  // one per family present
  std::vector<ImplicitFamily> implicitFamilies;                  // hit group 1 + i is family i's
};

// What of the scene depends on where render space's origin is, kept in world
// space (double) so that rebase() can place it again about another origin
// without the scene: everything but the meshes' BLASes, which are in object
// space (or about their merge group's centre).
struct GpuScene::WorldPlacement {
  std::vector<gpu::InstanceData> instances;  // as uploaded: mesh instances, then implicit objects
  std::vector<glm::dmat4> meshInstanceToWorld;  // object to world of instances[i], i < their count
  std::vector<EmitterSource> emitters;
  std::vector<scene::PointLight> pointLights;
  std::vector<scene::ImplicitObject> implicits;
  uint32_t firstImplicitInstance = 0;
  // The TLAS: the meshes' instances first (placed by meshTlasInstanceToWorld),
  // then one per implicit family (identity: their objects carry their own
  // transforms, and their AABBs are in render space).
  std::vector<rhi::rt::InstanceDesc> tlasInstances;
  std::vector<glm::dmat4> meshTlasInstanceToWorld;
};

GpuScene::GpuScene(rhi::IDevice& device, const scene::Scene& scene, const glm::dvec3& renderOrigin,
                   bool allImplicitFamilies)
    : device_(device),
      renderOrigin_(renderOrigin),
      commandList_(device.createCommandList("scene upload")) {
  upload(scene, allImplicitFamilies);
}

GpuScene::~GpuScene() = default;

const std::vector<ImplicitFamily>& GpuScene::implicitFamilies() const {
  return buffers_->implicitFamilies;
}

glm::dmat4 GpuScene::worldToRenderSpace() const {
  return glm::translate(glm::dmat4(1.0), -renderOrigin_);
}

// Where each mesh lies in the shared vertex and index buffers, and the GPU
// order of the mesh instances.
struct GpuScene::MeshLayout {
  std::vector<gpu::float4> vertices;
  std::vector<uint32_t> indices;
  std::vector<uint32_t> firstVertex, firstIndex;  // per mesh
  // Vertex attributes parallel to `vertices`; zero where a mesh has none,
  // which the closest-hit shader reads as "none".
  std::vector<gpu::float4> normals, tangents, texcoords;
  // COLOR_0 parallel to `vertices` when any mesh has vertex colours (one
  // element otherwise: a scene without them keeps no buffer for them).
  std::vector<gpu::float4> colors;
  MeshInstanceOrder order;
};

uint64_t GpuScene::uploadBytes(const scene::Scene& scene) {
  uint64_t vertices = 0, indices = 0;
  bool colors = false;
  for (const auto& mesh : scene.meshes) {
    vertices += mesh.positions.size();
    indices += mesh.indices.size();
    colors = colors || !mesh.colors.empty();
  }
  // Positions, normals, tangents, texture coordinates (and colours): a
  // float4 each, as packMeshes lays them out.
  const uint64_t perVertex = (colors ? 5 : 4) * sizeof(gpu::float4);
  return vertices * perVertex + indices * sizeof(uint32_t);
}

// Every mesh's vertices, attributes and indices, back to back in shared
// buffers.
GpuScene::MeshLayout GpuScene::packMeshes(const scene::Scene& scene) {
  MeshLayout l;
  const bool anyColors = std::any_of(scene.meshes.begin(), scene.meshes.end(),
                                     [](const scene::Mesh& m) { return !m.colors.empty(); });
  for (const auto& mesh : scene.meshes) {
    l.firstVertex.push_back(uint32_t(l.vertices.size()));
    l.firstIndex.push_back(uint32_t(l.indices.size()));
    for (size_t v = 0; v < mesh.positions.size(); ++v) {
      l.vertices.push_back(toFloat4(mesh.positions[v], 1.0f));
      l.normals.push_back(mesh.normals.empty() ? gpu::float4{} : toFloat4(mesh.normals[v]));
      const glm::vec4 t = mesh.tangents.empty() ? glm::vec4(0.0f) : mesh.tangents[v];
      l.tangents.push_back({t.x, t.y, t.z, t.w});
      const glm::vec2 uv0 = mesh.uv0.empty() ? glm::vec2(0.0f) : mesh.uv0[v];
      const glm::vec2 uv1 = mesh.uv1.empty() ? glm::vec2(0.0f) : mesh.uv1[v];
      l.texcoords.push_back({uv0.x, uv0.y, uv1.x, uv1.y});
      if (anyColors)
        l.colors.push_back(mesh.colors.empty() ? toFloat4(glm::vec4(1.0f))
                                               : toFloat4(mesh.colors[v]));
    }
    l.indices.insert(l.indices.end(), mesh.indices.begin(), mesh.indices.end());
  }
  if (l.colors.empty()) l.colors.push_back(toFloat4(glm::vec4(1.0f)));
  return l;
}

// The instances as the GPU sees them, in GPU order (meshes, then implicit
// objects), and the emitters' sources for the emitter table.
std::vector<gpu::InstanceData> GpuScene::placeInstances(const scene::Scene& scene,
                                                        const MeshLayout& layout) {
  // Everything the GPU sees is placed relative to renderOrigin_ (the camera's
  // position when the scene was uploaded), in double until then: the render
  // space, where floats are precise near the camera wherever the scene is.
  const glm::dmat4 toRenderSpace = worldToRenderSpace();
  // Emitters: render-space triangles of every instance of an emissive mesh,
  // chosen for NEE in proportion to power (area x luminance).
  std::vector<gpu::InstanceData> instances;
  uint32_t emissiveTriangles = 0;
  for (uint32_t sceneIndex : layout.order.sceneInstance) {
    const auto& inst = scene.instances[sceneIndex];
    const auto& mesh = scene.meshes[inst.mesh];
    const auto& material = scene.materials[mesh.material];
    const glm::dmat4 objectToRender = toRenderSpace * inst.transform;
    gpu::InstanceData data =
        instanceData(layout.firstIndex[inst.mesh], layout.firstVertex[inst.mesh], mesh.material,
                     PT_NO_EMISSION, objectToRender);
    data.vertexAttributes = (mesh.normals.empty() ? 0u : PT_VERTEX_NORMALS) |
                            (mesh.tangents.empty() ? 0u : PT_VERTEX_TANGENTS) |
                            (mesh.uv0.empty() && mesh.uv1.empty() ? 0u : PT_VERTEX_TEXCOORDS) |
                            (mesh.colors.empty() ? 0u : PT_VERTEX_COLORS);
    if (material.isEmissive()) {
      data.firstEmissiveTriangle = emissiveTriangles;
      emissiveTriangles += uint32_t(mesh.indices.size() / 3);
      placement_->emitters.push_back(emitterSource(scene, inst));
    }
    placement_->meshInstanceToWorld.push_back(inst.transform);
    instances.push_back(data);
  }
  for (const auto& object : scene.implicits) {
    const bool emits = scene.materials[object.material].isEmissive();
    instances.push_back(instanceData(
        0, 0, object.material, emits ? PT_EMISSION_NOT_SAMPLED : PT_NO_EMISSION, glm::dmat4(1.0)));
  }
  return instances;
}

void GpuScene::upload(const scene::Scene& scene, bool allImplicitFamilies) {
  buffers_ = std::make_unique<Buffers>();
  placement_ = std::make_unique<WorldPlacement>();
  MeshLayout layout = packMeshes(scene);
  layout.order = meshInstanceOrder(scene);
  gpuToSceneInstance_ = layout.order.sceneInstance;

  std::vector<gpu::MaterialData> materials;
  for (const auto& m : scene.materials) materials.push_back(packMaterial(m));
  placement_->pointLights = scene.pointLights;
  std::vector<gpu::PointLight> pointLights;
  for (const auto& l : scene.pointLights) pointLights.push_back(packPointLight(l, renderOrigin_));
  pointLightCount_ = uint32_t(pointLights.size());

  const std::vector<gpu::InstanceData> instances = placeInstances(scene, layout);
  placement_->instances = instances;
  const EmitterTable emitterTable = placeEmitters(placement_->emitters, worldToRenderSpace());
  const std::vector<gpu::EmissiveTriangle>& emissive = emitterTable.triangles;
  emissiveTriangleCount_ = emitterTable.sampledCount;

  using rhi::BufferUsage;
  auto& s = *buffers_;
  const auto& vertices = layout.vertices;
  const auto& indices = layout.indices;
  const auto& normals = layout.normals;
  const auto& tangents = layout.tangents;
  const auto& texcoords = layout.texcoords;
  const auto& colors = layout.colors;
  s.vertices = makeStorageBuffer(device_, vertices, BufferUsage::AccelStructBuildInput, "vertices");
  s.indices = makeStorageBuffer(device_, indices, BufferUsage::AccelStructBuildInput, "indices");
  s.instances = makeStorageBuffer(device_, instances, BufferUsage::None, "instances");
  s.materials = makeStorageBuffer(device_, materials, BufferUsage::None, "materials");
  s.emissive = makeStorageBuffer(device_, emissive, BufferUsage::None, "emissive triangles");
  s.pointLights = makeStorageBuffer(device_, pointLights, BufferUsage::None, "point lights");
  s.normals = makeStorageBuffer(device_, normals, BufferUsage::None, "vertex normals");
  s.tangents = makeStorageBuffer(device_, tangents, BufferUsage::None, "vertex tangents");
  s.texcoords = makeStorageBuffer(device_, texcoords, BufferUsage::None, "vertex texcoords");
  s.colors = makeStorageBuffer(device_, colors, BufferUsage::None, "vertex colours");

  auto* cmd = commandList_.get();
  cmd->open();
  if (!vertices.empty()) {
    cmd->writeBuffer(s.vertices.get(), vertices.data(), vertices.size() * sizeof(gpu::float4));
    cmd->writeBuffer(s.normals.get(), normals.data(), normals.size() * sizeof(gpu::float4));
    cmd->writeBuffer(s.tangents.get(), tangents.data(), tangents.size() * sizeof(gpu::float4));
    cmd->writeBuffer(s.texcoords.get(), texcoords.data(), texcoords.size() * sizeof(gpu::float4));
  }
  writeAll(*cmd, s.colors, colors);
  if (!indices.empty())
    cmd->writeBuffer(s.indices.get(), indices.data(), indices.size() * sizeof(uint32_t));
  writeAll(*cmd, s.instances, instances);
  writeAll(*cmd, s.materials, materials);
  writeAll(*cmd, s.emissive, emissive);
  writeAll(*cmd, s.pointLights, pointLights);
  s.textures = uploadSceneTextures(device_, *cmd, scene);
  s.textureRefs = makeStorageBuffer(device_, s.textures.refs, BufferUsage::None, "texture refs");
  cmd->writeBuffer(s.textureRefs.get(), s.textures.refs.data(),
                   s.textures.refs.size() * sizeof(gpu::TextureRefData));
  static_assert(kSheenAlbedoSize == PT_SHEEN_ALBEDO_SIZE);
  const std::vector<float> sheenAlbedo(kSheenAlbedo.begin(), kSheenAlbedo.end());
  s.sheenAlbedo = makeStorageBuffer(device_, sheenAlbedo, BufferUsage::None, "sheen albedo");
  writeAll(*cmd, s.sheenAlbedo, sheenAlbedo);

  // The builds go in a list of their own, after the uploads, so that GPU
  // timestamps around them time the builds alone (accelStructBuildTimes).
  cmd->close();
  device_.submit(cmd);
  device_.waitForIdle();
  uploadEnvironment(scene.environment);
  buildAccelStructs(scene, layout, allImplicitFamilies);
}

// The acceleration structures: merged and per-mesh BLASes, the implicit
// families', the TLAS; their builds timed alone (accelStructBuildTimes).
void GpuScene::buildAccelStructs(const scene::Scene& scene, const MeshLayout& layout,
                                 bool allImplicitFamilies) {
  auto& s = *buffers_;
  auto* cmd = commandList_.get();
  const glm::dmat4 toRenderSpace = worldToRenderSpace();
  using rhi::BufferUsage;
  cmd->open();
  rhi::TimerQueryHandle bottomLevelTimer = device_.createTimerQuery();
  rhi::TimerQueryHandle topLevelTimer = device_.createTimerQuery();
  cmd->beginTimerQuery(bottomLevelTimer.get());

  // Alpha-masked meshes are the only non-opaque geometry: the any-hit
  // shader runs for them alone. Each texel is one hit or none, so duplicate
  // any-hit calls could not change a result, but they cost time.
  auto meshGeometry = [&](uint32_t m) {
    rhi::rt::GeometryDesc geo;
    geo.type = rhi::rt::GeometryType::Triangles;
    geo.flags =
        alphaMasked(scene.materials[scene.meshes[m].material], hasVertexAlpha(scene.meshes[m]))
            ? rhi::rt::GeometryFlags::NoDuplicateAnyHitInvocation
            : rhi::rt::GeometryFlags::Opaque;
    geo.triangles.vertexBuffer = s.vertices.get();
    geo.triangles.vertexOffset = uint64_t(layout.firstVertex[m]) * sizeof(gpu::float4);
    geo.triangles.vertexStride = sizeof(gpu::float4);
    geo.triangles.vertexCount = uint32_t(scene.meshes[m].positions.size());
    geo.triangles.indexBuffer = s.indices.get();
    geo.triangles.indexOffset = uint64_t(layout.firstIndex[m]) * sizeof(uint32_t);
    geo.triangles.indexCount = uint32_t(scene.meshes[m].indices.size());
    return geo;
  };
  std::vector<rhi::rt::InstanceDesc> tlasInstances;
  std::vector<rhi::rt::AffineTransform> transforms;  // every group's geometries, in GPU order
  for (const MergeGroup& group : layout.order.groups)
    for (uint32_t k = group.first; k < group.first + group.count; ++k)
      transforms.push_back(toAffine(glm::translate(glm::dmat4(1.0), -group.centre) *
                                    scene.instances[layout.order.sceneInstance[k]].transform));
  s.mergedTransforms = makeStorageBuffer(device_, transforms, BufferUsage::AccelStructBuildInput,
                                         "merged BLAS transforms");
  if (!transforms.empty())
    cmd->writeBuffer(s.mergedTransforms.get(), transforms.data(),
                     transforms.size() * sizeof(transforms[0]));
  for (const MergeGroup& group : layout.order.groups) {
    rhi::rt::AccelStructDesc blas;
    blas.debugName = fmt::format("BLAS of {} meshes drawn once", group.count);
    for (uint32_t k = group.first; k < group.first + group.count; ++k) {
      rhi::rt::GeometryDesc geo = meshGeometry(scene.instances[layout.order.sceneInstance[k]].mesh);
      geo.triangles.transformBuffer = s.mergedTransforms.get();
      geo.triangles.transformOffset = k * sizeof(rhi::rt::AffineTransform);
      blas.bottomLevelGeometries.push_back(geo);
    }
    s.mergedBottomLevels.push_back(device_.createAccelStruct(blas));
    cmd->buildBottomLevelAccelStruct(s.mergedBottomLevels.back().get());
    rhi::rt::InstanceDesc d;
    placement_->meshTlasInstanceToWorld.push_back(glm::translate(glm::dmat4(1.0), group.centre));
    d.transform = toAffine(toRenderSpace * placement_->meshTlasInstanceToWorld.back());
    d.instanceID = group.first;  // + geometry index: the GPU instance (triangle.rchit)
    d.flags = rhi::rt::InstanceTriangleCullDisable;
    d.bottomLevelAddress = s.mergedBottomLevels.back()->deviceAddress();
    tlasInstances.push_back(d);
  }
  s.bottomLevels.resize(scene.meshes.size());
  for (uint32_t gpuIndex = layout.order.merged; gpuIndex < layout.order.sceneInstance.size();
       ++gpuIndex) {
    const auto& inst = scene.instances[layout.order.sceneInstance[gpuIndex]];
    auto& bottomLevel = s.bottomLevels[inst.mesh];
    if (!bottomLevel) {
      rhi::rt::AccelStructDesc blas;
      blas.debugName = "BLAS " + scene.meshes[inst.mesh].name;
      blas.bottomLevelGeometries.push_back(meshGeometry(inst.mesh));
      bottomLevel = device_.createAccelStruct(blas);
      cmd->buildBottomLevelAccelStruct(bottomLevel.get());
    }
    rhi::rt::InstanceDesc d;
    placement_->meshTlasInstanceToWorld.push_back(inst.transform);
    d.transform = toAffine(toRenderSpace * inst.transform);
    d.instanceID = gpuIndex;
    d.flags = rhi::rt::InstanceTriangleCullDisable;
    d.bottomLevelAddress = bottomLevel->deviceAddress();
    tlasInstances.push_back(d);
  }
  uploadImplicits(scene, allImplicitFamilies, tlasInstances);
  placement_->tlasInstances = tlasInstances;
  cmd->endTimerQuery(bottomLevelTimer.get());
  rhi::rt::AccelStructDesc tlas;
  tlas.isTopLevel = true;
  tlas.topLevelMaxInstances = uint32_t(tlasInstances.size());
  tlas.debugName = "TLAS " + scene.name;
  s.topLevel = device_.createAccelStruct(tlas);
  cmd->beginTimerQuery(topLevelTimer.get());
  cmd->buildTopLevelAccelStruct(s.topLevel.get(), tlasInstances.data(),
                                uint32_t(tlasInstances.size()));
  cmd->endTimerQuery(topLevelTimer.get());
  cmd->close();
  device_.submit(cmd);
  device_.waitForIdle();
  buildTimes_.bottomLevelSeconds = device_.timerQuerySeconds(bottomLevelTimer.get());
  buildTimes_.topLevelSeconds = device_.timerQuerySeconds(topLevelTimer.get());
}

// Records the open command list's BLAS builds; appends one TLAS instance per
// implicit family present (implicit_geometry.h).
void GpuScene::uploadImplicits(const scene::Scene& scene, bool allImplicitFamilies,
                               std::vector<rhi::rt::InstanceDesc>& tlasInstances) {
  auto& s = *buffers_;
  placement_->implicits = scene.implicits;
  placement_->firstImplicitInstance = uint32_t(scene.instances.size());
  const ImplicitLayout layout = implicitLayoutInRenderSpace();
  s.implicits = makeStorageBuffer(device_, layout.data, rhi::BufferUsage::None, "implicit objects");
  s.implicitAabbs = makeStorageBuffer(device_, layout.aabbs,
                                      rhi::BufferUsage::AccelStructBuildInput, "implicit AABBs");
  // The full pipeline holds every family's hit group, in enum order, whether
  // the scene uses it or not; a specialized one only the families present.
  if (allImplicitFamilies)
    for (uint32_t f = 0; f < kImplicitFamilyCount; ++f)
      s.implicitFamilies.push_back(ImplicitFamily(f));
  else
    for (const auto& range : layout.families) s.implicitFamilies.push_back(range.family);
  if (layout.data.empty()) return;
  auto* cmd = commandList_.get();
  cmd->writeBuffer(s.implicits.get(), layout.data.data(),
                   layout.data.size() * sizeof(gpu::ImplicitData));
  cmd->writeBuffer(s.implicitAabbs.get(), layout.aabbs.data(),
                   layout.aabbs.size() * sizeof(layout.aabbs[0]));
  for (const auto& range : layout.families) {
    rhi::rt::AccelStructDesc blas;
    blas.debugName = std::string("BLAS ") + implicitHitGroupName(range.family);
    rhi::rt::GeometryDesc geo;
    geo.type = rhi::rt::GeometryType::AABBs;
    geo.flags = rhi::rt::GeometryFlags::Opaque;
    geo.aabbs.buffer = s.implicitAabbs.get();
    geo.aabbs.offset = uint64_t(range.firstObject) * sizeof(layout.aabbs[0]);
    geo.aabbs.count = range.objectCount;
    geo.aabbs.stride = sizeof(layout.aabbs[0]);
    blas.bottomLevelGeometries.push_back(geo);
    s.implicitBottomLevels.push_back(device_.createAccelStruct(blas));
    cmd->buildBottomLevelAccelStruct(s.implicitBottomLevels.back().get());

    rhi::rt::InstanceDesc d;  // identity: each object's transform is in its ImplicitData
    d.instanceID = range.firstObject;
    d.instanceMask = 0xff;
    const auto slot = std::find(s.implicitFamilies.begin(), s.implicitFamilies.end(), range.family);
    d.instanceContributionToHitGroupIndex = 1 + uint32_t(slot - s.implicitFamilies.begin());
    d.bottomLevelAddress = s.implicitBottomLevels.back()->deviceAddress();
    tlasInstances.push_back(d);
  }
}

ImplicitLayout GpuScene::implicitLayoutInRenderSpace() const {
  std::vector<scene::ImplicitObject> objects = placement_->implicits;
  for (auto& object : objects) object.transform = worldToRenderSpace() * object.transform;
  return layoutImplicits(objects, placement_->firstImplicitInstance);
}

void GpuScene::rebase(const glm::dvec3& origin) {
  // Frames in flight still read the buffers and the TLAS rewritten here.
  device_.waitForIdle();
  renderOrigin_ = origin;
  const glm::dmat4 toRenderSpace = worldToRenderSpace();
  WorldPlacement& w = *placement_;
  // The same computations as upload's, so a rebased tracer renders
  // exactly what one built with its camera here would.
  std::vector<gpu::InstanceData> instances = w.instances;
  for (size_t i = 0; i < w.meshInstanceToWorld.size(); ++i)
    placeInstance(instances[i], toRenderSpace * w.meshInstanceToWorld[i]);
  const EmitterTable emitterTable = placeEmitters(w.emitters, toRenderSpace);
  const std::vector<gpu::EmissiveTriangle>& emissive = emitterTable.triangles;
  emissiveTriangleCount_ = emitterTable.sampledCount;
  std::vector<gpu::PointLight> pointLights;
  for (const auto& l : w.pointLights) pointLights.push_back(packPointLight(l, renderOrigin_));
  const ImplicitLayout implicits = implicitLayoutInRenderSpace();
  for (size_t i = 0; i < w.meshTlasInstanceToWorld.size(); ++i)
    w.tlasInstances[i].transform = toAffine(toRenderSpace * w.meshTlasInstanceToWorld[i]);

  auto& s = *buffers_;
  submitAndWait([&](rhi::ICommandList& cmd) {
    writeAll(cmd, s.instances, instances);
    writeAll(cmd, s.emissive, emissive);
    writeAll(cmd, s.pointLights, pointLights);
    writeAll(cmd, s.implicits, implicits.data);
    writeAll(cmd, s.implicitAabbs, implicits.aabbs);
    // In place: the binding sets keep pointing at the same TLAS, and the
    // meshes' BLASes are not touched.
    for (auto& bottomLevel : s.implicitBottomLevels)
      cmd.buildBottomLevelAccelStruct(bottomLevel.get());
    cmd.buildTopLevelAccelStruct(s.topLevel.get(), w.tlasInstances.data(),
                                 uint32_t(w.tlasInstances.size()));
  });
}

void GpuScene::submitAndWait(const std::function<void(rhi::ICommandList&)>& work) {
  auto* cmd = commandList_.get();
  cmd->open();
  work(*cmd);
  cmd->close();
  device_.submit(cmd);
  device_.waitForIdle();
}

void GpuScene::writeMaterials(const std::vector<scene::Material>& materials) {
  std::vector<gpu::MaterialData> packed;
  for (const auto& m : materials) packed.push_back(packMaterial(m));
  submitAndWait([&](rhi::ICommandList& cmd) { writeAll(cmd, buffers_->materials, packed); });
}

void GpuScene::uploadEnvironment(const scene::Environment& environment) {
  // Everything is built and written before anything is replaced: an
  // allocation that fails (a map too large for the device) leaves the
  // environment that was there, bound and whole.
  const EnvironmentTables tables = buildEnvironmentTables(environment);
  using rhi::BufferUsage;
  const std::vector<gpu::EnvironmentData> info = {tables.info};
  rhi::BufferHandle newInfo = makeStorageBuffer(device_, info, BufferUsage::None, "environment");
  rhi::BufferHandle newTexels =
      makeStorageBuffer(device_, tables.texels, BufferUsage::None, "environment texels");
  rhi::BufferHandle newCdf =
      makeStorageBuffer(device_, tables.cdf, BufferUsage::None, "environment CDF");
  submitAndWait([&](rhi::ICommandList& cmd) {
    writeAll(cmd, newInfo, info);
    writeAll(cmd, newTexels, tables.texels);
    writeAll(cmd, newCdf, tables.cdf);
  });
  auto& s = *buffers_;
  s.environmentInfo = std::move(newInfo);
  s.environmentTexels = std::move(newTexels);
  s.environmentCdf = std::move(newCdf);
}

void GpuScene::writeEnvironmentPlacement(const scene::Environment& environment) {
  const std::vector<gpu::EnvironmentData> info = {environmentInfo(environment)};
  submitAndWait([&](rhi::ICommandList& cmd) { writeAll(cmd, buffers_->environmentInfo, info); });
}

std::vector<rhi::BindingSetItem> GpuScene::bindingItems() const {
  using Item = rhi::BindingSetItem;
  const Buffers& b = *buffers_;
  return {Item::accelStructure(PT_SLOT_SCENE, b.topLevel),
          Item::storageBuffer(PT_SLOT_VERTICES, b.vertices),
          Item::storageBuffer(PT_SLOT_INDICES, b.indices),
          Item::storageBuffer(PT_SLOT_INSTANCES, b.instances),
          Item::storageBuffer(PT_SLOT_MATERIALS, b.materials),
          Item::storageBuffer(PT_SLOT_EMISSIVE_TRIANGLES, b.emissive),
          Item::storageBuffer(PT_SLOT_POINT_LIGHTS, b.pointLights),
          Item::storageBuffer(PT_SLOT_NORMALS, b.normals),
          Item::storageBuffer(PT_SLOT_TANGENTS, b.tangents),
          Item::storageBuffer(PT_SLOT_TEXCOORDS, b.texcoords),
          Item::storageBuffer(PT_SLOT_COLORS, b.colors),
          Item::storageBuffer(PT_SLOT_IMPLICITS, b.implicits),
          Item::storageBuffer(PT_SLOT_TEXTURE_REFS, b.textureRefs),
          Item::storageBuffer(PT_SLOT_ENVIRONMENT_INFO, b.environmentInfo),
          Item::storageBuffer(PT_SLOT_ENVIRONMENT, b.environmentTexels),
          Item::storageBuffer(PT_SLOT_ENVIRONMENT_CDF, b.environmentCdf),
          Item::storageBuffer(PT_SLOT_SHEEN_ALBEDO, b.sheenAlbedo),
          Item::sampledTextures(PT_SLOT_TEXTURES, b.textures.textures),
          Item::samplers(PT_SLOT_SAMPLERS, b.textures.samplers)};
}

}  // namespace penumbra::render
