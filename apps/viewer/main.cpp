// `penumbra-viewer`: the interactive viewer (GLFW window, Dear ImGui menus).
#include <CLI/CLI.hpp>
#include <cstdio>

#include "render/image_size.h"
#include "util/error.h"
#include "util/log.h"
#include "viewer_app.h"

namespace {
// "1280x720" -> width and height; false when malformed.
bool parseSize(const std::string& text, uint32_t& width, uint32_t& height) {
  unsigned w = 0, h = 0;
  char extra = 0;
  if (std::sscanf(text.c_str(), "%ux%u%c", &w, &h, &extra) != 2 ||
      !penumbra::render::isValidImageSize(w, h))
    return false;
  width = w;
  height = h;
  return true;
}
}  // namespace

int main(int argc, char** argv) {
  using namespace penumbra;
  viewer::ViewerOptions o;
  std::string size = "1280x720";
  float renderScale = 0;
  bool noVsync = false;
  CLI::App app{"Penumbra viewer: interactive path tracing"};
  app.add_option("--scene", o.scene, "Built-in scene name or scene file (.json)")
      ->capture_default_str();
  app.add_option("--size", size, "Window size WIDTHxHEIGHT (offscreen: the image shown)")
      ->capture_default_str();
  app.add_flag("--offscreen", o.offscreen,
               "No window: the viewer loop renders into an image on any device, a GPU "
               "server without a display too; needs --script");
  app.add_option("--record", o.recordDirectory,
                 "Write every frame as shown, menus included, as DIR/frame-NNNNNN.png");
  app.add_option("--backend", o.backend, "Backend: vulkan or d3d12")->capture_default_str();
  app.add_option("--device", o.device,
                 "Device index from 'penumbra devices' (default: best with ray tracing)");
  app.add_option("--render-scale", renderScale,
                 "Fixed render scale (0.125..1) instead of the automatic one")
      ->check(CLI::Range(0.125f, 1.0f));
  app.add_option("--spp-per-frame", o.samplesPerFrame, "Samples per pixel each frame")
      ->check(CLI::Range(1u, 16u))
      ->capture_default_str();
  app.add_option("--frames-in-flight", o.framesInFlight,
                 "Frames the CPU may record ahead of the GPU")
      ->check(CLI::Range(1u, 4u))
      ->capture_default_str();
  app.add_flag("--no-vsync", noVsync, "Present without waiting for vertical blank");
  app.add_option("--script", o.script, "Run scripted commands (see apps/viewer/script.h)");
  app.add_flag("--allow-external-files", o.allowExternalFiles,
               "Let glTF files read buffers and images outside their own folder");
  app.add_option("--config", o.config, "Viewer settings file holding camera bookmarks");
  std::string envMap, envBackground;
  float envRotation = 0.0f, envIntensity = 1.0f;
  app.add_option("--env", envMap,
                 "Environment light: an equirectangular .exr or .hdr, 'default' or 'none'");
  app.add_option("--env-rotation", envRotation, "Turn the environment about the up axis (degrees)");
  app.add_option("--env-intensity", envIntensity, "Scale the environment's radiance")
      ->check(CLI::Range(0.0f, 1e6f));
  app.add_option("--env-background", envBackground,
                 "Whether camera rays that miss see the environment: visible | hidden")
      ->check(CLI::IsMember({"visible", "hidden"}));
  app.add_flag("--validation", o.validation,
               "Enable the API validation layer; exit 1 on any message");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);
    std::fprintf(stderr, "error: %s (see --help)\n", e.what());
    return 2;
  }
  if (!parseSize(size, o.width, o.height)) {
    std::fprintf(stderr, "error: --size '%s': expected WIDTHxHEIGHT, e.g. 1280x720\n",
                 size.c_str());
    return 2;
  }
  if (o.offscreen && o.script.empty()) {
    std::fprintf(stderr,
                 "error: --offscreen needs --script (nothing else would end the session)\n");
    return 2;
  }
  if (renderScale > 0) o.renderScale = renderScale;
  o.environment.map = envMap;
  if (app.count("--env-rotation") > 0) o.environment.rotationDegrees = envRotation;
  if (app.count("--env-intensity") > 0) o.environment.intensity = envIntensity;
  if (app.count("--env-background") > 0)
    o.environment.visibleBackground = envBackground == "visible";
  o.vsync = !noVsync;
  try {
    viewer::Viewer viewer(o);
    return viewer.run();
  } catch (const Error& e) {
    log::error("{}", e.what());
    return 1;
  } catch (const std::exception& e) {
    log::error("internal error: {}", e.what());
    return 1;
  }
}
