#pragma once
// The scene on the GPU: its buffers (vertices and their attributes, indices,
// instances, materials, emitters, point lights, implicit objects, textures,
// the environment's tables), its acceleration structures (one BLAS per merge
// group of meshes drawn once, one per instanced mesh, one per implicit
// family; the TLAS), and their updates: a new render-space origin, new
// materials, a new environment. Every pipeline that traces the scene (the
// integrators, the ray probe) binds what bindingItems() lists.
#include <functional>
#include <glm/glm.hpp>
#include <memory>
#include <vector>

#include "path_tracer_shared.h"
#include "penumbra/render/implicit_geometry.h"
#include "penumbra/rhi/rhi.h"
#include "penumbra/scene/scene.h"

namespace penumbra::render {

// The GPU form of a scene material (path_tracer_shared.h).
gpu::MaterialData packMaterial(const scene::Material& material);

// GPU time of the scene's acceleration-structure builds (timestamps around
// them): every BLAS (meshes, and the implicit objects' AABBs with their small
// uploads), then the TLAS.
struct AccelStructBuildTimes {
  double bottomLevelSeconds = 0;
  double topLevelSeconds = 0;
};

// Render space's origin for a camera at `position`: the nearest point of a
// 64 m grid (docs/ARCHITECTURE.md, "Precision").
glm::dvec3 renderOriginNear(const glm::dvec3& position);

class GpuScene {
 public:
  // Uploads `scene` (validated by the caller) placed about `renderOrigin`
  // and builds its acceleration structures; waits for the GPU.
  // `allImplicitFamilies`: the TLAS's hit-group offsets count every implicit
  // family, in enum order, as a pipeline holding all effects lists them;
  // otherwise only the families the scene has.
  GpuScene(rhi::IDevice& device, const scene::Scene& scene, const glm::dvec3& renderOrigin,
           bool allImplicitFamilies);
  ~GpuScene();
  GpuScene(const GpuScene&) = delete;
  GpuScene& operator=(const GpuScene&) = delete;
  // The bytes of the vertex, attribute and index arrays the upload of
  // `scene` builds on the host (and then holds on the device as well):
  // what an out-of-memory message says a scene needs, before acceleration
  // structures.
  static uint64_t uploadBytes(const scene::Scene& scene);

  // Places everything that depends on the origin again about `origin`
  // (instances, emitters, point lights, implicit objects; the implicit
  // BLASes and the TLAS rebuilt in place, the meshes' BLASes kept): the
  // scene as one uploaded about `origin` would be. Waits for frames in
  // flight first and for the GPU after.
  void rebase(const glm::dvec3& origin);
  // Rewrites the materials (same count and order as the scene's); waits.
  void writeMaterials(const std::vector<scene::Material>& materials);
  // Builds and uploads the environment's tables (an absent environment gets
  // placeholders); the new buffers replace the old only once written, so a
  // failure leaves the old ones bound and whole. Binding sets made before
  // hold the old buffers: make them again.
  void uploadEnvironment(const scene::Environment& environment);
  // Rewrites the environment's rotation, intensity and background alone.
  void writeEnvironmentPlacement(const scene::Environment& environment);

  const glm::dvec3& renderOrigin() const { return renderOrigin_; }
  glm::dmat4 worldToRenderSpace() const;
  // Emissive triangles NEE samples, and point/spot/directional lights.
  uint32_t emissiveTriangleCount() const { return emissiveTriangleCount_; }
  uint32_t pointLightCount() const { return pointLightCount_; }
  // The implicit families' hit groups, in the order of the TLAS instances'
  // hit-group offsets (hit group 1 + i is family i's).
  const std::vector<ImplicitFamily>& implicitFamilies() const;
  // GPU instance index -> scene instance index, for mesh instances (the GPU
  // orders them by merge group); implicit objects follow in both orders.
  const std::vector<uint32_t>& gpuToSceneInstance() const { return gpuToSceneInstance_; }
  const AccelStructBuildTimes& accelStructBuildTimes() const { return buildTimes_; }
  // The scene's resources by their PT_SLOT_* registers.
  std::vector<rhi::BindingSetItem> bindingItems() const;

 private:
  struct Buffers;
  struct WorldPlacement;
  struct MeshLayout;
  void upload(const scene::Scene& scene, bool allImplicitFamilies);
  static MeshLayout packMeshes(const scene::Scene& scene);
  std::vector<gpu::InstanceData> placeInstances(const scene::Scene& scene,
                                                const MeshLayout& layout);
  void buildAccelStructs(const scene::Scene& scene, const MeshLayout& layout,
                         bool allImplicitFamilies);
  void uploadImplicits(const scene::Scene& scene, bool allImplicitFamilies,
                       std::vector<rhi::rt::InstanceDesc>& tlasInstances);
  ImplicitLayout implicitLayoutInRenderSpace() const;
  // Records `work` into the scene's own command list, submits it and waits.
  void submitAndWait(const std::function<void(rhi::ICommandList&)>& work);

  rhi::IDevice& device_;
  glm::dvec3 renderOrigin_;
  rhi::CommandListHandle commandList_;
  std::unique_ptr<Buffers> buffers_;
  std::unique_ptr<WorldPlacement> placement_;
  std::vector<uint32_t> gpuToSceneInstance_;
  uint32_t emissiveTriangleCount_ = 0;
  uint32_t pointLightCount_ = 0;
  AccelStructBuildTimes buildTimes_;
};

}  // namespace penumbra::render
