#include "viewer_app.h"

#include <fmt/format.h>
#include <imgui.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <limits>

#include "backend_factory.h"
#include "backends/imgui_impl_glfw.h"
#include "penumbra/batch/render_job.h"
#include "penumbra/batch/render_output.h"
#include "penumbra/image/image_io.h"
#include "penumbra/render/image_size.h"
#include "penumbra/rhi/fault_injection.h"
#include "penumbra/scene/material_row.h"
#include "penumbra/scene/scene_loader.h"
#include "penumbra/util/error.h"
#include "penumbra/util/log.h"
#include "picking.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace penumbra::viewer {
namespace {

// A walking speed that crosses the scene in about five seconds.
float speedForScene(const scene::Scene& scene) {
  glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
  for (const auto& instance : scene.instances)
    for (const auto& p : scene.meshes[instance.mesh].positions) {
      const glm::vec3 world(instance.transform * glm::vec4(p, 1.0f));
      lo = glm::min(lo, world);
      hi = glm::max(hi, world);
    }
  const float size = glm::length(hi - lo);
  return std::isfinite(size) && size > 0 ? size / 5.0f : 1.0f;
}

}  // namespace

Viewer::Viewer(const ViewerOptions& options)
    : options_(options),
      offscreenWidth_(options.width),
      offscreenHeight_(options.height),
      scale_(options.renderScale.value_or(1.0f), !options.renderScale.has_value()),
      bookmarks_(options.config.empty() ? BookmarkStore::defaultPath() : options.config) {
  if (!options_.offscreen)
    window_ = std::make_unique<Window>(options.width, options.height, "Penumbra viewer");
  if (!options_.recordDirectory.empty()) {
    std::error_code error;
    std::filesystem::create_directories(options_.recordDirectory, error);
    if (error)
      throw Error(fmt::format("--record {}: cannot create the directory ({})",
                              options_.recordDirectory, error.message()));
  }
  rhi::DeviceCreateInfo info = options_.device.createInfo();
  if (window_) info.presentWindow = window_->nativeWindow();
  device_ = backends::createDevice(options_.device.backend, info);

  settings_.render = options_.render;
  settings_.vsync = options_.vsync;
  settings_.renderScale = scale_.scale();
  settings_.autoRenderScale = scale_.automatic();

  rhi::SwapchainDesc swapchain;
  if (window_) {
    swapchain.window = window_->nativeWindow();
    window_->framebufferSize(swapchain.width, swapchain.height);
    swapchain.vsync = options_.vsync;
    swapchain.framesInFlight = options_.framesInFlight;
    swapchain_ = device_->createSwapchain(swapchain);
  }

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini in the working directory
  ImGui::StyleColorsDark();
  if (window_) ImGui_ImplGlfw_InitForOther(window_->handle(), true);
  ui_ = std::make_unique<ImGuiRenderer>(*device_, options_.framesInFlight);
  display_ = std::make_unique<render::DisplayPass>(*device_);
  for (uint32_t i = 0; i < options_.framesInFlight; ++i)
    frameLists_.push_back(
        device_->createCommandList(fmt::format("viewer frame {}", frameLists_.size())));

  if (!options_.script.empty()) script_ = loadScript(options_.script);
  loadScene(options_.scene, options_.camera, options_.variant, options_.animation);
  const auto& adapter = device_->adapter();
  fmt::print("device: {} ({}) via {}, {}\n", adapter.name, rhi::adapterTypeName(adapter.type),
             device_->backendName(),
             window_ ? fmt::format("{} window", rhi::windowSystemName(swapchain.window.system))
                     : fmt::format("offscreen {}x{}", offscreenWidth_, offscreenHeight_));
  std::fflush(stdout);
}

Viewer::~Viewer() {
  if (device_) device_->waitForIdle();
  ui_.reset();
  if (window_) ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
}

