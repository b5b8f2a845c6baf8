#include "penumbra/study/study_plan.h"

#include <fmt/format.h>

#include <algorithm>
#include <iterator>

#include "penumbra/batch/render_job.h"
#include "penumbra/util/error.h"

namespace penumbra::study {

render::PathTracerSettings Technique::settings(uint32_t seed) const {
  render::PathTracerSettings s;
  s.integrator = integrator;
  s.strategy = strategy;
  s.misHeuristic = heuristic;
  s.sampler = sampler;
  s.maxDepth = maxDepth;
  s.russianRoulette = russianRoulette;
  s.radianceClamp = clamp;
  s.seed = seed;
  s.writeGuides = denoise != render::DenoiseMode::Off;
  return s;
}

std::string Technique::label() const {
  const Technique defaults;
  std::string name = integrator == render::Integrator::Whitted ? render::integratorName(integrator)
                                                               : render::strategyName(strategy);
  if (integrator == render::Integrator::Path && heuristic != defaults.heuristic)
    name += fmt::format(" {}", render::misHeuristicName(heuristic));
  if (sampler != defaults.sampler) name += fmt::format(" {}", render::samplerName(sampler));
  if (maxDepth != defaults.maxDepth) name += fmt::format(" depth={}", maxDepth);
  if (integrator == render::Integrator::Path) {
    if (!russianRoulette) name += " rr=off";
    if (clamp > 0.0f) name += fmt::format(" clamp={:g}", clamp);
    if (denoise != render::DenoiseMode::Off)
      name += fmt::format(" denoise={}", render::denoiseModeName(denoise));
  }
  if (allEffects) name += " full";
  return name;
}

bool Technique::operator==(const Technique& o) const {
  return integrator == o.integrator && strategy == o.strategy && heuristic == o.heuristic &&
         sampler == o.sampler && maxDepth == o.maxDepth && russianRoulette == o.russianRoulette &&
         clamp == o.clamp && denoise == o.denoise && allEffects == o.allEffects;
}

namespace {

template <class T>
void requireValues(const std::vector<T>& list, const char* what) {
  if (list.empty()) throw Error(fmt::format("study: no {} given", what));
}

}  // namespace

std::vector<Technique> studyTechniques(const StudySpec& spec) {
  requireValues(spec.integrators, "integrator");
  requireValues(spec.strategies, "strategy");
  requireValues(spec.heuristics, "MIS heuristic");
  requireValues(spec.samplers, "sampler");
  requireValues(spec.maxDepths, "max depth");
  requireValues(spec.russianRoulette, "Russian roulette setting");
  requireValues(spec.clamps, "clamp");
  requireValues(spec.denoise, "denoiser");
  requireValues(spec.allEffects, "pipeline");
  // The product of the lists, odometer order: the last list turns fastest.
  const size_t sizes[] = {
      spec.integrators.size(), spec.strategies.size(), spec.heuristics.size(),
      spec.samplers.size(),    spec.maxDepths.size(),  spec.russianRoulette.size(),
      spec.clamps.size(),      spec.denoise.size(),    spec.allEffects.size()};
  constexpr size_t kLists = std::size(sizes);
  size_t at[kLists] = {};
  std::vector<Technique> techniques;
  for (bool more = true; more;) {
    Technique t;
    t.integrator = spec.integrators[at[0]];
    t.sampler = spec.samplers[at[3]];
    t.maxDepth = spec.maxDepths[at[4]];
    t.allEffects = spec.allEffects[at[8]];
    const auto denoise = spec.denoise[at[7]];
    bool keep = true;
    if (t.integrator == render::Integrator::Path) {
      t.strategy = spec.strategies[at[1]];
      t.heuristic = spec.heuristics[at[2]];
      t.russianRoulette = spec.russianRoulette[at[5]];
      t.clamp = spec.clamps[at[6]];
      t.denoise = denoise;
    } else {
      keep = denoise == render::DenoiseMode::Off;
    }
    if (keep && std::find(techniques.begin(), techniques.end(), t) == techniques.end())
      techniques.push_back(t);
    more = false;
    for (size_t k = kLists; k-- > 0;) {
      if (++at[k] < sizes[k]) {
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
  requireValues(spec.spp, "spp");
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
