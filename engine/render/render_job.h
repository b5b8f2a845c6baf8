#pragma once
// Everything that determines a rendered image, as one JSON document: the
// viewer writes it beside each screenshot and `penumbra render --settings
// FILE` reads it back, so the screenshot can be reproduced exactly (same
// device, same samples, same seed).
//
//   { "format": "penumbra-render", "version": 1,
//     "scene": "cornell-box", "vary": "", "set": "",
//     "camera": { "position": [x,y,z], "forward": [..], "up": [..], "verticalFovDegrees": 39.3 },
//     "width": 512, "height": 512, "spp": 64, "sppPerFrame": 4,
//     "integrator": "path", "strategy": "mis", "misHeuristic": "power",
//     "maxDepth": 8, "russianRoulette": true, "rouletteStartDepth": 3,
//     "radianceClamp": 0, "seed": 0,
//     "exposure": 1, "toneMapping": "clamp", "allEffects": false }
// Floats are written with enough digits to read back bit-identical.
#include <optional>
#include <string>

#include "render/path_tracer.h"
#include "render/tone_mapping.h"
#include "scene/scene.h"

namespace penumbra::render {

struct RenderJob {
  std::string scene = "cornell-box";    // built-in name or scene file path
  std::string vary, set;                // material-test row (scene::changeMaterialRow)
  std::optional<scene::Camera> camera;  // absent: the scene's camera
  uint32_t width = 512, height = 512;
  uint32_t spp = 64;
  uint32_t sppPerFrame = 16;
  PathTracerSettings settings;
  ToneMapping toneMapping;
  bool allEffects = false;
};

const char* integratorName(Integrator integrator);
const char* strategyName(SamplingStrategy strategy);
const char* misHeuristicName(MisHeuristic heuristic);
std::optional<Integrator> parseIntegrator(std::string_view name);
std::optional<SamplingStrategy> parseStrategy(std::string_view name);
std::optional<MisHeuristic> parseMisHeuristic(std::string_view name);

std::string renderJobToJson(const RenderJob& job);
// Throws penumbra::Error naming `source` and the field on a malformed document.
RenderJob renderJobFromJson(const std::string& text, const std::string& source);
void saveRenderJob(const std::string& path, const RenderJob& job);
RenderJob loadRenderJob(const std::string& path);

}  // namespace penumbra::render
