#include "penumbra/scene/gltf_loader.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string_view>

#include "penumbra/scene/camera_placement.h"
#include "penumbra/scene/gltf_animation.h"
#include "penumbra/scene/gltf_container.h"
#include "penumbra/scene/gltf_draco.h"
#include "penumbra/scene/gltf_instancing.h"
#include "penumbra/scene/gltf_lights.h"
#include "penumbra/scene/gltf_materials.h"
#include "penumbra/scene/gltf_meshopt.h"
#include "penumbra/scene/gltf_primitives.h"
#include "penumbra/scene/gltf_skin.h"
#include "penumbra/scene/gltf_textures.h"
#include "penumbra/scene/tinygltf.h"
#include "penumbra/util/error.h"
#include "penumbra/util/log.h"

namespace penumbra::scene {
namespace {

namespace fs = std::filesystem;

// tinygltf reports several lines, and its JSON errors quote the input (a
// whole data URI, say); a penumbra::Error is one readable line.
std::string oneLine(std::string text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
  std::replace(text.begin(), text.end(), '\n', ';');
  std::replace(text.begin(), text.end(), '\r', ' ');
  constexpr size_t kLimit = 300;
  if (text.size() > kLimit) text = text.substr(0, kLimit) + "...";
  return text;
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return s;
}

std::string named(const char* kind, size_t index, const std::string& name) {
  return name.empty() ? fmt::format("{} {}", kind, index)
                      : fmt::format("{} {} '{}'", kind, index, name);
}

// In double, as glTF stores it: a big root translation (georeferenced data)
// must survive composition (scene.h says why).
// `pose`: what an animation sets on the node, in place of its own values.
glm::dmat4 localTransform(const tinygltf::Node& node, const gltf::NodePose& pose,
                          const std::string& where) {
  glm::dmat4 m(1.0);
  auto sizeIs = [&](const std::vector<double>& v, size_t n, const char* what) {
    if (!v.empty() && v.size() != n)
      throw Error(fmt::format("{}: {} has {} numbers, expected {}", where, what, v.size(), n));
    return !v.empty();
  };
  const bool animated = pose.translation || pose.rotation || pose.scale;
  if (sizeIs(node.matrix, 16, "matrix")) {
    if (animated)
      throw Error(fmt::format(
          "{}: is animated but has a matrix (glTF allows animating only translation, rotation "
          "and scale)",
          where));
    for (int i = 0; i < 16; ++i) glm::value_ptr(m)[i] = node.matrix[size_t(i)];  // column-major
  } else {
    glm::dmat4 t(1.0), r(1.0), s(1.0);
    if (pose.translation)
      t = glm::translate(glm::dmat4(1.0), *pose.translation);
    else if (sizeIs(node.translation, 3, "translation"))
      t = glm::translate(glm::dmat4(1.0),
                         glm::dvec3(node.translation[0], node.translation[1], node.translation[2]));
    if (pose.rotation) {
      r = glm::mat4_cast(*pose.rotation);
    } else if (sizeIs(node.rotation, 4, "rotation")) {
      // glTF stores (x, y, z, w); glm::quat's constructor takes w first.
      glm::dquat q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
      const double len = glm::length(q);
      if (!(len > 0.0)) throw Error(fmt::format("{}: rotation is not a unit quaternion", where));
      r = glm::mat4_cast(q / len);
    }
    if (pose.scale)
      s = glm::scale(glm::dmat4(1.0), *pose.scale);
    else if (sizeIs(node.scale, 3, "scale"))
      s = glm::scale(glm::dmat4(1.0), glm::dvec3(node.scale[0], node.scale[1], node.scale[2]));
    m = t * r * s;
  }
  for (int i = 0; i < 16; ++i)
    if (!std::isfinite(glm::value_ptr(m)[i]))
      throw Error(fmt::format("{}: transform is not finite", where));
  return m;
}

class Importer {
 public:
  Importer(const tinygltf::Model& model, gltf::ImageDecoding& decoding, std::string file,
           const InputLimits& limits)
      : model_(model),
        file_(std::move(file)),
        textures_(model, decoding, at(), out_.scene, out_.warnings) {
    budget_.limits = limits;
    pose_.nodes.resize(model.nodes.size());
  }