void Viewer::loadScene(const std::string& nameOrPath, const scene::CameraPlacement& placement,
                       const std::string& variant, const scene::AnimationChoice& animation) {
  // Throws before anything changes.
  scene::Scene scene = scene::loadScene(nameOrPath, {options_.allowExternalFiles}, {}, animation);
  scene::placeCamera(scene, placement);
  if (!variant.empty()) scene::selectMaterialVariant(scene, variant);
  const scene::Environment own = scene.environment;
  render::applyEnvironmentChoice(scene, options_.environment);
  if (device_) device_->waitForIdle();
  // The GPU side can still fail (a scene too large for the device): then the
  // previous scene comes back, so a failed load from the menu leaves a
  // working viewer with the error in its status line.
  const bool hadScene = tracer_ != nullptr;
  scene::Scene previousScene = std::move(scene_);
  std::unique_ptr<CameraController> previousCamera = std::move(camera_);
  const scene::Environment previousEnvironment = sceneEnvironment_;
  const render::EnvironmentChoice previousChoice = environment_;
  sceneEnvironment_ = own;
  environment_ = options_.environment;
  scene_ = std::move(scene);
  camera_ = std::make_unique<CameraController>(scene_.camera, speedForScene(scene_));
  try {
    createTracer();
  } catch (const Error&) {
    if (!hadScene) throw;
    scene_ = std::move(previousScene);
    camera_ = std::move(previousCamera);
    sceneEnvironment_ = previousEnvironment;
    environment_ = previousChoice;
    createTracer();  // the scene that fitted before
    throw;
  }
  sceneName_ = nameOrPath;
  sceneVariant_ = variant;
  sceneAnimation_ = animation;
  vary_ = scene_.materialRow ? scene_.materialRow->vary : "";
  set_.clear();
  loadedMaterials_ = scene_.materials;
  loadedRow_ = scene_.materialRow;
  selectedMaterial_ = 0;
  std::snprintf(scenePath_, sizeof(scenePath_), "%s", nameOrPath.c_str());
}

void Viewer::targetSize(uint32_t& width, uint32_t& height) const {
  if (window_) {
    window_->framebufferSize(width, height);
  } else {
    width = offscreenWidth_;
    height = offscreenHeight_;
  }
}

void Viewer::createTracer() {
  uint32_t w = 0, h = 0;
  targetSize(w, h);
  const RenderSize size = renderSize(std::max(w, 1u), std::max(h, 1u), scale_.scale());
  render::PipelineOptions pipeline;
  pipeline.allEffects = settings_.render.allEffects;
  // Frames in flight still use the old tracer's resources.
  device_->waitForIdle();
  tracer_.reset();
  tracer_ = std::make_unique<render::PathTracer>(*device_, scene_, size.width, size.height,
                                                 pipeline, camera_->camera());
  denoiser_.reset();  // made for the new tracer's size when first needed
  if (frameQueries_.empty())
    for (size_t i = 0; i < frameLists_.size(); ++i)
      frameQueries_.push_back(tracer_->createFrameQueries());
  for (auto& queries : frameQueries_) queries.samples = 0;  // nothing of the new tracer's yet
}

void Viewer::resizeRender() {
  uint32_t w = 0, h = 0;
  targetSize(w, h);
  if (w == 0 || h == 0) return;
  const RenderSize size = renderSize(w, h, scale_.scale());
  tracer_->resize(size.width, size.height);
}

void Viewer::applyEffect(SettingEffect effect) {
  if (swapchain_ && settings_.vsync != swapchain_->desc().vsync)
    swapchain_->setVsync(settings_.vsync);
  if (settings_.autoRenderScale != scale_.automatic())
    scale_.setAutomatic(settings_.autoRenderScale);
  switch (effect) {
    case SettingEffect::None:
      break;
    case SettingEffect::ResetAccumulation:
      tracer_->resetAccumulation();
      break;
    case SettingEffect::RebuildRenderer:
      createTracer();
      break;
    case SettingEffect::Resize:
      scale_.setScale(settings_.renderScale);
      resizeRender();
      break;
  }
}

