#pragma once
// What a study sweeps (`penumbra study`): rendering techniques, each at a
// series of sample counts and several seeds, over one scene. Every point is
// timed and compared with a reference (study_runner.h), and the rows answer
// "which technique gives the lowest error in my budget" (study_analysis.h).
//
// A technique is a set of render settings (batch/render_settings.h); the
// settings a study can sweep are its axes (studyAxes()), each a settings
// table entry, so their names, ranges and spellings are the table's.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "penumbra/batch/render_settings.h"

namespace penumbra::study {

// A setting a study can sweep, in the order the sweep turns (the last
// fastest) and its results list them.
struct StudyAxis {
  const render::Setting* setting = nullptr;  // the settings table's entry
  std::string_view csvColumn;                // results.csv's column
  std::string_view jsonKey;                  // results.json's key
  // How a technique's label shows a value other than the default:
  // "depth=" gives "depth=4", "" the value alone ("sobol"; a flag: its
  // onWord, "full").
  std::string_view labelTag;
  // A flag's values in labels and results ("on"/"off", "full"/"specialized");
  // results.json writes on/off flags as true/false.
  std::string_view onWord = "on", offWord = "off";
  // `penumbra study`'s option ("max-depth" for --max-depth): the setting's
  // command-line name, but "pipeline" for allEffects.
  std::string_view option;
  // The value as labels and results.csv spell it: a choice's name, a count,
  // a number with enough digits to read back the same double, a flag's word.
  std::string spell(double value) const;
  // What spell() wrote, or the table's spellings; nothing when it names no
  // value of this axis.
  std::optional<double> parse(std::string_view text) const;
};
// integrator, strategy, misHeuristic, sampler, maxDepth, russianRoulette,
// radianceClamp, denoise, allEffects.
const std::vector<StudyAxis>& studyAxes();
// The axis of a settings key or CLI name, or nullptr.
const StudyAxis* findStudyAxis(std::string_view keyOrName);

// One way of rendering: everything but the sample count and the seed.
struct Technique {
  render::RenderSettings settings;

  // The path tracer's settings for one seed (guides written for a denoiser).
  render::PathTracerSettings frameSettings(uint32_t seed) const;
  // A setting's value by settings key ("maxDepth").
  double value(std::string_view key) const;
  // A short name: the strategy (or "whitted"), then whatever differs from
  // the defaults, e.g. "mis", "bsdf depth=4 clamp=10", "mis sobol denoise=svgf".
  std::string label() const;
  // Equal in every study axis.
  bool operator==(const Technique& other) const;
};

// The values each axis sweeps; the study is their product. An axis not
// listed keeps its default.
struct StudySpec {
  struct Sweep {
    std::string key;             // settings key of a study axis
    std::vector<double> values;  // in the table's terms: a choice's index, 0/1, the number
  };
  std::vector<Sweep> sweeps;
  std::vector<uint32_t> spp{1, 4, 16, 64};
  uint32_t seeds = 3;  // seeds firstSeed .. firstSeed + seeds - 1 per point
  uint32_t firstSeed = 1;

  // Sweeps `key` over `values` (enums, counts, numbers, bools), replacing
  // an earlier sweep of it.
  template <class T>
  void sweep(std::string_view key, const std::vector<T>& values) {
    std::vector<double> v;
    for (const T& x : values) v.push_back(double(x));
    sweepValues(key, std::move(v));
  }
  // Throws penumbra::Error for a key that is no study axis.
  void sweepValues(std::string_view key, std::vector<double> values);
};

struct StudyPoint {
  Technique technique;
  uint32_t spp = 1;
  uint32_t seed = 1;
};

// The techniques of the product, in sweep order, without repeats: the
// Whitted integrator ignores the path tracer's options (the settings table's
// pathTracerOnly: its combinations collapse into one technique) and takes no
// denoiser (one asking for a denoiser is left out).
std::vector<Technique> studyTechniques(const StudySpec& spec);
// Every point: each technique at each spp with each seed. Throws
// penumbra::Error on an empty list, spp 0, or no seeds.
std::vector<StudyPoint> expandStudy(const StudySpec& spec);

}  // namespace penumbra::study