  GltfImport run(const AnimationChoice& animation) {
    out_.scene.name = fs::path(file_).stem().string();
    checkExtensions();
    pose(animation);
    convertMaterials();
    readVariants();
    textures_.warnUnusedBrokenImages();
    traverse(sceneRoots());
    if (auto line = gltf::degenerateTrianglesWarning(budget_, at()); !line.empty())
      warn(std::move(line));
    if (out_.scene.instances.empty())
      throw Error(fmt::format("{}: the scene has no triangle meshes to render", at()));
    std::stable_sort(cameras_.begin(), cameras_.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    for (auto& [node, camera] : cameras_) out_.scene.cameras.push_back(std::move(camera));
    out_.scene.camera =
        out_.scene.cameras.empty() ? framingCamera(out_.scene) : out_.scene.cameras.front().camera;
    validate(out_.scene);
    return std::move(out_);
  }

 private:
  std::string at() const { return fmt::format("glTF '{}'", file_); }
  void warn(std::string line) { out_.warnings.push_back(std::move(line)); }

  void checkExtensions() {
    // Required ones were checked before tinygltf read the file
    // (requireSupportedExtensions).
    for (const auto& name : model_.extensionsUsed)
      if (!gltf::isSupportedExtension(name))
        warn(fmt::format("{}: optional extension {} is not supported; ignored", at(), name));
  }

  // The animation's values at the chosen time, in place of the nodes' own.
  void pose(const AnimationChoice& choice) {
    if (choice.empty()) return;
    if ((choice.animation.empty() || choice.animation == "all") && model_.animations.empty())
      throw Error(fmt::format("{}: the file has no animations to draw at a time", at()));
    const double seconds = choice.seconds.value_or(0.0);
    if (!std::isfinite(seconds))
      throw Error(fmt::format("{}: the animation time {} is not a finite number", at(), seconds));
    // "all": every animation at once, a later one winning where two animate
    // the same property (files whose animations are parts of one motion).
    const bool all = choice.animation == "all" &&
                     std::none_of(model_.animations.begin(), model_.animations.end(),
                                  [](const auto& a) { return a.name == "all"; });
    std::vector<size_t> chosen;
    if (all)
      for (size_t i = 0; i < model_.animations.size(); ++i) chosen.push_back(i);
    else
      chosen.push_back(
          choice.animation.empty() ? 0 : gltf::findAnimation(model_, choice.animation, at()));
    pose_.start = INFINITY;
    pose_.end = -INFINITY;
    for (size_t index : chosen) {
      const gltf::AnimationPose one =
          gltf::evaluateAnimation(model_, index, seconds, at(), budget_.limits, out_.warnings);
      for (size_t n = 0; n < one.nodes.size(); ++n) {
        const gltf::NodePose& from = one.nodes[n];
        gltf::NodePose& to = pose_.nodes[n];
        if (from.translation) to.translation = from.translation;
        if (from.rotation) to.rotation = from.rotation;
        if (from.scale) to.scale = from.scale;
        if (from.weights) to.weights = from.weights;
      }
      if (one.start <= one.end) {  // an animation with no channel drawn has no keyframes
        pose_.start = std::min(pose_.start, one.start);
        pose_.end = std::max(pose_.end, one.end);
      }
    }
    const std::string name = all ? std::string("the animations")
                                 : named("animation", chosen[0], model_.animations[chosen[0]].name);
    // (start > end: no channel was drawn, so no time is outside.)
    if (pose_.start <= pose_.end && (seconds < pose_.start || seconds > pose_.end))
      warn(fmt::format(
          "{}: {:g} s is outside the keyframes of {} ({:g} to {:g} s); the {} pose is "
          "drawn",
          at(), seconds, name, pose_.start, pose_.end, seconds < pose_.start ? "first" : "last"));
  }

  // Node `index`'s world transform in the drawn pose, through its first
  // parent (for skin joints, which need not lie on the path being
  // traversed).
  glm::dmat4 worldOf(int index) {
    if (parents_.empty()) {
      parents_.assign(model_.nodes.size(), -1);
      worlds_.resize(model_.nodes.size());
      for (size_t n = model_.nodes.size(); n-- > 0;)
        for (int c : model_.nodes[n].children)
          if (c >= 0 && size_t(c) < parents_.size()) parents_[size_t(c)] = int(n);
    }
    std::vector<int> chain;
    int n = index;
    while (n >= 0 && !worlds_[size_t(n)]) {
      chain.push_back(n);
      if (chain.size() > model_.nodes.size())
        throw Error(fmt::format("{} {}: cyclic node graph (the node is its own ancestor)", at(),
                                named("node", size_t(index), model_.nodes[size_t(index)].name)));
      n = parents_[size_t(n)];
    }
    glm::dmat4 world = n >= 0 ? *worlds_[size_t(n)] : glm::dmat4(1.0);
    for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
      const auto& node = model_.nodes[size_t(*it)];
      world =
          world * localTransform(node, pose_.nodes[size_t(*it)],
                                 fmt::format("{} {}", at(), named("node", size_t(*it), node.name)));
      worlds_[size_t(*it)] = world;
    }
    return world;
  }