void Viewer::handleInput(float seconds) {
  const ImGuiIO& io = ImGui::GetIO();
  if (!window_) return;  // offscreen: the script is the only input
  CameraInput input;
  GLFWwindow* w = window_->handle();
  // F1 shows and hides the menus (on the key going down, not while held).
  const bool f1 = glfwGetKey(w, GLFW_KEY_F1) == GLFW_PRESS;
  if (f1 && !f1WasDown_) settings_.showUi = !settings_.showUi;
  f1WasDown_ = f1;
  // Home on the key going down, polled like F1 (sticky keys keep a tap):
  // ImGui 1.86 loses a tap that begins and ends between two frames.
  const bool home = glfwGetKey(w, GLFW_KEY_HOME) == GLFW_PRESS;
  const bool homePressed = home && !homeWasDown_;
  homeWasDown_ = home;
  if (!io.WantCaptureKeyboard) {
    auto key = [&](int k) { return glfwGetKey(w, k) == GLFW_PRESS ? 1.0f : 0.0f; };
    input.move = {key(GLFW_KEY_D) - key(GLFW_KEY_A), key(GLFW_KEY_E) - key(GLFW_KEY_Q),
                  key(GLFW_KEY_W) - key(GLFW_KEY_S)};
    if (homePressed) {
      camera_->reset();
      tracer_->setCamera(camera_->camera());
    }
  }
  if (!io.WantCaptureMouse) {
    if (io.MouseDown[0]) input.turn = {io.MouseDelta.x, io.MouseDelta.y};
    input.scrollSteps = io.MouseWheel;
    if (ImGui::IsMouseDoubleClicked(0) && io.DisplaySize.x > 0 && io.DisplaySize.y > 0) {
      const glm::vec2 pixel(io.MousePos.x / io.DisplaySize.x * float(tracer_->width()),
                            io.MousePos.y / io.DisplaySize.y * float(tracer_->height()));
      focusOn(pixel);
    }
  }
  if (camera_->update(input, seconds)) tracer_->setCamera(camera_->camera());
}

void Viewer::focusOn(glm::vec2 renderPixel) {
  const Ray ray = cameraRay(camera_->camera(), tracer_->width(), tracer_->height(), renderPixel);
  const auto hit = pick(*tracer_, scene_, ray);
  if (!hit) {
    statusLine_ = "nothing under the cursor";
    return;
  }
  camera_->focusOn(hit->position);
  tracer_->setCamera(camera_->camera());
  selectedMaterial_ = int(hit->material);
  statusLine_ = fmt::format("focus: {} ({}), {:.3f} m away", hit->object,
                            scene_.materials[hit->material].name, hit->distance);
}

bool Viewer::stepScript() {
  using Kind = ScriptCommand::Kind;
  while (scriptPosition_ < script_.size()) {
    const ScriptCommand& c = script_[scriptPosition_];
    try {
      switch (c.kind) {
        case Kind::WaitFrames:
          if (!waiting_) {
            waitUntilFrame_ = frameNumber_ + uint64_t(c.numbers[0]);
            waiting_ = true;
          }
          if (frameNumber_ < waitUntilFrame_) return true;
          waiting_ = false;
          break;
        case Kind::WaitSamples:
          if (tracer_->accumulatedSamples() < uint32_t(c.numbers[0])) return true;
          break;
        case Kind::Move:
          camera_->move({c.numbers[0], c.numbers[1], c.numbers[2]});
          tracer_->setCamera(camera_->camera());
          break;
        case Kind::Turn:
          camera_->turn(c.numbers[0], c.numbers[1]);
          tracer_->setCamera(camera_->camera());
          break;
        case Kind::ResetCamera:
          camera_->reset();
          tracer_->setCamera(camera_->camera());
          break;
        case Kind::Set:
          applyEffect(applySetting(settings_, c.args[0], c.args[1]));
          break;
        case Kind::Scene:
          loadScene(c.args[0]);
          break;
        case Kind::InjectFault:
          rhi::faults::arm(c.args[0] == "submit" ? rhi::faults::Site::Submit
                                                 : rhi::faults::Site::Allocation,
                           std::stoul(c.args[1]));
          break;
        case Kind::WindowSize:
          if (window_) {
            glfwSetWindowSize(window_->handle(), int(c.numbers[0]), int(c.numbers[1]));
          } else if (render::isValidImageSize(uint32_t(c.numbers[0]), uint32_t(c.numbers[1]))) {
            offscreenWidth_ = uint32_t(c.numbers[0]);
            offscreenHeight_ = uint32_t(c.numbers[1]);
            resizeRender();
          } else {
            throw Error(fmt::format("window-size {}x{}: outside the image size limit", c.numbers[0],
                                    c.numbers[1]));
          }
          break;
        case Kind::Material:
          editMaterial(c.args[0], c.args[1], c.numbers);
          break;
        case Kind::Environment:
          changeEnvironment(c.args[0], c.args[1]);
          break;
        case Kind::Screenshot:
          takeScreenshot(c.args[0]);
          break;
        case Kind::Capture:
          // Written once this frame is rendered: the step ends here, so the
          // frame shows the script's state up to this line and no further.
          if (image::formatFromPath(c.args[0]) != image::FileFormat::Png)
            throw Error(fmt::format("capture {}: a capture is a .png", c.args[0]));
          image::checkWritable(c.args[0]);
          pendingCaptures_.push_back(c.args[0]);
          ++scriptPosition_;
          return true;
        case Kind::Quit:
          return false;
      }
    } catch (const Error& e) {
      throw Error(fmt::format("{}:{}: {}", options_.script, c.line, e.what()));
    }
    ++scriptPosition_;
  }
  return true;
}

