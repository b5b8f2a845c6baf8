// The viewer's Dear ImGui menus: scene, camera, algorithm, material, stats.
#include <fmt/format.h>
#include <imgui.h>

#include <algorithm>

#include "penumbra/batch/render_job.h"
#include "penumbra/render/effect_set.h"
#include "penumbra/scene/material_row.h"
#include "penumbra/scene/scene_loader.h"
#include "penumbra/util/error.h"
#include "viewer_app.h"

namespace penumbra::viewer {
namespace {

// Combo over named values; returns whether the selection changed.
template <class T, class NameOf>
bool enumCombo(const char* label, T& value, const std::vector<T>& values, NameOf nameOf) {
  bool changed = false;
  if (ImGui::BeginCombo(label, nameOf(value))) {
    for (const T& v : values) {
      if (ImGui::Selectable(nameOf(v), v == value) && v != value) {
        value = v;
        changed = true;
      }
    }
    ImGui::EndCombo();
  }
  return changed;
}

// The widget a table setting asks for; true when it changed the value.
bool settingWidget(const render::Setting& setting, render::RenderSettings& settings) {
  const std::string label(setting.label);
  const double before = setting.get(settings);
  double value = before;
  switch (setting.widget) {
    case render::SettingWidget::None:
      return false;
    case render::SettingWidget::Checkbox: {
      bool on = value != 0.0;
      if (ImGui::Checkbox(label.c_str(), &on)) value = on ? 1.0 : 0.0;
      break;
    }
    case render::SettingWidget::Slider: {
      int v = int(value);
      if (ImGui::SliderInt(label.c_str(), &v, int(setting.widgetMin), int(setting.widgetMax)))
        value = double(v);
      break;
    }
    case render::SettingWidget::Drag: {
      float v = float(value);
      if (ImGui::DragFloat(label.c_str(), &v, setting.widgetStep, setting.widgetMin,
                           setting.widgetMax))
        value = double(v);
      break;
    }
    case render::SettingWidget::Input: {
      int v = int(value);
      if (ImGui::InputInt(label.c_str(), &v) && v >= 0) value = double(v);
      break;
    }
    case render::SettingWidget::Combo: {
      const size_t current = size_t(value);
      if (ImGui::BeginCombo(label.c_str(), std::string(setting.choices[current]).c_str())) {
        for (size_t i = 0; i < setting.choices.size(); ++i)
          if (ImGui::Selectable(std::string(setting.choices[i]).c_str(), i == current))
            value = double(i);
        ImGui::EndCombo();
      }
      break;
    }
  }
  // Widgets may offer values past the accepted range (a dragged float):
  // what the table refuses is not set.
  if (value == before || !setting.accepts(value)) return false;
  setting.set(settings, value);
  return true;
}

}  // namespace

void Viewer::drawUi() {
  if (!settings_.showUi) return;
  ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(320, 0), ImGuiCond_FirstUseEver);
  ImGui::Begin("Penumbra");
  try {
    if (ImGui::CollapsingHeader("Scene", ImGuiTreeNodeFlags_DefaultOpen)) drawSceneMenu();
    if (ImGui::CollapsingHeader("Camera")) drawCameraMenu();
    if (ImGui::CollapsingHeader("Environment")) drawEnvironmentMenu();
    if (ImGui::CollapsingHeader("Algorithm")) drawAlgorithmMenu();
    if (ImGui::CollapsingHeader("Material")) drawMaterialMenu();
  } catch (const Error& e) {
    // A bad scene path or edit is reported in the window, not fatal.
    statusLine_ = e.what();
  }
  if (!statusLine_.empty()) ImGui::TextWrapped("%s", statusLine_.c_str());
  ImGui::End();
  drawStats();
}