  // The morph weights node `index` draws its mesh with: the animation's,
  // else the node's own, else the mesh's defaults.
  std::vector<double> morphWeightsOf(size_t index) const {
    const auto& node = model_.nodes[index];
    if (pose_.nodes[index].weights) return *pose_.nodes[index].weights;
    if (!node.weights.empty()) return node.weights;
    return model_.meshes[size_t(node.mesh)].weights;
  }

  void convertMaterials() {
    for (size_t i = 0; i < model_.materials.size(); ++i) {
      const auto& src = model_.materials[i];
      const std::string where = fmt::format("{} {}", at(), named("material", i, src.name));
      auto converted = gltf::convertMaterial(src, where, out_.warnings);
      if (converted.material.name.empty()) converted.material.name = fmt::format("material{}", i);
      textures_.attach(src, converted.material, where);
      invisible_.push_back(converted.invisible);
      out_.scene.materials.push_back(std::move(converted.material));
    }
  }

  // The renderer reads (0, 0) for a texture coordinate set a primitive lacks:
  // a texture then shows one texel across the whole surface.
  void warnMissingTexCoords(const Mesh& mesh, const std::string& where) {
    const Material& m = out_.scene.materials[mesh.material];
    bool reads[2] = {false, false};
    for (uint32_t ref : m.textures())
      if (ref != Material::kNoTexture) reads[out_.scene.textureRefs[ref].texCoord] = true;
    const bool has[2] = {!mesh.uv0.empty(), !mesh.uv1.empty()};
    for (int set = 0; set < 2; ++set)
      if (reads[set] && !has[set])
        warn(
            fmt::format("{}: material '{}' reads TEXCOORD_{}, which the primitive does not have; "
                        "its textures are sampled at (0, 0)",
                        where, m.name, set));
  }

  // KHR_materials_variants: the file's variant names, in order.
  void readVariants() {
    const auto ext = model_.extensions.find("KHR_materials_variants");
    if (ext == model_.extensions.end()) return;
    const tinygltf::Value& variants = ext->second.Get("variants");
    if (!variants.IsArray())
      throw Error(fmt::format("{}: KHR_materials_variants has no variants array", at()));
    for (size_t i = 0; i < variants.ArrayLen(); ++i) {
      const tinygltf::Value& name = variants.Get(int(i)).Get("name");
      if (!name.IsString())
        throw Error(fmt::format("{}: KHR_materials_variants variant {} has no name", at(), i));
      out_.scene.materialVariants.push_back({name.Get<std::string>(), {}});
    }
  }

