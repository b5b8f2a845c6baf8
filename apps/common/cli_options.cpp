#include "cli_options.h"

#include <fmt/format.h>

#include <regex>

#include "penumbra/render/image_size.h"
#include "penumbra/render/shader_binding_offsets.h"
#include "penumbra/util/error.h"

namespace penumbra::app {

rhi::DeviceCreateInfo DeviceOptions::createInfo() const {
  rhi::DeviceCreateInfo info;
  info.adapterIndex = device;
  info.validation = validation;
  info.bindingOffsets = render::kShaderBindingOffsets;
  return info;
}

void addDeviceOptions(CLI::App& cmd, DeviceOptions& o) {
  cmd.add_option("--backend", o.backend, "Backend: vulkan | d3d12")->capture_default_str();
  cmd.add_option("--device", o.device,
                 "Device index from 'penumbra devices' (default: best with ray tracing)");
  cmd.add_flag("--validation", o.validation,
               "Enable the API validation layer; fail on any message");
}

void addSceneOptions(CLI::App& cmd, SceneOptions& o, const std::string& sceneHelp) {
  cmd.add_option("--scene", o.scene, sceneHelp)->capture_default_str();
  cmd.add_option("--size", o.size, "Image size WIDTHxHEIGHT")->capture_default_str();
}

std::pair<uint32_t, uint32_t> parseImageSize(const std::string& text) {
  static const std::regex pattern("([0-9]{1,5})x([0-9]{1,5})");
  std::smatch m;
  if (!std::regex_match(text, m, pattern))
    throw Error(fmt::format("--size '{}': expected WIDTHxHEIGHT, e.g. 512x512", text));
  uint32_t w = std::stoul(m[1]), h = std::stoul(m[2]);
  if (!render::isValidImageSize(w, h))
    throw Error(
        fmt::format("--size '{}': width and height must be 1..{}", text, render::kMaxImageSide));
  return {w, h};
}

void addEnvironmentOptions(CLI::App& cmd, EnvironmentOptions& o) {
  cmd.add_option("--env", o.map,
                 "Environment light: an equirectangular .exr or .hdr, 'default' (the studio "
                 "environment scenes without light get) or 'none'");
  cmd.add_option("--env-rotation", o.rotationDegrees,
                 "Turn the environment about the up axis (degrees, counter-clockwise from above)");
  cmd.add_option("--env-intensity", o.intensity, "Scale the environment's radiance")
      ->check(CLI::Range(0.0f, 1e6f));
  cmd.add_option("--env-background", o.background,
                 "Whether camera rays that miss see the environment: visible | hidden (black)")
      ->check(CLI::IsMember({"visible", "hidden"}));
}

void EnvironmentOptions::apply(const CLI::App& cmd, render::EnvironmentChoice& choice) const {
  if (cmd.count("--env") > 0) choice = render::EnvironmentChoice{map, {}, {}, {}};
  if (cmd.count("--env-rotation") > 0) choice.rotationDegrees = rotationDegrees;
  if (cmd.count("--env-intensity") > 0) choice.intensity = intensity;
  if (cmd.count("--env-background") > 0) choice.visibleBackground = background == "visible";
}

void addAnimationOptions(CLI::App& cmd, AnimationOptions& o) {
  cmd.add_option("--animation", o.animation,
                 "Draw the glTF files' animation of this name, or index (0 is the first), or "
                 "'all' of them at once, at --time (default 0 s)");
  cmd.add_option("--time", o.seconds,
                 "Seconds into the animation (the first one without --animation): nodes, morph "
                 "weights and skins as it sets them then; default: the file's own pose")
      ->check(CLI::Range(-1e9, 1e9));
}

void AnimationOptions::apply(const CLI::App& cmd, scene::AnimationChoice& choice) const {
  if (cmd.count("--animation") > 0) choice.animation = animation;
  if (cmd.count("--time") > 0) choice.seconds = seconds;
}

void addCameraOptions(CLI::App& cmd, CameraOptions& o) {
  cmd.add_option("--camera", o.camera,
                 "Render from the scene's camera of this name (glTF camera or node name) or "
                 "index in node order (0 is the first; default: the first camera)");
  cmd.add_option("--camera-position", o.position,
                 "Put the camera at X,Y,Z (world units: metres after a scene file's unitScale)")
      ->expected(3)
      ->delimiter(',');
  cmd.add_option("--look-at", o.lookAt,
                 "Turn the camera towards the point X,Y,Z (after --camera-position)")
      ->expected(3)
      ->delimiter(',');
  cmd.add_option("--fov", o.fovDegrees,
                 "Vertical field of view in degrees, at any image shape (a perspective camera)")
      ->check(CLI::Range(0.001f, 179.999f));
  cmd.add_option("--orthographic", o.orthographicHeight,
                 "An orthographic camera whose view is HEIGHT world units tall, at any image "
                 "shape (rays parallel along the camera's forward)")
      ->type_name("HEIGHT")
      ->check(CLI::Range(1e-9f, 1e9f));
}

scene::CameraPlacement CameraOptions::placement(const CLI::App& cmd) const {
  scene::CameraPlacement p;
  p.name = camera;
  auto point = [](const std::vector<double>& v) { return glm::dvec3(v[0], v[1], v[2]); };
  if (cmd.count("--camera-position") > 0) p.position = point(position);
  if (cmd.count("--look-at") > 0) p.lookAt = point(lookAt);
  if (cmd.count("--fov") > 0) p.verticalFovDegrees = fovDegrees;
  if (cmd.count("--orthographic") > 0) p.orthographicHeight = orthographicHeight;
  return p;
}

void SettingOptions::add(CLI::App& cmd, const render::RenderSettings& defaults,
                         const Filter& include) {
  using render::SettingType;
  for (const render::Setting& s : render::renderSettingsTable()) {
    if (!s.commandLine || (include && !include(s))) continue;
    Bound& b = bound_.emplace_back(Bound{&s, s.commandLineFlag()});
    const double value = s.get(defaults);
    const std::string help(s.help);
    switch (s.type) {
      case SettingType::Flag:
        cmd.add_flag(b.flag, b.flagGiven, help);
        break;
      case SettingType::Count:
        b.count = uint32_t(value);
        cmd.add_option(b.flag, b.count, help)
            ->check(CLI::Range(uint32_t(s.min), uint32_t(s.max)))
            ->capture_default_str();
        break;
      case SettingType::Number:
        b.number = float(value);
        cmd.add_option(b.flag, b.number, help)
            ->check(CLI::Range(float(s.min), float(s.max)))
            ->capture_default_str();
        break;
      case SettingType::Choice: {
        b.choice = s.format(value);
        std::vector<std::string> names(s.choices.begin(), s.choices.end());
        cmd.add_option(b.flag, b.choice, help)->check(CLI::IsMember(names))->capture_default_str();
        break;
      }
    }
  }
}

void SettingOptions::apply(const CLI::App& cmd, render::RenderSettings& settings) const {
  using render::SettingType;
  for (const Bound& b : bound_) {
    if (cmd.count(b.flag) == 0) continue;
    const render::Setting& s = *b.setting;
    switch (s.type) {
      case SettingType::Flag:
        // The flag names the side that is not the default.
        s.set(settings, s.get(render::RenderSettings{}) != 0.0 ? 0.0 : 1.0);
        break;
      case SettingType::Count:
        s.set(settings, double(b.count));
        break;
      case SettingType::Number:
        s.set(settings, double(b.number));
        break;
      case SettingType::Choice:
        s.set(settings, s.parseOrThrow(b.choice, b.flag));
        break;
    }
  }
}

}  // namespace penumbra::app