void Viewer::drawSceneMenu() {
  static const std::vector<std::string> builtIn = scene::builtInSceneNames();
  if (ImGui::BeginCombo("built-in", sceneName_.c_str())) {
    for (const auto& name : builtIn)
      if (ImGui::Selectable(name.c_str(), name == sceneName_)) loadScene(name);
    ImGui::EndCombo();
  }
  ImGui::InputText("file", scenePath_, sizeof(scenePath_));
  ImGui::SameLine();
  if (ImGui::Button("Open")) loadScene(scenePath_);
  static char shotPath[256] = "penumbra-screenshot.exr";
  ImGui::InputText("##shot", shotPath, sizeof(shotPath));
  ImGui::SameLine();
  if (ImGui::Button("Screenshot")) takeScreenshot(shotPath);
}

void Viewer::drawCameraMenu() {
  const scene::Camera& c = camera_->camera();
  ImGui::Text("position %.3f %.3f %.3f", c.position.x, c.position.y, c.position.z);
  float speed = camera_->speed();
  if (ImGui::DragFloat("speed (m/s)", &speed, 0.01f, 0.001f, 1000.0f, "%.3f",
                       ImGuiSliderFlags_Logarithmic))
    camera_->setSpeed(speed);
  if (ImGui::Button("Reset to scene camera (Home)")) {
    camera_->reset();
    tracer_->setCamera(camera_->camera());
  }
  scene::Camera lens = c;
  bool orthographic = lens.orthographic();
  bool lensChanged = ImGui::Checkbox("orthographic", &orthographic);
  if (lensChanged)
    lens.orthographicHeight =
        orthographic ? scene::orthographicHeightAt(lens, lens.focusDistance) : 0.0f;
  if (lens.orthographic())
    lensChanged |= ImGui::DragFloat("view height (m)", &lens.orthographicHeight, 0.01f, 0.001f,
                                    1e5f, "%.3f", ImGuiSliderFlags_Logarithmic);
  else
    lensChanged |= ImGui::DragFloat("vertical field of view (deg)", &lens.verticalFovDegrees, 0.1f,
                                    1.0f, 170.0f, "%.1f");
  lensChanged |=
      ImGui::DragFloat("aperture radius (m)", &lens.apertureRadius, 0.0005f, 0.0f, 1.0f, "%.4f");
  lensChanged |= ImGui::DragFloat("focus distance (m)", &lens.focusDistance, 0.01f, 0.001f, 1e5f,
                                  "%.3f", ImGuiSliderFlags_Logarithmic);
  int blades = int(lens.apertureBlades);
  if (ImGui::SliderInt("aperture blades (0: round)", &blades, 0, 12)) {
    lens.apertureBlades = blades > 0 && blades < 3 ? 3u : uint32_t(blades);
    lensChanged = true;
  }
  if (lensChanged) {
    camera_->setCamera(lens);
    tracer_->setCamera(lens);
  }
  ImGui::TextDisabled("WASD move, Q/E down/up, drag to look, wheel: speed (orthographic: zoom)");
  ImGui::TextDisabled("double-click: look at that surface, focus on it, select its material");
  ImGui::Separator();
  ImGui::InputText("##bookmark", bookmarkName_, sizeof(bookmarkName_));
  ImGui::SameLine();
  if (ImGui::Button("Save bookmark"))
    bookmarks_.save(sceneName_, {bookmarkName_, camera_->camera()});
  for (const auto& b : bookmarks_.list(sceneName_)) {
    ImGui::PushID(b.name.c_str());
    if (ImGui::Button(b.name.c_str())) {
      camera_->setCamera(b.camera);
      tracer_->setCamera(camera_->camera());
    }
    ImGui::SameLine();
    if (ImGui::SmallButton("x")) bookmarks_.remove(sceneName_, b.name);
    ImGui::PopID();
  }
  ImGui::TextDisabled("bookmarks: %s", bookmarks_.path().c_str());
}