  // The primitive's materials under each variant that maps it.
  void addVariantMappings(const tinygltf::Primitive& prim, uint32_t mesh,
                          const std::string& where) {
    const auto ext = prim.extensions.find("KHR_materials_variants");
    if (ext == prim.extensions.end()) return;
    const tinygltf::Value& mappings = ext->second.Get("mappings");
    auto index = [&](const tinygltf::Value& v, size_t count, const char* what) {
      if (!v.IsNumber() || !(v.GetNumberAsDouble() >= 0.0) ||
          !(v.GetNumberAsDouble() < double(count)) ||
          std::floor(v.GetNumberAsDouble()) != v.GetNumberAsDouble())
        throw Error(fmt::format("{}: KHR_materials_variants {} is not one of the {} there are",
                                where, what, count));
      return uint32_t(v.GetNumberAsDouble());
    };
    for (size_t m = 0; mappings.IsArray() && m < mappings.ArrayLen(); ++m) {
      const tinygltf::Value& mapping = mappings.Get(int(m));
      const uint32_t material = index(mapping.Get("material"), model_.materials.size(), "material");
      const tinygltf::Value& variants = mapping.Get("variants");
      for (size_t v = 0; variants.IsArray() && v < variants.ArrayLen(); ++v)
        out_.scene
            .materialVariants[index(variants.Get(int(v)), out_.scene.materialVariants.size(),
                                    "variant")]
            .meshMaterials.push_back({mesh, material});
    }
  }

  uint32_t defaultMaterialIndex() {
    if (!defaultMaterial_) {
      defaultMaterial_ = uint32_t(out_.scene.materials.size());
      out_.scene.materials.push_back(gltf::defaultMaterial());
    }
    return *defaultMaterial_;
  }

  std::vector<int> sceneRoots() {
    if (model_.scenes.empty()) {
      // No scenes: every node that is nobody's child is a root.
      std::vector<bool> child(model_.nodes.size(), false);
      for (const auto& n : model_.nodes)
        for (int c : n.children)
          if (c >= 0 && size_t(c) < child.size()) child[size_t(c)] = true;
      std::vector<int> roots;
      for (size_t i = 0; i < child.size(); ++i)
        if (!child[i]) roots.push_back(int(i));
      return roots;
    }
    int index = model_.defaultScene < 0 ? 0 : model_.defaultScene;
    if (size_t(index) >= model_.scenes.size())
      throw Error(fmt::format("{}: default scene {} does not exist ({} scenes)", at(), index,
                              model_.scenes.size()));
    return model_.scenes[size_t(index)].nodes;
  }

  // The scene meshes of glTF mesh `index` in `shape`, one per triangle
  // primitive. Unskinned ones are converted the first time a node draws the
  // mesh with those morph weights, and shared after.
  std::vector<uint32_t> meshesOf(int index, const gltf::PrimitiveShape& shape) {
    if (!shape.joints.empty()) return convertMesh(index, shape);
    auto key = std::make_pair(index, shape.morphWeights);
    auto it = meshes_.find(key);
    if (it == meshes_.end()) it = meshes_.emplace(key, convertMesh(index, shape)).first;
    return it->second;
  }

  std::vector<uint32_t> convertMesh(int index, const gltf::PrimitiveShape& shape) {
    std::vector<uint32_t> result;
    const auto& src = model_.meshes[size_t(index)];
    for (size_t p = 0; p < src.primitives.size(); ++p) {
      const auto& prim = src.primitives[p];
      const std::string name =
          fmt::format("{} {} primitive {}", at(), named("mesh", size_t(index), src.name), p);
      uint32_t material;
      if (prim.material < 0) {
        material = defaultMaterialIndex();
      } else if (size_t(prim.material) < model_.materials.size()) {
        if (invisible_[size_t(prim.material)]) continue;  // alpha MASK cuts it all away
        material = uint32_t(prim.material);
      } else {
        throw Error(fmt::format("{}: material {} does not exist ({} materials)", name,
                                prim.material, model_.materials.size()));
      }
      auto mesh =
          gltf::convertPrimitive(model_, prim, material, shape, name, out_.warnings, budget_);
      if (!mesh) continue;
      warnMissingTexCoords(*mesh, name);
      mesh->name =
          fmt::format("{}/{}", src.name.empty() ? fmt::format("mesh{}", index) : src.name, p);
      addVariantMappings(prim, uint32_t(out_.scene.meshes.size()), name);
      result.push_back(uint32_t(out_.scene.meshes.size()));
      out_.scene.meshes.push_back(std::move(*mesh));
    }
    return result;
  }