void Viewer::changeEnvironment(const std::string& key, const std::string& value) {
  render::EnvironmentChoice choice = environment_;
  scene::Environment& env = scene_.environment;
  if (key == "map") {
    // A new map starts unrotated at intensity 1, as --env FILE alone would.
    choice = render::EnvironmentChoice{};
    choice.map = value;
    scene::Environment chosen = render::chooseEnvironment(sceneEnvironment_, scene_, choice);
    tracer_->setEnvironment(chosen);  // validates before anything changes
    env = std::move(chosen);
    environment_ = choice;
    statusLine_ = env.present() ? fmt::format("environment: {}", env.source) : "environment: none";
    return;
  }
  if (!env.present())
    throw Error(fmt::format("environment {}: there is no environment (environment map FILE)", key));
  // The rest moves the map uploaded without copying it: the sliders call
  // this every tick.
  float rotation = env.rotationDegrees, intensity = env.intensity;
  bool background = env.visibleBackground;
  if (key == "rotation" || key == "intensity") {
    float number = 0.0f;
    try {
      size_t used = 0;
      number = std::stof(value, &used);
      if (used != value.size()) throw std::invalid_argument(value);
    } catch (const std::exception&) {
      throw Error(fmt::format("environment {}: '{}' is not a number", key, value));
    }
    (key == "rotation" ? choice.rotationDegrees : choice.intensity) = number;
    (key == "rotation" ? rotation : intensity) = number;
  } else if (key == "background") {
    if (value != "visible" && value != "hidden")
      throw Error(fmt::format("environment background: '{}' (visible, hidden)", value));
    choice.visibleBackground = background = value == "visible";
  } else {
    throw Error(fmt::format(
        "environment: unknown setting '{}' (map, rotation, intensity, background)", key));
  }
  tracer_->setEnvironmentPlacement(rotation, intensity, background);  // validates first
  env.rotationDegrees = rotation;
  env.intensity = intensity;
  env.visibleBackground = background;
  environment_ = choice;
  statusLine_ = fmt::format("environment: {}", env.source);
}

void Viewer::takeScreenshot(const std::string& path) {
  image::checkWritable(path);
  render::saveRender(*tracer_, tracer_->accumulation(), path, settings_.render.toneMapping);
  const std::string record = std::filesystem::path(path).replace_extension(".json").string();
  const RenderSize size{tracer_->width(), tracer_->height()};
  // The record holds the scene by name, the material-test row as --vary/--set
  // and the Material menu's edits as overrides on top of both.
  render::RenderJob job = makeRenderJob(settings_, sceneName_, vary_, set_, camera_->camera(), size,
                                        tracer_->accumulatedSamples());
  job.variant = sceneVariant_;
  job.animation = sceneAnimation_;
  job.materials = render::materialOverrides(uneditedMaterials(), scene_.materials);
  job.environment = environment_;
  render::saveRenderJob(record, job);
  statusLine_ =
      fmt::format("saved {} and {} ({} spp)", path, record, tracer_->accumulatedSamples());
  fmt::print("screenshot: {} ({}x{}, {} spp), settings {}\n", path, size.width, size.height,
             tracer_->accumulatedSamples(), record);
  std::fflush(stdout);
}

void Viewer::editMaterial(const std::string& name, const std::string& parameter,
                          const std::vector<float>& values) {
  auto& materials = scene_.materials;
  const auto found = std::find_if(materials.begin(), materials.end(),
                                  [&](const scene::Material& m) { return m.name == name; });
  if (found == materials.end())
    throw Error(fmt::format("scene '{}' has no material '{}'", sceneName_, name));
  render::setEditableParameter(*found, parameter, values);
  selectedMaterial_ = int(found - materials.begin());
  materialsChanged();  // resets accumulation
}

