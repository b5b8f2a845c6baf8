#pragma once
// The interactive viewer: a window, the path tracer accumulating while the
// camera and settings are still, the display pass and Dear ImGui menus into
// an RGBA8 display texture, copied into the back buffer. Offscreen, the same
// loop runs without a window or swapchain (a GPU server without a display)
// and the display texture is what captures and recordings read back.
#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bookmarks.h"
#include "camera_controller.h"
#include "cli_options.h"
#include "imgui_renderer.h"
#include "penumbra/batch/render_job.h"
#include "penumbra/render/denoiser.h"
#include "penumbra/render/display_pass.h"
#include "penumbra/render/path_tracer.h"
#include "penumbra/rhi/rhi.h"
#include "penumbra/scene/scene.h"
#include "render_scale.h"
#include "script.h"
#include "viewer_settings.h"
#include "window.h"

namespace penumbra::viewer {

struct ViewerOptions {
  std::string scene = "cornell-box";
  uint32_t width = 1280, height = 720;
  app::DeviceOptions device;
  std::string script;
  std::optional<float> renderScale;  // fixed scale; unset: automatic
  // The settings table's settings the session starts with (the command
  // line's; ViewerSettings' defaults otherwise).
  render::RenderSettings render = ViewerSettings::defaultRenderSettings();
  uint32_t framesInFlight = 2;
  bool vsync = true;
  std::string config;                     // bookmarks file; empty: BookmarkStore::defaultPath()
  render::EnvironmentChoice environment;  // --env options, applied to every scene loaded
  // --camera, --camera-position, --look-at, --fov, --orthographic: the first
  // scene's view (a scene opened later starts from its own camera).
  scene::CameraPlacement camera;
  // --variant, --animation, --time: the first scene's material variant and
  // animation pose (a scene opened later has its own materials and pose).
  std::string variant;
  scene::AnimationChoice animation;
  // No window and no swapchain: width x height is the size the window would
  // have; a script drives the session (nothing else ends it).
  bool offscreen = false;
  // Write every frame as shown (UI included) as DIR/frame-NNNNNN.png.
  std::string recordDirectory;
  // glTF files may read buffers and images outside their own folder.
  bool allowExternalFiles = false;
};

class Viewer {
 public:
  explicit Viewer(const ViewerOptions& options);
  ~Viewer();
  // Runs until the window closes or the script quits; the exit status.
  int run();

 private:
  void loadScene(const std::string& nameOrPath, const scene::CameraPlacement& placement = {},
                 const std::string& variant = "", const scene::AnimationChoice& animation = {});
  void createTracer();
  void resizeRender();
  void applyEffect(SettingEffect effect);
  void handleInput(float seconds);
  // Double-click: look at the surface under the cursor and select its material.
  void focusOn(glm::vec2 renderPixel);
  bool stepScript();  // false once the script asked to quit
  void renderFrame();
  // Records the denoiser for this frame (if on) and returns what to show.
  const rhi::TextureHandle& recordDenoiser(rhi::ICommandList& list, size_t slot);
  void drawUi();
  void drawSceneMenu();
  void ensureDisplayTargets(uint32_t width, uint32_t height, bool capturing);
  void collectFrameStats(size_t slot);
  void recordPathTracing(rhi::ICommandList& list, size_t slot);
  void drawAlgorithmMenu();
  void drawDisplayOptions();  // the viewer's own: vsync, render scale, sample cap
  void drawMaterialMenu();
  void drawCameraMenu();
  void drawEnvironmentMenu();
  // The Environment menu's and the script's edits: "map" (a file, "none",
  // "default"), "rotation", "intensity", "background" (visible, hidden).
  void changeEnvironment(const std::string& key, const std::string& value);
  void drawStats();
  void takeScreenshot(const std::string& path);
  // The size of what is shown: the window's framebuffer, or the offscreen size.
  void targetSize(uint32_t& width, uint32_t& height) const;
  // Reads the display texture of the frame just submitted into a PNG.
  void saveCapture(const std::string& path);
  // Median GPU times over the frames shown, printed when the viewer ends.
  void printTimings() const;
  void materialsChanged();
  // Sets one parameter of the named material, as the Material menu would.
  void editMaterial(const std::string& name, const std::string& parameter,
                    const std::vector<float>& values);
  // The scene's materials as loaded with vary_/set_ applied, without the
  // Material menu's edits.
  std::vector<scene::Material> uneditedMaterials() const;