  void addCamera(size_t nodeIndex, const glm::dmat4& world) {
    const auto& node = model_.nodes[nodeIndex];
    const std::string where = fmt::format("{} {}", at(), named("node", nodeIndex, node.name));
    if (node.camera < 0 || size_t(node.camera) >= model_.cameras.size())
      throw Error(fmt::format("{}: camera {} does not exist ({} cameras)", where, node.camera,
                              model_.cameras.size()));
    const auto& src = model_.cameras[size_t(node.camera)];
    const std::string name = named("camera", size_t(node.camera), src.name);
    const bool orthographic = src.type == "orthographic";
    if (!orthographic && src.type != "perspective")
      throw Error(fmt::format("{}: {} has type '{}'; 'perspective' or 'orthographic' expected",
                              where, name, src.type));
    const double yfov = src.perspective.yfov;
    const double xmag = src.orthographic.xmag, ymag = src.orthographic.ymag;
    // The view's height and shape as the camera holds them, in floats: the
    // height at most 1e9 (scene::validateCamera), neither rounded to 0 or
    // to infinity.
    const float height = float(2.0 * std::abs(ymag));
    const float shape = float(std::abs(xmag / ymag));
    if (orthographic && !(height > 0.0f && height <= 1e9f && shape > 0.0f && std::isfinite(shape)))
      throw Error(fmt::format(
          "{}: {} has xmag {} and ymag {}; the view's height 2|ymag| must be in (0, 1e9] and "
          "its aspect |xmag/ymag| a finite float above 0",
          where, name, xmag, ymag));
    if (!orthographic && !(yfov > 0.0 && yfov < glm::pi<double>()))
      throw Error(fmt::format("{}: {} has yfov {}, not in (0, pi)", where, name, yfov));
    // glTF cameras look down their node's -z with +y up; scale is ignored.
    NamedCamera c;
    c.name = src.name;
    c.nodeName = node.name;
    c.camera.position = glm::dvec3(world * glm::dvec4(0, 0, 0, 1));
    const glm::vec3 forward = glm::vec3(world * glm::dvec4(0, 0, -1, 0));
    const glm::vec3 up = glm::vec3(world * glm::dvec4(0, 1, 0, 0));
    if (!(glm::length(forward) > 0.0f) || !(glm::length(glm::cross(forward, up)) > 0.0f))
      throw Error(fmt::format("{}: the node's transform collapses {}'s view", where, name));
    c.camera.forward = glm::normalize(forward);
    c.camera.up = glm::normalize(up);
    // The frame the view was chosen for: a narrower image keeps its
    // horizontal field of view or width (scene::Camera::aspectRatio).
    double aspect = src.perspective.aspectRatio;
    if (orthographic) {
      // xmag and ymag are half the view's width and height.
      c.camera.orthographicHeight = height;
      aspect = shape;
    } else {
      c.camera.verticalFovDegrees = float(glm::degrees(yfov));
    }
    if (aspect > 0.0 && std::isfinite(aspect)) c.camera.aspectRatio = float(aspect);
    cameras_.emplace_back(nodeIndex, std::move(c));
  }