std::vector<scene::Material> Viewer::uneditedMaterials() const {
  scene::Scene loaded;
  loaded.name = scene_.name;
  loaded.materials = loadedMaterials_;
  loaded.materialRow = loadedRow_;
  // As penumbra render does: the row's --vary/--set on the scene as loaded.
  if (!vary_.empty() || !set_.empty()) scene::changeMaterialRow(loaded, vary_, set_);
  return loaded.materials;
}

// The display image (and the capture buffer screenshots read) at the
// framebuffer's size.
void Viewer::ensureDisplayTargets(uint32_t w, uint32_t h, bool capturing) {
  if (!displayTexture_ || displayTexture_->desc().width != w ||
      displayTexture_->desc().height != h) {
    device_->waitForIdle();  // frames in flight draw into the old one
    rhi::TextureDesc desc;
    desc.width = w;
    desc.height = h;
    desc.format = rhi::Format::RGBA8_UNORM;
    desc.usage = rhi::TextureUsage::Storage | rhi::TextureUsage::RenderTarget |
                 rhi::TextureUsage::CopySource;
    desc.debugName = "display";
    displayTexture_ = device_->createTexture(desc);
    captureBuffer_.reset();
  }
  if (capturing && !captureBuffer_) {
    rhi::BufferDesc desc;
    desc.byteSize = uint64_t(w) * h * 4;
    desc.usage = rhi::BufferUsage::CopyDest;
    desc.memory = rhi::MemoryLocation::Readback;
    desc.debugName = "display capture";
    captureBuffer_ = device_->createBuffer(desc);
  }
}

// The statistics of the frame this slot held last: its GPU has finished it
// (the slot's list was just opened).
void Viewer::collectFrameStats(size_t slot) {
  if (frameQueries_[slot].samples > 0) {
    lastStats_ = tracer_->frameStats(frameQueries_[slot]);
    tracingMs_.push_back(lastStats_.gpuSeconds * 1e3);
  }
  frameQueries_[slot].samples = 0;
  for (PassTimer& timer : passTimers_) {
    if (timer.queries.size() != frameLists_.size()) {
      timer.recorded.assign(frameLists_.size(), false);
      timer.queries.clear();
      for (size_t i = 0; i < frameLists_.size(); ++i)
        timer.queries.push_back(device_->createTimerQuery());
    }
    if (timer.recorded[slot]) {
      timer.lastSeconds = device_->timerQuerySeconds(timer.queries[slot].get());
      timer.milliseconds.push_back(timer.lastSeconds * 1e3);
    }
    timer.recorded[slot] = false;
  }
}

// The path tracer's frame: the guide buffers and the temporal denoiser's
// sample sequence decided, then the frame recorded.
void Viewer::recordPathTracing(rhi::ICommandList& list, size_t slot) {
  // The temporal denoiser integrates frames itself: until its history is
  // full, each frame starts a new mean; then the tracer accumulates.
  // The guide buffers cost about a tenth of a frame: written only while the
  // denoiser or a guide view reads them, and a change starts a new mean, so
  // that they always hold every sample of it.
  const bool guidesRead = render::denoises(settings_.render) || settings_.view != ViewBuffer::Image;
  if (guidesRead != settings_.render.tracer.writeGuides) {
    settings_.render.tracer.writeGuides = guidesRead;
    tracer_->resetAccumulation();
  }
  const bool startedOver = tracer_->accumulationGeneration() != seenGeneration_;
  if (startedOver) stillFrames_ = 0;
  const bool denoising = render::denoises(settings_.render);
  const render::DenoiserSettings defaults;
  if (denoising && settings_.render.denoiser.mode == render::DenoiseMode::Svgf &&
      stillFrames_ < defaults.maxHistory) {
    // New samples every frame, also across camera moves (which start the
    // sequence over), or the history would integrate the same noise.
    tracer_->startNewMean(temporalSamples_);
    temporalSamples_ += settings_.render.sppPerFrame;
  }
  seenGeneration_ = tracer_->accumulationGeneration();
  if (settings_.maxSamples == 0 || tracer_->accumulatedSamples() < settings_.maxSamples)
    tracer_->recordFrame(list, settings_.render.tracer, settings_.render.sppPerFrame,
                         frameQueries_[slot]);
  stillFrames_ += 1;
}

