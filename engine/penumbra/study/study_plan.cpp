#include "penumbra/study/study_plan.h"

#include <fmt/format.h>

#include <algorithm>

#include "penumbra/util/error.h"

namespace penumbra::study {

const std::vector<StudyAxis>& studyAxes() {
  static const std::vector<StudyAxis> axes = [] {
    auto axis = [](std::string_view key, std::string_view column, std::string_view tag) {
      const render::Setting* setting = render::findSetting(key);
      if (!setting) throw Error(fmt::format("internal error: study axis '{}' is no setting", key));
      return StudyAxis{.setting = setting,
                       .csvColumn = column,
                       .jsonKey = key,
                       .labelTag = tag,
                       .option = setting->name};
    };
    // The results' spellings that predate the table's keys.
    StudyAxis clamp = axis("radianceClamp", "clamp", "clamp=");
    clamp.jsonKey = "clamp";
    StudyAxis pipeline = axis("allEffects", "pipeline", "");
    pipeline.jsonKey = pipeline.option = "pipeline";
    pipeline.onWord = "full";
    pipeline.offWord = "specialized";
    std::vector<StudyAxis> list = {axis("integrator", "integrator", ""),
                                   axis("strategy", "strategy", ""),
                                   axis("misHeuristic", "mis_heuristic", ""),
                                   axis("sampler", "sampler", ""),
                                   axis("maxDepth", "max_depth", "depth="),
                                   axis("russianRoulette", "russian_roulette", "rr="),
                                   clamp,
                                   axis("denoise", "denoise", "denoise="),
                                   pipeline};
    return list;
  }();
  return axes;
}

std::string StudyAxis::spell(double value) const {
  switch (setting->type) {
    case render::SettingType::Flag:
      return std::string(value != 0.0 ? onWord : offWord);
    case render::SettingType::Number:
      return fmt::format("{:.17g}", value);
    default:
      return setting->format(value);
  }
}

std::optional<double> StudyAxis::parse(std::string_view text) const {
  if (setting->type == render::SettingType::Flag) {
    if (text == onWord) return 1.0;
    if (text == offWord) return 0.0;
    // Words of its own ("full"): those alone. on/off flags: the table's too.
    if (onWord != "on") return std::nullopt;
  }
  return setting->parse(text);
}

const StudyAxis* findStudyAxis(std::string_view keyOrName) {
  for (const StudyAxis& a : studyAxes())
    if (a.setting->key == keyOrName || a.setting->name == keyOrName || a.option == keyOrName)
      return &a;
  return nullptr;
}

render::PathTracerSettings Technique::frameSettings(uint32_t seed) const {
  render::PathTracerSettings s = render::frameSettings(settings);
  s.seed = seed;
  return s;
}

double Technique::value(std::string_view key) const {
  const render::Setting* setting = render::findSetting(key);
  if (!setting) throw Error(fmt::format("internal error: no setting '{}'", key));
  return setting->get(settings);
}

std::string Technique::label() const {
  const bool whitted = settings.tracer.integrator == render::Integrator::Whitted;
  std::string name = whitted ? render::integratorName(settings.tracer.integrator)
                             : render::strategyName(settings.tracer.strategy);
  for (const StudyAxis& axis : studyAxes()) {
    const render::Setting& s = *axis.setting;
    if (s.key == "integrator" || s.key == "strategy" || s.isDefault(settings)) continue;
    if (whitted && s.pathTracerOnly) continue;  // Whitted ignores it
    const double v = s.get(settings);
    // Numbers to 6 digits (labels name images), not spell()'s 17.
    name += fmt::format(
        " {}{}", axis.labelTag,
        s.type == render::SettingType::Number ? fmt::format("{:g}", float(v)) : axis.spell(v));
  }
  return name;
}

bool Technique::operator==(const Technique& other) const {
  for (const StudyAxis& axis : studyAxes())
    if (axis.setting->get(settings) != axis.setting->get(other.settings)) return false;
  return true;
}

void StudySpec::sweepValues(std::string_view key, std::vector<double> values) {
  const StudyAxis* axis = findStudyAxis(key);
  if (!axis) throw Error(fmt::format("study: '{}' is no setting a study sweeps", key));
  for (double v : values)
    if (!axis->setting->accepts(v))
      throw Error(
          fmt::format("study: {} {} is not {}", axis->setting->name, v, axis->setting->expected()));
  for (Sweep& s : sweeps)
    if (s.key == axis->setting->key) {
      s.values = std::move(values);
      return;
    }
  sweeps.push_back({std::string(axis->setting->key), std::move(values)});
}

std::vector<Technique> studyTechniques(const StudySpec& spec) {
  // Each axis's values: the sweep's, or the default alone.
  const std::vector<StudyAxis>& axes = studyAxes();
  std::vector<std::vector<double>> lists;
  for (const StudyAxis& axis : axes) {
    std::vector<double> values{axis.setting->get(render::RenderSettings{})};
    for (const auto& s : spec.sweeps)
      if (s.key == axis.setting->key) values = s.values;
    if (values.empty()) throw Error(fmt::format("study: no {} given", axis.setting->name));
    lists.push_back(std::move(values));
  }
  // The product of the lists, odometer order: the last list turns fastest.
  std::vector<size_t> at(lists.size(), 0);
  std::vector<Technique> techniques;
  for (bool more = true; more;) {
    Technique t;
    for (size_t k = 0; k < axes.size(); ++k) axes[k].setting->set(t.settings, lists[k][at[k]]);
    // The denoiser filters the path tracer's image only; the path tracer's
    // other options mean nothing to Whitted.
    const bool keep =
        t.settings.denoiser.mode == render::DenoiseMode::Off || render::denoises(t.settings);
    if (t.settings.tracer.integrator != render::Integrator::Path)
      for (const StudyAxis& axis : axes)
        if (axis.setting->pathTracerOnly)
          axis.setting->set(t.settings, axis.setting->get(render::RenderSettings{}));
    if (keep && std::find(techniques.begin(), techniques.end(), t) == techniques.end())
      techniques.push_back(t);
    more = false;
    for (size_t k = at.size(); k-- > 0;) {
      if (++at[k] < lists[k].size()) {
        more = true;
        break;
      }
      at[k] = 0;
    }
  }
  if (techniques.empty())
    throw Error("study: no technique left (the denoiser filters only --integrator path)");
  return techniques;
}

std::vector<StudyPoint> expandStudy(const StudySpec& spec) {
  if (spec.spp.empty()) throw Error("study: no spp given");
  for (uint32_t spp : spec.spp)
    if (spp == 0) throw Error("study: spp 0 (every point needs at least one sample)");
  if (spec.seeds == 0) throw Error("study: --seeds 0 (every point needs a seed)");
  std::vector<StudyPoint> points;
  for (const Technique& t : studyTechniques(spec))
    for (uint32_t spp : spec.spp)
      for (uint32_t k = 0; k < spec.seeds; ++k) points.push_back({t, spp, spec.firstSeed + k});
  return points;
}

}  // namespace penumbra::study