void Viewer::drawEnvironmentMenu() {
  const scene::Environment& env = scene_.environment;
  ImGui::Text("%s", env.present()
                        ? fmt::format("{} ({}x{})", env.source, env.width, env.height).c_str()
                        : "none");
  // The menu's edits go through changeEnvironment, as a script's do; a bad
  // file shows its error in the status line instead of ending the session.
  auto change = [&](const std::string& key, const std::string& value) {
    try {
      changeEnvironment(key, value);
    } catch (const Error& e) {
      statusLine_ = e.what();
    }
  };
  ImGui::InputText("##envpath", environmentPath_, sizeof(environmentPath_));
  ImGui::SameLine();
  if (ImGui::Button("Load .exr/.hdr")) change("map", environmentPath_);
  if (ImGui::Button("Default studio")) change("map", "default");
  ImGui::SameLine();
  if (ImGui::Button("None")) change("map", "none");
  if (!env.present()) return;
  float rotation = env.rotationDegrees;
  if (ImGui::SliderFloat("rotation (deg)", &rotation, -180.0f, 180.0f, "%.1f"))
    change("rotation", fmt::format("{}", rotation));
  float intensity = env.intensity;
  if (ImGui::DragFloat("intensity", &intensity, 0.01f, 0.0f, 1000.0f, "%.3f",
                       ImGuiSliderFlags_Logarithmic))
    change("intensity", fmt::format("{}", intensity));
  bool background = env.visibleBackground;
  if (ImGui::Checkbox("visible background", &background))
    change("background", background ? "visible" : "hidden");
}

void Viewer::drawAlgorithmMenu() {
  // The settings table's widgets (batch/render_settings.h), group by group;
  // the viewer's own display settings follow the table's display group.
  auto& r = settings_.render;
  std::optional<render::SettingGroup> group;
  auto endGroup = [&](render::SettingGroup ended) {
    if (ended == render::SettingGroup::Denoiser)
      enumCombo("view", settings_.view, allViewBuffers(), &viewBufferName);
    if (ended == render::SettingGroup::Display) drawDisplayOptions();
  };
  for (const render::Setting& setting : render::renderSettingsTable()) {
    if (setting.widget == render::SettingWidget::None) continue;
    if (setting.pathTracerOnly && r.tracer.integrator != render::Integrator::Path) continue;
    if (group != setting.group) {
      if (group) {
        endGroup(*group);
        ImGui::Separator();
      }
      group = setting.group;
      if (*group == render::SettingGroup::Pipeline) {
        std::string effects;
        for (const auto& name : render::effectNames(tracer_->pipelineEffects()))
          effects += (effects.empty() ? "" : ", ") + name;
        ImGui::TextWrapped("pipeline effects: %s", effects.empty() ? "none" : effects.c_str());
      }
    }
    const bool disabled =
        setting.key == "fireflyClamp" && r.denoiser.mode == render::DenoiseMode::Off;
    ImGui::BeginDisabled(disabled);
    if (settingWidget(setting, r)) applyEffect(settingEffect(setting.change));
    ImGui::EndDisabled();
  }
  if (group) endGroup(*group);
}

void Viewer::drawDisplayOptions() {
  if (ImGui::Checkbox("vsync", &settings_.vsync)) applyEffect(SettingEffect::None);
  if (ImGui::Checkbox("auto render scale", &settings_.autoRenderScale))
    applyEffect(SettingEffect::None);
  ImGui::BeginDisabled(settings_.autoRenderScale);
  float scale = scale_.scale();
  if (ImGui::SliderFloat("render scale", &scale, RenderScaleController::kMinScale,
                         RenderScaleController::kMaxScale, "%.3f")) {
    settings_.renderScale = scale;
    applyEffect(SettingEffect::Resize);
  }
  ImGui::EndDisabled();
  int cap = int(settings_.maxSamples);
  if (ImGui::InputInt("stop at spp (0 = never)", &cap) && cap >= 0)
    settings_.maxSamples = uint32_t(cap);
}

void Viewer::materialsChanged() {
  if (tracer_->updateMaterials(scene_.materials))
    statusLine_ = "pipeline rebuilt for the new effects";
}

