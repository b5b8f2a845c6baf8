#include "penumbra/batch/render_settings.h"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <limits>

#include "penumbra/batch/render_job.h"
#include "penumbra/util/error.h"

namespace penumbra::render {
namespace {

// Field access as a double: every value a setting holds (uint32_t, float,
// bool, an enum's index) is exact in a double, so one representation serves
// parsing, records, widgets and the hash.
template <class T>
double toDouble(T v) {
  if constexpr (std::is_enum_v<T>)
    return double(static_cast<std::underlying_type_t<T>>(v));
  else
    return double(v);
}
template <class T>
T fromDouble(double v) {
  if constexpr (std::is_enum_v<T>)
    return static_cast<T>(static_cast<std::underlying_type_t<T>>(v));
  else if constexpr (std::is_same_v<T, bool>)
    return v != 0.0;
  else
    return T(v);
}

// A setting's get/set through a chain of members from RenderSettings, e.g.
// access<&RenderSettings::tracer, &PathTracerSettings::maxDepth>.
template <auto Outer, auto Inner>
struct Nested {
  static auto& ref(RenderSettings& s) { return (s.*Outer).*Inner; }
  static const auto& ref(const RenderSettings& s) { return (s.*Outer).*Inner; }
};
template <auto Member>
struct Direct {
  static auto& ref(RenderSettings& s) { return s.*Member; }
  static const auto& ref(const RenderSettings& s) { return s.*Member; }
};
template <class Path>
Setting field(Setting s) {
  s.get = [](const RenderSettings& r) { return toDouble(Path::ref(r)); };
  s.set = [](RenderSettings& r, double v) {
    auto& f = Path::ref(r);
    f = fromDouble<std::remove_reference_t<decltype(f)>>(v);
  };
  return s;
}
template <auto Member>
using Tracer = Nested<&RenderSettings::tracer, Member>;

constexpr double kFloatMax = std::numeric_limits<float>::max();

using T = SettingType;
using W = SettingWidget;
using C = SettingChange;
using G = SettingGroup;

// What and how the path tracer samples.
void addSamplingSettings(std::vector<Setting>& table) {
  table.push_back(
      field<Tracer<&PathTracerSettings::integrator>>({.key = "integrator",
                                                      .name = "integrator",
                                                      .help = "Integrator: path | whitted",
                                                      .type = T::Choice,
                                                      .choices = {"path", "whitted"},
                                                      .label = "integrator",
                                                      .widget = W::Combo}));
  table.push_back(
      field<Direct<&RenderSettings::sppPerFrame>>({.key = "sppPerFrame",
                                                   .name = "spp-per-frame",
                                                   .help = "Samples per pixel in each GPU frame",
                                                   .type = T::Count,
                                                   .min = 1,
                                                   .max = PathTracer::kMaxSamplesPerFrame,
                                                   .label = "spp per frame",
                                                   .widget = W::Slider,
                                                   .widgetMin = 1,
                                                   .widgetMax = PathTracer::kMaxSamplesPerFrame}));
  table.push_back(field<Tracer<&PathTracerSettings::maxDepth>>({.key = "maxDepth",
                                                                .name = "max-depth",
                                                                .help = "Maximum bounces",
                                                                .type = T::Count,
                                                                .min = 0,
                                                                .max = kMaxPathDepth,
                                                                .label = "max depth",
                                                                .widget = W::Slider,
                                                                .widgetMin = 0,
                                                                .widgetMax = 64}));
  table.push_back(field<Tracer<&PathTracerSettings::strategy>>(
      {.key = "strategy",
       .name = "strategy",
       .help = "Path sampling: uniform | cosine | bsdf (no light sampling) | nee | mis",
       .type = T::Choice,
       .choices = {"uniform", "cosine", "bsdf", "nee", "mis"},
       .label = "strategy",
       .widget = W::Combo,
       .pathTracerOnly = true}));
  table.push_back(
      field<Tracer<&PathTracerSettings::misHeuristic>>({.key = "misHeuristic",
                                                        .name = "mis-heuristic",
                                                        .help = "MIS weights: power | balance",
                                                        .type = T::Choice,
                                                        .choices = {"power", "balance"},
                                                        .label = "MIS heuristic",
                                                        .widget = W::Combo,
                                                        .pathTracerOnly = true}));
  table.push_back(
      field<Tracer<&PathTracerSettings::russianRoulette>>({.key = "russianRoulette",
                                                           .name = "russian-roulette",
                                                           .help = "Disable Russian roulette",
                                                           .type = T::Flag,
                                                           .label = "Russian roulette",
                                                           .widget = W::Checkbox,
                                                           .pathTracerOnly = true}));
}

// The path tracer's finer controls and its random numbers.
void addPathSettings(std::vector<Setting>& table) {
  table.push_back(field<Tracer<&PathTracerSettings::rouletteStartDepth>>(
      {.key = "rouletteStartDepth",
       .name = "roulette-start-depth",
       .help = "The bounce Russian roulette starts at",
       .type = T::Count,
       .min = 0,
       .max = kMaxPathDepth,
       .pathTracerOnly = true}));
  table.push_back(field<Tracer<&PathTracerSettings::radianceClamp>>(
      {.key = "radianceClamp",
       .name = "clamp",
       .help = "Clamp each sample's radiance to this value (0 = off)",
       .type = T::Number,
       .min = 0,
       .max = kFloatMax,
       .label = "clamp (0 = off)",
       .widget = W::Drag,
       .widgetMin = 0,
       .widgetMax = 1e4f,
       .widgetStep = 0.1f,
       .pathTracerOnly = true}));
  table.push_back(field<Tracer<&PathTracerSettings::sampler>>(
      {.key = "sampler",
       .name = "sampler",
       .help = "Random numbers: random (hashed) | sobol (Owen-scrambled Sobol)",
       .type = T::Choice,
       .choices = {"random", "sobol"},
       .label = "sampler",
       .widget = W::Combo}));
  table.push_back(
      field<Tracer<&PathTracerSettings::seed>>({.key = "seed",
                                                .name = "seed",
                                                .help = "Random seed",
                                                .type = T::Count,
                                                .min = 0,
                                                .max = std::numeric_limits<uint32_t>::max(),
                                                .label = "seed",
                                                .widget = W::Input}));
  // Derived, not chosen: the denoiser and the AOVs need the guide buffers.
  // Recorded because the pipeline that writes them is another variant,
  // which a GPU compiler may contract differently (docs/results.md).
  table.push_back(
      field<Tracer<&PathTracerSettings::writeGuides>>({.key = "guides",
                                                       .name = "guides",
                                                       .help = "Write the denoiser's guide buffers",
                                                       .type = T::Flag,
                                                       .commandLine = false}));
}

// The denoiser, the display transform and the pipeline.
void addOutputSettings(std::vector<Setting>& table) {
  table.push_back(field<Nested<&RenderSettings::denoiser, &DenoiserSettings::mode>>(
      {.key = "denoise",
       .name = "denoise",
       .help = "Denoiser: off | atrous (single frame, on the final image) | svgf (temporal, every "
               "frame)",
       .type = T::Choice,
       .choices = {"off", "atrous", "svgf"},
       .label = "denoiser",
       .widget = W::Combo,
       .group = G::Denoiser,
       .identity = false,
       .recorded = false,
       .pathTracerOnly = true}));
  table.push_back(field<Nested<&RenderSettings::denoiser, &DenoiserSettings::fireflyClamp>>(
      {.key = "fireflyClamp",
       .name = "firefly-clamp",
       .help = "Denoiser: clamp a pixel brighter than all its neighbours to the brightest (fewer "
               "spikes at 1-4 spp, but their light is lost)",
       .type = T::Flag,
       .label = "firefly clamp",
       .widget = W::Checkbox,
       .group = G::Denoiser,
       .change = C::Display,
       .identity = false,
       .recorded = false,
       .pathTracerOnly = true}));
  table.push_back(field<Nested<&RenderSettings::toneMapping, &ToneMapping::exposure>>(
      {.key = "exposure",
       .name = "exposure",
       .help = "Exposure multiplier for PNG output",
       .type = T::Number,
       .min = 0,
       .max = 1e6,
       .label = "exposure",
       .widget = W::Drag,
       .widgetMin = 0,
       .widgetMax = 100,
       .widgetStep = 0.01f,
       .group = G::Display,
       .change = C::Display,
       .identity = false}));
  table.push_back(field<Nested<&RenderSettings::toneMapping, &ToneMapping::toneOperator>>(
      {.key = "toneMapping",
       .name = "tonemap",
       .help = "Tone curve for PNG output: clamp | reinhard | aces | pbr-neutral | agx",
       .type = T::Choice,
       .choices = {"clamp", "reinhard", "aces", "pbr-neutral", "agx"},
       .label = "tone mapping",
       .widget = W::Combo,
       .group = G::Display,
       .change = C::Display,
       .identity = false}));
  table.push_back(field<Direct<&RenderSettings::allEffects>>(
      {.key = "allEffects",
       .name = "all-effects",
       .help = "Build the full pipeline instead of only the effects the scene calls for",
       .type = T::Flag,
       .label = "all effects",
       .widget = W::Checkbox,
       .group = G::Pipeline,
       .change = C::Pipeline}));
}

std::vector<Setting> makeTable() {
  std::vector<Setting> table;
  addSamplingSettings(table);
  addPathSettings(table);
  addOutputSettings(table);
  return table;
}

}  // namespace

bool denoises(const RenderSettings& settings) {
  return settings.denoiser.mode != DenoiseMode::Off &&
         settings.tracer.integrator == Integrator::Path;
}

PathTracerSettings frameSettings(const RenderSettings& settings) {
  PathTracerSettings tracer = settings.tracer;
  if (denoises(settings)) tracer.writeGuides = true;
  return tracer;
}

std::string Setting::commandLineFlag() const {
  if (type == SettingType::Flag && get(RenderSettings{}) != 0.0)
    return fmt::format("--no-{}", name);
  return fmt::format("--{}", name);
}

std::string Setting::format(double value) const {
  switch (type) {
    case SettingType::Flag:
      return value != 0.0 ? "on" : "off";
    case SettingType::Count:
      return fmt::format("{}", uint64_t(value));
    case SettingType::Number:
      return fmt::format("{}", float(value));
    case SettingType::Choice:
      return size_t(value) < choices.size() ? std::string(choices[size_t(value)]) : "?";
  }
  return "?";
}

std::optional<double> Setting::parse(std::string_view text) const {
  switch (type) {
    case SettingType::Flag:
      if (text == "on" || text == "true" || text == "1") return 1.0;
      if (text == "off" || text == "false" || text == "0") return 0.0;
      return std::nullopt;
    case SettingType::Count: {
      uint64_t v = 0;
      auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
      if (ec != std::errc() || end != text.data() + text.size() || double(v) < min ||
          double(v) > max)
        return std::nullopt;
      return double(v);
    }
    case SettingType::Number: {
      const std::string s(text);
      size_t used = 0;
      double v = 0;
      try {
        v = std::stod(s, &used);
      } catch (const std::exception&) {
        return std::nullopt;
      }
      // Read as the float the setting holds, so the range is the stored value's.
      const double stored = double(float(v));
      if (used != s.size() || !std::isfinite(stored) || stored < min || stored > max)
        return std::nullopt;
      return stored;
    }
    case SettingType::Choice:
      for (size_t i = 0; i < choices.size(); ++i)
        if (text == choices[i]) return double(i);
      return std::nullopt;
  }
  return std::nullopt;
}

std::string Setting::expected() const {
  switch (type) {
    case SettingType::Flag:
      return "on or off";
    case SettingType::Count:
      return fmt::format("an integer in {}..{}", uint64_t(min), uint64_t(max));
    case SettingType::Number:
      return fmt::format("a number in {}..{}", min, max);
    case SettingType::Choice: {
      std::string list;
      for (auto c : choices) list += (list.empty() ? "" : ", ") + std::string(c);
      return "one of " + list;
    }
  }
  return "?";
}

double Setting::parseOrThrow(std::string_view text, std::string_view where) const {
  auto v = parse(text);
  if (!v) throw Error(fmt::format("{} '{}': not {}", where, text, expected()));
  return *v;
}

bool Setting::accepts(double value) const {
  switch (type) {
    case SettingType::Flag:
      return value == 0.0 || value == 1.0;
    case SettingType::Choice:
      return value >= 0 && value < double(choices.size()) && value == std::floor(value);
    case SettingType::Count:
      return value >= min && value <= max && value == std::floor(value);
    case SettingType::Number:
      return value >= min && value <= max;
  }
  return false;
}

void Setting::setChecked(RenderSettings& settings, double value, std::string_view where) const {
  if (!accepts(value))
    throw Error(fmt::format("{}: \"{}\" {} is not {}", where, key, value, expected()));
  set(settings, value);
}

bool Setting::isDefault(const RenderSettings& settings) const {
  return get(settings) == get(RenderSettings{});
}

const std::vector<Setting>& renderSettingsTable() {
  static const std::vector<Setting> table = makeTable();
  return table;
}

const Setting* findSetting(std::string_view nameOrKey) {
  for (const Setting& s : renderSettingsTable())
    if (s.name == nameOrKey || s.key == nameOrKey) return &s;
  return nullptr;
}

namespace {

const Setting& choiceSetting(std::string_view key) {
  const Setting* setting = findSetting(key);
  if (!setting || setting->type != SettingType::Choice)
    throw Error(fmt::format("internal error: no choice setting '{}'", key));
  return *setting;
}
template <class Enum>
const char* choiceName(std::string_view key, Enum value) {
  const Setting& setting = choiceSetting(key);
  const size_t i = size_t(toDouble(value));
  return i < setting.choices.size() ? setting.choices[i].data() : "?";
}
template <class Enum>
std::optional<Enum> choiceValue(std::string_view key, std::string_view name) {
  const auto index = choiceSetting(key).parse(name);
  if (!index) return std::nullopt;
  return fromDouble<Enum>(*index);
}

}  // namespace

// The enums' names are their settings' choices (the string_views above
// point at literals, so .data() is terminated).
const char* integratorName(Integrator v) {
  return choiceName("integrator", v);
}
const char* strategyName(SamplingStrategy v) {
  return choiceName("strategy", v);
}
const char* misHeuristicName(MisHeuristic v) {
  return choiceName("misHeuristic", v);
}
const char* samplerName(Sampler v) {
  return choiceName("sampler", v);
}
const char* toneMapOperatorName(ToneMapOperator v) {
  return choiceName("toneMapping", v);
}
std::optional<ToneMapOperator> parseToneMapOperator(std::string_view name) {
  return choiceValue<ToneMapOperator>("toneMapping", name);
}
const char* denoiseModeName(DenoiseMode v) {
  return choiceName("denoise", v);
}
std::optional<DenoiseMode> parseDenoiseMode(std::string_view name) {
  return choiceValue<DenoiseMode>("denoise", name);
}

}  // namespace penumbra::render
