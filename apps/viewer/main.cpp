// `penumbra-viewer`: the interactive viewer (GLFW window, Dear ImGui menus).
#include <CLI/CLI.hpp>
#include <cstdio>
#include <tuple>

#include "cli_options.h"
#include "penumbra/util/error.h"
#include "penumbra/util/log.h"
#include "viewer_app.h"

int main(int argc, char** argv) {
  using namespace penumbra;
  viewer::ViewerOptions o;
  app::SceneOptions scene{"cornell-box", "1280x720"};
  app::DeviceOptions device;
  app::EnvironmentOptions environment;
  app::SettingOptions settings;
  float renderScale = 0;
  bool noVsync = false;
  CLI::App app{"Penumbra viewer: interactive path tracing"};
  app::addSceneOptions(app, scene, "Built-in scene name, scene file (.json) or glTF file");
  app.add_flag("--offscreen", o.offscreen,
               "No window: the viewer loop renders into an image on any device, a GPU "
               "server without a display too; needs --script");
  app.add_option("--record", o.recordDirectory,
                 "Write every frame as shown, menus included, as DIR/frame-NNNNNN.png");
  app::addDeviceOptions(app, device);
  app.add_option("--render-scale", renderScale,
                 "Fixed render scale (0.125..1) instead of the automatic one")
      ->check(CLI::Range(0.125f, 1.0f));
  // The settings table's settings (batch/render_settings.h), as `render`
  // takes them; the menus and `set` change them later.
  settings.add(app, o.render);
  app.add_option("--frames-in-flight", o.framesInFlight,
                 "Frames the CPU may record ahead of the GPU")
      ->check(CLI::Range(1u, 4u))
      ->capture_default_str();
  app.add_flag("--no-vsync", noVsync, "Present without waiting for vertical blank");
  app.add_option("--script", o.script, "Run scripted commands (see apps/viewer/script.h)");
  app.add_flag("--allow-external-files", o.allowExternalFiles,
               "Let glTF files read buffers and images outside their own folder");
  app.add_option("--config", o.config, "Viewer settings file holding camera bookmarks");
  app::addEnvironmentOptions(app, environment);
  app::CameraOptions camera;
  app::addCameraOptions(app, camera);
  app.add_option("--variant", o.variant,
                 "Draw the glTF file's material variant of this name, or index (0 is the first; "
                 "KHR_materials_variants)");
  app::AnimationOptions animation;
  app::addAnimationOptions(app, animation);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);
    std::fprintf(stderr, "error: %s (see --help)\n", e.what());
    return 2;
  }
  try {
    std::tie(o.width, o.height) = app::parseImageSize(scene.size);
  } catch (const Error& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
  o.scene = scene.scene;
  o.device = device;
  settings.apply(app, o.render);
  if (o.offscreen && o.script.empty()) {
    std::fprintf(stderr,
                 "error: --offscreen needs --script (nothing else would end the session)\n");
    return 2;
  }
  if (renderScale > 0) o.renderScale = renderScale;
  environment.apply(app, o.environment);
  o.camera = camera.placement(app);
  animation.apply(app, o.animation);
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