  // Depth-first over the node trees with an explicit stack (deep hierarchies
  // cannot overflow the call stack). A node met again while it is still on
  // the current path is a cycle; one reached through a second parent (not
  // allowed by glTF, seen in the wild) is instanced again, with a warning.
  void traverse(const std::vector<int>& roots) {
    struct Step {
      int node;
      glm::dmat4 parent;
      bool leave;
    };
    std::vector<Step> stack;
    for (auto it = roots.rbegin(); it != roots.rend(); ++it)
      stack.push_back({*it, glm::dmat4(1.0), false});
    std::vector<uint8_t> onPath(model_.nodes.size(), 0), seen(model_.nodes.size(), 0);
    size_t visits = 0;
    while (!stack.empty()) {
      const Step step = stack.back();
      stack.pop_back();
      if (step.leave) {
        onPath[size_t(step.node)] = 0;
        continue;
      }
      if (step.node < 0 || size_t(step.node) >= model_.nodes.size())
        throw Error(fmt::format("{}: node {} does not exist ({} nodes)", at(), step.node,
                                model_.nodes.size()));
      const size_t index = size_t(step.node);
      const auto& node = model_.nodes[index];
      const std::string where = fmt::format("{} {}", at(), named("node", index, node.name));
      if (onPath[index])
        throw Error(fmt::format("{}: cyclic node graph (the node is its own ancestor)", where));
      if (seen[index] == 1)
        warn(fmt::format("{}: has more than one parent; instanced under each", where));
      seen[index] = uint8_t(std::min(seen[index] + 1, 2));
      requireAtMost(++visits, budget_.limits.maxNodeVisits, "maxNodeVisits",
                    at() + " node graph's node visits");
      onPath[index] = 1;
      stack.push_back({step.node, glm::dmat4(1.0), true});

      const glm::dmat4 world = step.parent * localTransform(node, pose_.nodes[index], where);
      if (node.mesh >= 0) {
        if (size_t(node.mesh) >= model_.meshes.size())
          throw Error(fmt::format("{}: mesh {} does not exist ({} meshes)", where, node.mesh,
                                  model_.meshes.size()));
        gltf::PrimitiveShape shape{morphWeightsOf(index), {}};
        // A skinned mesh is placed by its joints alone; its vertices are
        // taken into the node's space, which the instance keeps (gltf_skin.h),
        // or into world space where that space collapses (a zero scale).
        glm::dmat4 place = world;
        if (node.skin >= 0) {
          if (glm::determinant(world) == 0.0) place = glm::dmat4(1.0);
          shape.joints = gltf::jointMatrices(
              model_, node.skin, place, [&](int n) { return worldOf(n); }, where, budget_.limits);
        }
        // EXT_mesh_gpu_instancing: a copy of the mesh per instance, in the
        // node's space; otherwise the one at the node.
        std::vector<glm::dmat4> placements;
        for (const glm::dmat4& copy :
             gltf::gpuInstanceTransforms(model_, node, where, budget_.limits))
          placements.push_back(place * copy);
        if (placements.empty()) placements.push_back(place);
        for (uint32_t mesh : meshesOf(node.mesh, shape))
          for (const glm::dmat4& placement : placements) {
            requireAtMost(out_.scene.instances.size() + 1, budget_.limits.maxInstances,
                          "maxInstances", at() + " instance count");
            out_.scene.instances.push_back({mesh, placement});
          }
      }
      if (node.camera >= 0) addCamera(index, world);
      if (auto light = gltf::nodeLight(model_, node, world, where))
        out_.scene.pointLights.push_back(*light);
      for (auto it = node.children.rbegin(); it != node.children.rend(); ++it)
        stack.push_back({*it, world, false});
    }
  }