void Viewer::renderFrame() {
  uint32_t w = 0, h = 0;
  targetSize(w, h);
  if (w == 0 || h == 0) {  // minimised: nothing to present to
    glfwWaitEventsTimeout(0.1);
    return;
  }
  if (swapchain_ && (w != swapchain_->desc().width || h != swapchain_->desc().height)) {
    swapchain_->resize(w, h);
    resizeRender();
  }
  if (swapchain_) {
    w = swapchain_->desc().width;
    h = swapchain_->desc().height;
  }
  const bool capturing = !pendingCaptures_.empty() || !options_.recordDirectory.empty();
  ensureDisplayTargets(w, h, capturing);
  rhi::ITexture* backBuffer = nullptr;
  if (swapchain_) {
    backBuffer = swapchain_->acquireNextImage();
    if (!backBuffer) {
      swapchain_->resize(w, h);
      return;
    }
  }
  // One list per frame slot: open() waits for the slot's previous frame,
  // whose statistics are then ready. Path tracing, display and UI go into
  // the same list, so the CPU runs up to framesInFlight frames ahead.
  const size_t slot = frameNumber_ % frameLists_.size();
  auto& list = *frameLists_[slot];
  list.open();
  collectFrameStats(slot);

  recordPathTracing(list, slot);
  const rhi::TextureHandle& shown = recordDenoiser(list, slot);
  const render::DisplayChannels channels =
      settings_.view == ViewBuffer::Normal || settings_.view == ViewBuffer::Motion
          ? render::DisplayChannels::Signed
      : settings_.view == ViewBuffer::Depth ? render::DisplayChannels::Alpha
                                            : render::DisplayChannels::Color;
  rhi::ITimerQuery* displayQuery = passQuery(DisplayPass, slot);
  list.beginTimerQuery(displayQuery);
  display_->record(list, shown, displayTexture_, settings_.render.toneMapping, channels);
  list.endTimerQuery(displayQuery);
  if (settings_.showUi) {
    rhi::ITimerQuery* uiQuery = passQuery(UiPass, slot);
    list.beginTimerQuery(uiQuery);
    ui_->render(list, *displayTexture_);
    list.endTimerQuery(uiQuery);
  } else {
    passTimers_[UiPass].lastSeconds = 0;
  }
  if (capturing) list.copyTextureToBuffer(displayTexture_.get(), captureBuffer_.get());
  if (backBuffer) {
    list.copyTexture(backBuffer, displayTexture_.get());
    list.setTextureState(backBuffer, rhi::ResourceState::Present);
  }
  list.close();
  if (!swapchain_) {
    device_->submit(&list);
  } else if (!swapchain_->present(&list)) {
    swapchain_->resize(w, h);
  }
  if (capturing) {
    device_->waitForIdle();
    for (const auto& path : pendingCaptures_) saveCapture(path);
    pendingCaptures_.clear();
    if (!options_.recordDirectory.empty())
      saveCapture(fmt::format("{}/frame-{:06}.png", options_.recordDirectory, frameNumber_));
  }
}

rhi::ITimerQuery* Viewer::passQuery(Pass pass, size_t slot) {
  passTimers_[pass].recorded[slot] = true;
  return passTimers_[pass].queries[slot].get();
}

void Viewer::saveCapture(const std::string& path) {
  const auto& d = displayTexture_->desc();
  image::Image8 shown;
  shown.width = d.width;
  shown.height = d.height;
  shown.rgba.resize(size_t(d.width) * d.height * 4);
  std::memcpy(shown.rgba.data(), captureBuffer_->mappedData(), shown.rgba.size());
  for (size_t i = 3; i < shown.rgba.size(); i += 4) shown.rgba[i] = 255;  // the window is opaque
  image::savePng(path, shown);
  fmt::print("capture: {} ({}x{})\n", path, d.width, d.height);
  std::fflush(stdout);
}

void Viewer::printTimings() const {
  auto median = [](std::vector<double> v) {
    if (v.empty()) return 0.0;
    std::nth_element(v.begin(), v.begin() + long(v.size() / 2), v.end());
    return v[v.size() / 2];
  };
  auto pass = [&](const char* name, const std::vector<double>& ms) {
    return fmt::format("{} {:.3f} ms/frame (median of {})", name, median(ms), ms.size());
  };
  fmt::print("timings: {} frames; {}; {}; {}; {}\n", frameNumber_, pass("path tracing", tracingMs_),
             pass("denoiser", passTimers_[DenoisePass].milliseconds),
             pass("display", passTimers_[DisplayPass].milliseconds),
             pass("UI", passTimers_[UiPass].milliseconds));
  std::fflush(stdout);
}

