#pragma once
// Options more than one command takes, declared once: the device options,
// the scene and image size, and every setting of the settings table
// (batch/render_settings.h) as an option of its own.
#include <CLI/CLI.hpp>
#include <cstdint>
#include <deque>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "penumbra/batch/render_job.h"
#include "penumbra/batch/render_settings.h"
#include "penumbra/rhi/device.h"
#include "penumbra/scene/camera_placement.h"

namespace penumbra::app {

// --backend, --device, --validation.
struct DeviceOptions {
  std::string backend = "vulkan";
  int device = -1;  // adapter index; -1: the best with ray tracing
  bool validation = false;
  rhi::DeviceCreateInfo createInfo() const;
};
void addDeviceOptions(CLI::App& cmd, DeviceOptions& options);

// --scene (with `sceneHelp`, which says what files the command reads) and
// --size WIDTHxHEIGHT.
struct SceneOptions {
  std::string scene = "cornell-box";
  std::string size = "512x512";
};
void addSceneOptions(CLI::App& cmd, SceneOptions& options, const std::string& sceneHelp);
// "512x512" -> (512, 512); penumbra::Error naming --size otherwise.
std::pair<uint32_t, uint32_t> parseImageSize(const std::string& text);

// --env, --env-rotation, --env-intensity, --env-background: the
// environment asked for over the scene's (render::EnvironmentChoice).
struct EnvironmentOptions {
  std::string map;
  float rotationDegrees = 0.0f;
  float intensity = 1.0f;
  std::string background;  // visible | hidden
  // Applies the options given on the command line to `choice`: a new map
  // starts from its own defaults; what is not given stays.
  void apply(const CLI::App& cmd, render::EnvironmentChoice& choice) const;
};
void addEnvironmentOptions(CLI::App& cmd, EnvironmentOptions& options);

// --animation, --time: the moment of the glTF files' animations to draw
// (scene::AnimationChoice).
struct AnimationOptions {
  std::string animation;
  double seconds = 0.0;
  // Applies the options given on the command line to `choice`.
  void apply(const CLI::App& cmd, scene::AnimationChoice& choice) const;
};
void addAnimationOptions(CLI::App& cmd, AnimationOptions& options);

// --camera, --camera-position, --look-at, --fov, --orthographic: the view
// over the scene's camera (scene::CameraPlacement).
struct CameraOptions {
  std::string camera;
  std::vector<double> position, lookAt;
  float fovDegrees = 45.0f;
  float orthographicHeight = 1.0f;
  // The parts given on the command line.
  scene::CameraPlacement placement(const CLI::App& cmd) const;
};
void addCameraOptions(CLI::App& cmd, CameraOptions& options);

// The settings table's command-line settings as options: --max-depth,
// --strategy, --no-russian-roulette, ... each checked against the setting's
// range or choices, its default shown from `defaults`.
class SettingOptions {
 public:
  using Filter = std::function<bool(const render::Setting&)>;
  // Adds an option for each setting `include` accepts (default: every
  // command-line setting).
  void add(CLI::App& cmd, const render::RenderSettings& defaults, const Filter& include = {});
  // Copies each option given on the command line onto `settings`.
  void apply(const CLI::App& cmd, render::RenderSettings& settings) const;

 private:
  struct Bound {
    const render::Setting* setting;
    std::string flag;
    uint32_t count = 0;
    float number = 0;
    std::string choice;
    bool flagGiven = false;
  };
  std::deque<Bound> bound_;  // stable addresses: CLI11 writes into them
};

}  // namespace penumbra::app