  ViewerOptions options_;
  std::unique_ptr<Window> window_;  // null offscreen
  uint32_t offscreenWidth_ = 0, offscreenHeight_ = 0;
  rhi::DeviceHandle device_;
  rhi::SwapchainHandle swapchain_;  // null offscreen
  std::unique_ptr<ImGuiRenderer> ui_;
  std::unique_ptr<render::DisplayPass> display_;
  std::vector<rhi::CommandListHandle> frameLists_;
  std::vector<render::FrameQueries> frameQueries_;  // per frame slot
  rhi::TextureHandle displayTexture_;               // tone-mapped image + UI: what the window shows
  rhi::BufferHandle captureBuffer_;                 // its readback, for capture and --record
  std::vector<std::string> pendingCaptures_;        // captures asked for this frame
  std::vector<double> tracingMs_;                   // per frame shown, for printTimings
  uint64_t frameNumber_ = 0;

  std::string sceneName_;
  std::string sceneVariant_;               // as loadScene chose it, for the screenshot's record
  scene::AnimationChoice sceneAnimation_;  // likewise
  render::EnvironmentChoice environment_;  // as the screenshot records it
  scene::Environment sceneEnvironment_;    // the scene file's own
  char environmentPath_[512] = "";
  std::string vary_, set_;  // material-test row edits, as --vary/--set
  // The materials and row as loaded: with vary_/set_ applied, what a
  // screenshot's record compares the Material menu's edits against.
  std::vector<scene::Material> loadedMaterials_;
  std::optional<scene::MaterialRow> loadedRow_;
  scene::Scene scene_;
  std::unique_ptr<render::PathTracer> tracer_;
  std::unique_ptr<render::Denoiser> denoiser_;
  // GPU time of each pass after path tracing (whose time the tracer's frame
  // queries hold), per frame slot: a slot's queries are read when the slot
  // is recorded again, once its previous frame has finished.
  enum Pass { DenoisePass, DisplayPass, UiPass, kPassCount };
  struct PassTimer {
    std::vector<rhi::TimerQueryHandle> queries;  // per frame slot
    std::vector<bool> recorded;                  // per frame slot: its query holds a frame
    double lastSeconds = 0;                      // the last frame's, 0 if the pass did not run
    std::vector<double> milliseconds;            // every frame measured, for printTimings
  };
  PassTimer passTimers_[kPassCount];
  // Reads the slot's finished queries; returns the query to record into.
  rhi::ITimerQuery* passQuery(Pass pass, size_t slot);
  uint64_t seenGeneration_ = ~0ull;  // the tracer's accumulation generation last frame
  uint32_t stillFrames_ = 0;         // frames since the image last started over
  uint32_t temporalSamples_ = 0;     // the sample sequence of the temporal denoiser's frames
  bool temporalShown_ = false;       // the denoiser output holds a temporal frame to keep showing
  ViewerSettings settings_;
  RenderScaleController scale_;
  std::unique_ptr<CameraController> camera_;
  BookmarkStore bookmarks_;

  // UI state.
  char scenePath_[512] = {};
  char bookmarkName_[64] = "view 1";
  int selectedMaterial_ = 0;
  std::string statusLine_;
  render::FrameStats lastStats_;
  double frameSeconds_ = 0;
  std::chrono::steady_clock::time_point lastFrame_;
  bool f1WasDown_ = false;
  bool homeWasDown_ = false;

  // Script state.
  std::vector<ScriptCommand> script_;
  size_t scriptPosition_ = 0;
  uint64_t waitUntilFrame_ = 0;
  bool waiting_ = false;
};

}  // namespace penumbra::viewer