const rhi::TextureHandle& Viewer::recordDenoiser(rhi::ICommandList& list, size_t slot) {
  const bool denoising = render::denoises(settings_.render);
  if (denoising || settings_.view == ViewBuffer::Motion) {
    if (!denoiser_ || denoiser_->width() != tracer_->width() ||
        denoiser_->height() != tracer_->height()) {
      device_->waitForIdle();  // frames in flight still use the old one's textures
      denoiser_.reset();
      denoiser_ = std::make_unique<render::Denoiser>(*device_, tracer_->width(), tracer_->height());
    }
  }
  render::DenoiserSettings d;
  d.fireflyClamp = settings_.render.denoiser.fireflyClamp;
  const uint32_t samples = tracer_->accumulatedSamples();
  bool denoised = false;
  if (denoising && samples > 0) {
    const bool temporal =
        settings_.render.denoiser.mode == render::DenoiseMode::Svgf && stillFrames_ <= d.maxHistory;
    // Once still, the accumulation takes over from the temporal history when
    // it holds more samples than the history did; until then the last
    // temporal frame stays on screen.
    const bool accumulationAhead = samples >= d.maxHistory * settings_.render.sppPerFrame;
    if (temporal) {
      d.mode = render::DenoiseMode::Svgf;
      denoiser_->record(list, *tracer_, tracer_->camera(), samples, d,
                        passQuery(DenoisePass, slot));
      temporalShown_ = true;
      denoised = true;
    } else if (settings_.render.denoiser.mode == render::DenoiseMode::Atrous || accumulationAhead ||
               !temporalShown_) {
      d.mode = render::DenoiseMode::Atrous;
      denoiser_->record(list, *tracer_, tracer_->camera(), samples, d,
                        passQuery(DenoisePass, slot));
      temporalShown_ = false;
      denoised = true;
    } else {
      denoised = true;  // the last temporal frame, kept
    }
  } else {
    temporalShown_ = false;
  }
  if (!denoised) passTimers_[DenoisePass].lastSeconds = 0;
  const auto& g = tracer_->guides();
  switch (settings_.view) {
    case ViewBuffer::Image:
      break;
    case ViewBuffer::Albedo:
      return g.albedo;
    case ViewBuffer::Normal:
      return g.normalDepth;
    case ViewBuffer::Depth:
      return g.normalDepth;
    case ViewBuffer::Emission:
      return g.emission;
    case ViewBuffer::Motion:
      return denoiser_->motion();
  }
  return denoised ? denoiser_->output() : tracer_->accumulation();
}

int Viewer::run() {
  lastFrame_ = std::chrono::steady_clock::now();
  bool quit = false;
  while (!quit && !(window_ && window_->shouldClose())) {
    if (window_) glfwPollEvents();
    const auto now = std::chrono::steady_clock::now();
    frameSeconds_ = std::chrono::duration<double>(now - lastFrame_).count();
    lastFrame_ = now;
    if (frameNumber_ > 0 && scale_.update(frameSeconds_)) {
      settings_.renderScale = scale_.scale();
      resizeRender();
    }

    if (window_) {
      ImGui_ImplGlfw_NewFrame();
    } else {  // what the GLFW backend would set from the window
      uint32_t w = 0, h = 0;
      targetSize(w, h);
      ImGuiIO& io = ImGui::GetIO();
      io.DisplaySize = ImVec2(float(w), float(h));
      io.DeltaTime = float(std::max(frameSeconds_, 1e-6));
    }
    ImGui::NewFrame();
    handleInput(float(frameSeconds_));
    drawUi();
    ImGui::Render();
    quit = !stepScript();
    if (quit) break;
    renderFrame();
    ++frameNumber_;
  }
  device_->waitForIdle();
  printTimings();
  if (options_.device.validation && device_->validationMessageCount() > 0) {
    log::error("{} validation message(s)", device_->validationMessageCount());
    return 1;
  }
  return 0;
}

}  // namespace penumbra::viewer