void Viewer::drawMaterialMenu() {
  auto& materials = scene_.materials;
  if (materials.empty()) return;
  selectedMaterial_ = std::clamp(selectedMaterial_, 0, int(materials.size()) - 1);
  if (ImGui::BeginCombo("material", materials[size_t(selectedMaterial_)].name.c_str())) {
    for (int i = 0; i < int(materials.size()); ++i)
      if (ImGui::Selectable(fmt::format("{}##{}", materials[size_t(i)].name, i).c_str(),
                            i == selectedMaterial_))
        selectedMaterial_ = i;
    ImGui::EndCombo();
  }
  auto& m = materials[size_t(selectedMaterial_)];
  bool changed = ImGui::ColorEdit3("base color", &m.baseColor.x);
  if (m.model == scene::MaterialModel::Phong) {
    changed |= ImGui::SliderFloat("ks", &m.ks, 0, 1);
    changed |=
        ImGui::SliderFloat("exponent", &m.exponent, 1, 1000, "%.0f", ImGuiSliderFlags_Logarithmic);
    changed |= ImGui::SliderFloat("reflectivity", &m.reflectivity, 0, 1);
    changed |= ImGui::SliderFloat("transparency", &m.transparency, 0, 1);
    changed |= ImGui::SliderFloat("ior", &m.ior, 1, 3);
    // 20 / Abbe number (KHR_materials_dispersion); a refracting volume only.
    changed |= ImGui::SliderFloat("dispersion", &m.dispersion, 0, 2);
  } else {
    for (auto [label, field] : {std::pair{"metallic", &m.metallic},
                                {"roughness", &m.roughness},
                                {"anisotropic", &m.anisotropic},
                                {"specular", &m.specular},
                                {"specular tint", &m.specularTint},
                                {"sheen", &m.sheen},
                                {"sheen tint", &m.sheenTint},
                                {"sheen roughness (glTF)", &m.sheenRoughness},
                                {"clearcoat", &m.clearcoat},
                                {"clearcoat gloss", &m.clearcoatGloss},
                                {"transmission", &m.specTrans},
                                {"diffuse transmission", &m.diffuseTransmission},
                                {"subsurface", &m.subsurface},
                                {"anisotropy strength (glTF)", &m.anisotropyStrength}})
      changed |= ImGui::SliderFloat(label, field, 0, 1);
    // Radians, counter-clockwise from the tangent (KHR_materials_anisotropy).
    changed |= ImGui::SliderAngle("anisotropy rotation", &m.anisotropyRotation, -180.0f, 180.0f);
    changed |= ImGui::SliderFloat("ior", &m.ior, 1, 3);
    // A thin film (KHR_materials_iridescence); its thickness in nm is the
    // glTF maximum, the one used without a thickness texture.
    changed |= ImGui::SliderFloat("iridescence", &m.iridescence, 0, 1);
    changed |= ImGui::SliderFloat("film ior", &m.iridescenceIor, 1, 3);
    changed |= ImGui::SliderFloat("film thickness (nm)", &m.iridescenceThicknessMaximum, 0, 1200);
    // F0 = 0.08 specular x specularColor, clamped to 1: the colour may pass 1.
    changed |= ImGui::ColorEdit3("specular color", &m.specularColor.x,
                                 ImGuiColorEditFlags_Float | ImGuiColorEditFlags_HDR);
    changed |= ImGui::ColorEdit3("sheen color", &m.sheenColor.x);
    changed |= ImGui::ColorEdit3("diffuse transmission color", &m.diffuseTransmissionColor.x);
    // Typed or dragged values stay within what the scene accepts
    // (scene::validate): a record of them renders again.
    m.specularColor = glm::max(m.specularColor, glm::vec3(0.0f));
    m.sheenColor = glm::clamp(m.sheenColor, 0.0f, 1.0f);
    m.diffuseTransmissionColor = glm::clamp(m.diffuseTransmissionColor, 0.0f, 1.0f);
    m.iridescence = std::clamp(m.iridescence, 0.0f, 1.0f);
    m.iridescenceIor = std::clamp(m.iridescenceIor, 1.0f, 4.0f);
    m.dispersion = std::clamp(m.dispersion, 0.0f, 10.0f);
    m.iridescenceThicknessMaximum = std::clamp(m.iridescenceThicknessMaximum, 0.0f, 1e5f);
  }
  ImGui::TextDisabled("emission is fixed (emitters are tabulated when the scene loads)");
  if (changed) materialsChanged();

  if (scene_.materialRow) {
    ImGui::Separator();
    ImGui::TextUnformatted("material-test row");
    std::string vary = vary_;
    if (ImGui::BeginCombo("varied parameter", vary.c_str())) {
      for (const auto& name : scene::variableDisneyParameters())
        if (ImGui::Selectable(name.c_str(), name == vary)) vary = name;
      ImGui::EndCombo();
    }
    auto& base = scene_.materialRow->base;
    glm::vec3 color = base.baseColor;
    float metallic = base.metallic, roughness = base.roughness, specTrans = base.specTrans;
    bool rowChanged = vary != vary_;
    rowChanged |= ImGui::ColorEdit3("row base color", &color.x);
    rowChanged |= ImGui::SliderFloat("row metallic", &metallic, 0, 1);
    rowChanged |= ImGui::SliderFloat("row roughness", &roughness, 0, 1);
    rowChanged |= ImGui::SliderFloat("row transmission", &specTrans, 0, 1);
    if (rowChanged) {
      vary_ = vary;
      set_ = fmt::format("baseColor={},{},{},metallic={},roughness={},specTrans={}", color.x,
                         color.y, color.z, metallic, roughness, specTrans);
      scene::changeMaterialRow(scene_, vary_, set_);
      materialsChanged();
    }
  }
}