  const tinygltf::Model& model_;
  std::string file_;
  GltfImport out_;
  gltf::TextureImporter textures_;
  gltf::DecodeBudget budget_;
  std::vector<bool> invisible_;
  std::optional<uint32_t> defaultMaterial_;
  std::map<std::pair<int, std::vector<double>>, std::vector<uint32_t>> meshes_;
  std::vector<std::pair<size_t, NamedCamera>> cameras_;
  gltf::AnimationPose pose_;
  std::vector<int> parents_;                       // each node's first parent, -1 for none
  std::vector<std::optional<glm::dmat4>> worlds_;  // worldOf's results
};

}  // namespace

bool isGltfPath(const std::string& path) {
  const std::string ext = lower(fs::path(path).extension().string());
  return ext == ".gltf" || ext == ".glb";
}

namespace {

// tinygltf's file access, through FileAccess: the file a URI names must lie
// inside the glTF file's folder unless the user allowed others, and must be
// a regular file (a folder named by a URI once became a huge allocation).
struct FileAccessPolicy {
  std::string base;  // the folder as tinygltf joins URIs to it: the path up to its last '/'
  fs::path folder;   // canonical
  bool allowOutside = false;
};

bool inside(const fs::path& file, const fs::path& folder) {
  auto f = file.begin();
  for (auto d = folder.begin(); d != folder.end(); ++d, ++f)
    if (f == file.end() || *f != *d) return false;
  return true;
}

bool readWholeFile(std::vector<unsigned char>* out, std::string* err, const std::string& path,
                   void* user) {
  const auto& policy = *static_cast<const FileAccessPolicy*>(user);
  // tinygltf joins every URI to the folder, an absolute one too
  // ("folder//abs/path"): take such a URI as the path it is.
  std::string file = path;
  if (!policy.base.empty() && file.rfind(policy.base + "/", 0) == 0 &&
      fs::path(file.substr(policy.base.size() + 1)).is_absolute())
    file = file.substr(policy.base.size() + 1);
  std::error_code ec;
  const fs::path resolved = fs::weakly_canonical(fs::absolute(file, ec), ec);
  if (ec || !fs::is_regular_file(resolved, ec)) {
    if (err) *err += fmt::format("'{}' is not a readable file\n", file);
    return false;
  }
  if (!policy.allowOutside && !inside(resolved, policy.folder)) {
    if (err)
      *err += fmt::format(
          "'{}' lies outside the glTF file's folder {}; --allow-external-files lets a scene "
          "read it\n",
          file, policy.folder.string());
    return false;
  }
  return tinygltf::ReadWholeFile(out, err, resolved.string(), nullptr);
}

// tinygltf's default expands environment variables and ~ in URIs; a URI is a
// path relative to the glTF file and nothing else.
std::string expandNothing(const std::string& path, void*) {
  return path;
}

// A file that requires an extension Penumbra does not read is refused
// before tinygltf reads it: a compressed mesh or image would otherwise fail
// in tinygltf with a message about what it found instead (an accessor
// without a buffer view, an unknown image type).
//
// Skins without "joints" (files from before glTF 2.0 was final, which had
// "jointNames") are refused here too: tinygltf fails them without a reason.
void requireSupportedExtensions(std::string_view jsonText, const std::string& at) {
  const auto doc = nlohmann::json::parse(jsonText, nullptr, false);
  if (doc.is_discarded() || !doc.is_object()) return;  // tinygltf says what is wrong
  if (const auto skins = doc.find("skins"); skins != doc.end() && skins->is_array())
    for (size_t i = 0; i < skins->size(); ++i)
      if (!(*skins)[i].is_object() || !(*skins)[i].contains("joints") ||
          !(*skins)[i].at("joints").is_array())
        throw Error(fmt::format("{}: skin {} has no \"joints\" array{}", at, i,
                                (*skins)[i].is_object() && (*skins)[i].contains("jointNames")
                                    ? " (it has \"jointNames\", from a draft before glTF 2.0)"
                                    : ""));
  if (!doc.contains("extensionsRequired")) return;
  const nlohmann::json& required = doc.at("extensionsRequired");
  if (!required.is_array()) return;
  for (const auto& name : required) {
    if (!name.is_string() || gltf::isSupportedExtension(name.get<std::string>())) continue;
    std::string supported;
    for (auto s : gltf::supportedExtensions())
      supported += (supported.empty() ? "" : ", ") + std::string(s);
    throw Error(fmt::format("{}: requires extension {}, which is not supported (supported: {})", at,
                            name.get<std::string>(), supported));
  }
}

// Existence is judged by readWholeFile, which says why a file is refused.
bool fileExists(const std::string&, void*) {
  return true;
}

// The JSON text tinygltf will parse: the whole .gltf, or a .glb's first
// chunk where its header is sound (tinygltf refuses the file unparsed if not).
std::string_view jsonText(const std::vector<unsigned char>& data, bool binary) {
  const std::string_view all(reinterpret_cast<const char*>(data.data()), data.size());
  if (!binary) return all;
  if (data.size() < 20 || all.substr(0, 4) != "glTF") return {};
  uint32_t length = 0;
  std::memcpy(&length, data.data() + 12, 4);  // little-endian, as the targets
  return uint64_t(length) <= data.size() - 20 ? all.substr(20, length) : std::string_view();
}

}  // namespace

GltfImport importGltf(const std::string& path, const FileAccess& access, const InputLimits& limits,
                      const AnimationChoice& animation) {
  const std::string at = fmt::format("glTF '{}'", path);
  std::error_code ec;
  if (fs::is_directory(path, ec)) throw Error(fmt::format("{}: is a folder, not a file", at));
  if (!fs::is_regular_file(path, ec)) throw Error(fmt::format("{}: no such file", at));
  if (!isGltfPath(path))
    throw Error(fmt::format("{}: not a glTF file (expected .gltf or .glb)", at));
  tinygltf::TinyGLTF loader;
  const size_t slash = path.find_last_of("/\\");
  FileAccessPolicy policy{slash == std::string::npos ? "" : path.substr(0, slash),
                          fs::weakly_canonical(fs::absolute(path).parent_path(), ec),
                          access.allowOutsideFolder};
  loader.SetFsCallbacks({&fileExists, &expandNothing, &readWholeFile, nullptr, &policy});
  gltf::ImageDecoding decoding;
  decoding.limits = limits;
  loader.SetImageLoader(gltf::decodeImage, &decoding);
  // Read here rather than by tinygltf, so that the JSON's nesting is bounded
  // before its parser, and its recursive conversion of "extras", see it.
  std::vector<unsigned char> data;
  std::string readError;
  if (!readWholeFile(&data, &readError, path, &policy))
    throw Error(fmt::format("{}: {}", at, oneLine(readError)));
  if (data.empty()) throw Error(fmt::format("{}: the file is empty", at));
  if (data.size() > UINT32_MAX)
    throw Error(fmt::format("{}: larger than 4 GiB, more than glTF can address", at));
  const bool binary = lower(fs::path(path).extension().string()) == ".glb";
  requireJsonDepth(jsonText(data, binary), limits, at);
  requireSupportedExtensions(jsonText(data, binary), at);
  // Files tinygltf would refuse though valid with the extensions this build reads.
  const std::string_view json = jsonText(data, binary);
  const bool meshopt =
      gltf::meshoptSupported() && json.find("EXT_meshopt_compression") != json.npos;
  const bool draco = gltf::dracoSupported() && json.find("KHR_draco_mesh_compression") != json.npos;
  if (meshopt || draco)
    gltf::editJson(
        data, binary,
        [&](nlohmann::json& doc) {
          const bool emptied = meshopt && gltf::emptyMeshoptFallbacks(doc, binary);
          const bool pointed = draco && gltf::giveDracoIndicesAView(doc);
          return emptied || pointed;
        },
        at);
  tinygltf::Model model;
  std::string err, warn;
  bool ok = false;
  try {
    // policy.base is the folder as tinygltf's LoadFromFile would pass it.
    if (binary)
      ok = loader.LoadBinaryFromMemory(&model, &err, &warn, data.data(), uint32_t(data.size()),
                                       policy.base);
    else
      ok = loader.LoadASCIIFromString(&model, &err, &warn,
                                      reinterpret_cast<const char*>(data.data()),
                                      uint32_t(data.size()), policy.base);
  } catch (const std::exception& e) {
    // tinygltf catches its JSON parser's exceptions, but not every library error.
    throw Error(fmt::format("{}: {}", at, oneLine(e.what())));
  }
  if (!ok) {
    // tinygltf fails some files (an empty image file) with a warning only.
    const std::string& reason = !err.empty() ? err : warn;
    throw Error(fmt::format("{}: {}", at, oneLine(reason.empty() ? "cannot be read" : reason)));
  }
  gltf::decodeMeshoptViews(model, limits, at);
  gltf::decodeDracoPrimitives(model, limits, at);
  GltfImport result = Importer(model, decoding, path, limits).run(animation);
  if (!warn.empty())
    result.warnings.insert(result.warnings.begin(), fmt::format("{}: {}", at, oneLine(warn)));
  return result;
}

Scene loadGltf(const std::string& path, const FileAccess& access, const InputLimits& limits,
               const AnimationChoice& animation) {
  GltfImport result = importGltf(path, access, limits, animation);
  for (const auto& w : result.warnings) log::warning("{}", w);
  return std::move(result.scene);
}

}  // namespace penumbra::scene
