#pragma once
// What a study sweeps (`penumbra study`): rendering techniques, each at a
// series of sample counts and several seeds, over one scene. Every point is
// timed and compared with a reference (study_runner.h), and the rows answer
// "which technique gives the lowest error in my budget" (study_analysis.h).
#include <cstdint>
#include <string>
#include <vector>

#include "penumbra/render/denoiser.h"
#include "penumbra/render/path_tracer.h"

namespace penumbra::study {

// One way of rendering: everything but the sample count and the seed.
struct Technique {
  render::Integrator integrator = render::Integrator::Path;
  render::SamplingStrategy strategy = render::SamplingStrategy::Mis;
  render::MisHeuristic heuristic = render::MisHeuristic::Power;
  render::Sampler sampler = render::Sampler::Random;
  uint32_t maxDepth = 8;
  bool russianRoulette = true;
  float clamp = 0.0f;  // per-sample radiance clamp; 0 = off
  render::DenoiseMode denoise = render::DenoiseMode::Off;
  bool allEffects = false;  // the full pipeline instead of the specialized one

  // The path tracer's settings for one seed (guides written for a denoiser).
  render::PathTracerSettings settings(uint32_t seed) const;
  // A short name: the strategy (or "whitted"), then whatever differs from
  // the defaults, e.g. "mis", "bsdf depth=4 clamp=10", "mis sobol denoise=svgf".
  std::string label() const;
  bool operator==(const Technique& other) const;
};

// The lists a study sweeps; the study is their product.
struct StudySpec {
  std::vector<render::Integrator> integrators{render::Integrator::Path};
  std::vector<render::SamplingStrategy> strategies{render::SamplingStrategy::Mis};
  std::vector<render::MisHeuristic> heuristics{render::MisHeuristic::Power};
  std::vector<render::Sampler> samplers{render::Sampler::Random};
  std::vector<uint32_t> maxDepths{8};
  std::vector<bool> russianRoulette{true};
  std::vector<float> clamps{0.0f};
  std::vector<render::DenoiseMode> denoise{render::DenoiseMode::Off};
  std::vector<bool> allEffects{false};
  std::vector<uint32_t> spp{1, 4, 16, 64};
  uint32_t seeds = 3;  // seeds firstSeed .. firstSeed + seeds - 1 per point
  uint32_t firstSeed = 1;
};

struct StudyPoint {
  Technique technique;
  uint32_t spp = 1;
  uint32_t seed = 1;
};

// The techniques of the product, in sweep order, without repeats: the
// Whitted integrator takes none of the path tracer's sampling options (its
// combinations collapse into one technique) and no denoiser (the denoiser
// filters the path tracer's image).
std::vector<Technique> studyTechniques(const StudySpec& spec);
// Every point: each technique at each spp with each seed. Throws
// penumbra::Error on an empty list, spp 0, or no seeds.
std::vector<StudyPoint> expandStudy(const StudySpec& spec);

}  // namespace penumbra::study