void Viewer::drawStats() {
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(
      ImVec2(viewport->WorkPos.x + viewport->WorkSize.x - 8, viewport->WorkPos.y + 8),
      ImGuiCond_Always, ImVec2(1, 0));
  ImGui::SetNextWindowBgAlpha(0.5f);
  ImGui::Begin("stats", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                   ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoFocusOnAppearing |
                   ImGuiWindowFlags_NoNav);
  const auto& adapter = device_->adapter();
  ImGui::Text("%s (%s)", adapter.name.c_str(), device_->backendName());
  uint32_t shownWidth = 0, shownHeight = 0;
  targetSize(shownWidth, shownHeight);
  ImGui::Text("render %ux%u (scale %.3f%s), %s %ux%u", tracer_->width(), tracer_->height(),
              scale_.scale(), scale_.automatic() ? " auto" : "", window_ ? "window" : "offscreen",
              shownWidth, shownHeight);
  ImGui::Text("accumulated %u spp", tracer_->accumulatedSamples());
  ImGui::Text(
      "GPU %.2f ms/frame, %.1f Mrays/s", lastStats_.gpuSeconds * 1e3,
      lastStats_.gpuSeconds > 0 ? double(lastStats_.rays) / lastStats_.gpuSeconds * 1e-6 : 0.0);
  if (settings_.render.denoiser.mode != render::DenoiseMode::Off)
    ImGui::Text("denoiser (%s) GPU %.2f ms",
                render::denoiseModeName(settings_.render.denoiser.mode),
                passTimers_[DenoisePass].lastSeconds * 1e3);
  ImGui::Text("display GPU %.2f ms, UI GPU %.2f ms", passTimers_[DisplayPass].lastSeconds * 1e3,
              passTimers_[UiPass].lastSeconds * 1e3);
  ImGui::Text("frame %.1f ms (%.1f fps)", frameSeconds_ * 1e3,
              frameSeconds_ > 0 ? 1.0 / frameSeconds_ : 0.0);
  ImGui::End();
}

}  // namespace penumbra::viewer
