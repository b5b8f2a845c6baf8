#pragma once
// Every setting a render is made with, described once. RenderSettings holds
// the values; renderSettingsTable() says, for each one, its record (JSON)
// key, its command-line and viewer `set` name, its type and accepted range,
// its viewer widget, and whether it is part of a render's identity. The
// command line (apps/common/cli_options.h), render records
// (render_job.h), the viewer's Algorithm menu and `set` command, the study's
// technique axes and the split-render hash (partial_render.h) all read this
// table, so adding a setting is one field, one table entry (render_settings.cpp)
// and its use in the pass or shader. docs/ARCHITECTURE.md "Settings" walks
// through one such addition.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "penumbra/render/denoiser.h"
#include "penumbra/render/path_tracer.h"
#include "penumbra/render/tone_mapping.h"

namespace penumbra::render {

// The ranges counts must lie in (records, the command line, the viewer):
// larger ones are refused, not rendered for days.
inline constexpr uint32_t kMaxSamplesPerPixel = 1u << 20;
inline constexpr uint32_t kMaxPathDepth = 1024;  // maxDepth, rouletteStartDepth

struct RenderSettings {
  PathTracerSettings tracer;
  uint32_t sppPerFrame = 16;  // samples per pixel in each GPU frame (1..16)
  bool allEffects = false;    // the full pipeline instead of the scene's effects
  ToneMapping toneMapping;    // PNG output and the viewer's display
  DenoiserSettings denoiser{.mode = DenoiseMode::Off};
};

// Whether the denoiser runs: it is on and filters the path tracer's image
// (the Whitted integrator writes no guide buffers).
bool denoises(const RenderSettings& settings);
// The path tracer's settings for a frame of this render: the guide buffers
// are written whenever the denoiser reads them (whatever `guides` says).
PathTracerSettings frameSettings(const RenderSettings& settings);

enum class SettingType {
  Flag,    // on or off; JSON true/false; the CLI spells the non-default side
  Count,   // a whole number in [min, max]
  Number,  // a finite number in [min, max]
  Choice,  // one of `choices`, stored as its index (the enum's value)
};

// How the viewer's Algorithm menu shows it.
enum class SettingWidget { None, Checkbox, Slider, Drag, Combo, Input };

// Where the viewer's Algorithm menu shows it (a separator between groups).
enum class SettingGroup { Sampling, Denoiser, Display, Pipeline };

// What changing it does to the viewer's image.
enum class SettingChange {
  Image,     // another image: the running mean starts again
  Pipeline,  // another pipeline: the renderer is rebuilt
  Display,   // the same image shown another way (tone mapping)
};

struct Setting {
  std::string_view key;   // render records' JSON key, and the name the hash feeds in
  std::string_view name;  // the CLI flag without "--" and the viewer's `set` name
  std::string_view help;  // one line for --help
  SettingType type = SettingType::Count;
  double min = 0, max = 0;                // Count and Number: accepted values
  std::vector<std::string_view> choices;  // Choice: names, by enum value
  std::string_view label;                 // the viewer widget's label
  SettingWidget widget = SettingWidget::None;
  float widgetMin = 0, widgetMax = 0;  // Slider and Drag: the range the widget offers
  float widgetStep = 0;                // Drag: the change per pixel dragged
  SettingGroup group = SettingGroup::Sampling;
  SettingChange change = SettingChange::Image;
  // Part of a render's identity: split-render pieces merge only when every
  // identity setting agrees (splitSettingsHash).
  bool identity = true;
  bool recorded = true;         // written in and read from render records
  bool commandLine = true;      // a `penumbra render` option
  bool pathTracerOnly = false;  // only the path integrator reads it (Whitted ignores it)
  double (*get)(const RenderSettings&) = nullptr;
  void (*set)(RenderSettings&, double) = nullptr;

  // "--max-depth"; a flag on by default is given as its negation,
  // "--no-russian-roulette".
  std::string commandLineFlag() const;
  // "8", "mis", "on", "0.25": what parse() reads back to the same value.
  std::string format(double value) const;
  // The value `text` names, or nothing when it is not a value this setting
  // accepts (flags: on/off, true/false, 1/0).
  std::optional<double> parse(std::string_view text) const;
  // What parse() accepts, for messages: "an integer in 0..1024", "one of
  // path, whitted", "on or off".
  std::string expected() const;
  // parse(), or penumbra::Error "<where> '<text>': not <expected>".
  double parseOrThrow(std::string_view text, std::string_view where) const;
  // Whether `value` is one this setting holds (in range, a choice's index,
  // 0 or 1 for a flag).
  bool accepts(double value) const;
  // Sets the value, or throws penumbra::Error naming `where` and the
  // setting when it lies outside the accepted range.
  void setChecked(RenderSettings& settings, double value, std::string_view where) const;
  bool isDefault(const RenderSettings& settings) const;
};

// The enums' names: their settings' choices.
const char* integratorName(Integrator integrator);
const char* strategyName(SamplingStrategy strategy);
const char* misHeuristicName(MisHeuristic heuristic);
const char* samplerName(Sampler sampler);
const char* toneMapOperatorName(ToneMapOperator op);
std::optional<ToneMapOperator> parseToneMapOperator(std::string_view name);
const char* denoiseModeName(DenoiseMode mode);
std::optional<DenoiseMode> parseDenoiseMode(std::string_view name);

// Every setting, in the order the viewer's menu and --help show them
// (grouped: SettingGroup's order).
const std::vector<Setting>& renderSettingsTable();
// By `set`/CLI name ("max-depth") or record key ("maxDepth"); nullptr if none.
const Setting* findSetting(std::string_view nameOrKey);

}  // namespace penumbra::render
