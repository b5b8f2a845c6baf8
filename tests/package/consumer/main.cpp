// Links the installed package's libraries (consumer/CMakeLists.txt) and
// calls into each one, so a missing archive, header or dependency of the
// exported targets fails here, not in a user's project.
#include <cstdio>
#include <string>
#include <vector>

// The installed headers by the project's prefix, as a user includes them.
#include <penumbra/backend_factory.h>
#include <penumbra/batch/render_settings.h>
#include <penumbra/image/image_compare.h>
#include <penumbra/render/effect_set.h>
#include <penumbra/render/shader_binding_offsets.h>
#include <penumbra/rhi/device.h>
#include <penumbra/scene/scene_loader.h>
#include <penumbra/shaders/penumbra_shaders.h>
#include <penumbra/study/study_plan.h>

namespace {

int failures = 0;

void check(bool ok, const char* what) {
  std::printf("%s: %s\n", ok ? "ok" : "FAILED", what);
  if (!ok) ++failures;
}

}  // namespace

int main() {
  using namespace penumbra;

  const std::vector<std::string> available = backends::availableBackends();
  std::string names;
  bool vulkan = false;
  for (const std::string& name : available) {
    names += " " + name;
    vulkan = vulkan || name == "vulkan";
  }
  std::printf("backends:%s\n", names.c_str());
  check(vulkan, "penumbra::backends lists the Vulkan backend");

  // The built-in scene comes from the embedded-scenes archive, which only
  // penumbra::scene links (privately).
  const scene::Scene cornell = scene::loadScene("cornell-box");
  std::printf("scene %s: %zu meshes, %llu triangles, effects:", cornell.name.c_str(),
              cornell.meshes.size(), static_cast<unsigned long long>(cornell.triangleCount()));
  for (const std::string& effect : render::effectNames(render::deriveEffects(cornell)))
    std::printf(" %s", effect.c_str());
  std::printf("\n");
  check(!cornell.meshes.empty() && cornell.triangleCount() > 0,
        "penumbra::scene loads the Cornell box");

  image::Image a(4, 4), b(4, 4);
  for (float& value : a.rgba) value = 0.5f;
  b.rgba = a.rgba;
  check(image::compareImages(a, b, 1e-3).pixelsBeyondTolerance == 0,
        "penumbra::image compares two images");

  check(render::findSetting("max-depth") != nullptr,
        "penumbra::batch describes the settings (max-depth)");

  const study::StudySpec spec;  // 4 sample counts x 3 seeds of one technique
  check(study::expandStudy(spec).size() == spec.spp.size() * spec.seeds,
        "penumbra::study expands a study");

  check(!shaders::find("path_trace.rgen").empty(),
        "penumbra::shaders holds the path tracer's SPIR-V");
  check(
      render::kShaderBindingOffsets.registerForBinding(render::kShaderBindingOffsets.shaderResource)
              .registerClass == rhi::RegisterClass::T,
      "bindings.hlsli is installed for render/shader_binding_offsets.h");

  return failures == 0 ? 0 : 1;
}
