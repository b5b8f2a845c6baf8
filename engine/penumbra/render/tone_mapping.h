#pragma once
// The display transform's settings, shared by PNG output (Tonemapper) and the
// viewer (DisplayPass): exposure, then a tone curve, then sRGB encoding
// (shaders/shared/tonemap.hlsli).
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace penumbra::render {

// Values match TONEMAP_* in tonemap.hlsli.
enum class ToneMapOperator : uint32_t {
  Clamp = 0,       // linear, values above 1 clip (the default: PNGs match the EXR's values)
  Reinhard = 1,    // x / (1 + x) per channel
  AcesFitted = 2,  // Hill's fit of the ACES RRT + sRGB ODT
  PbrNeutral = 3,  // Khronos PBR Neutral: base colours as authored, highlights compressed
  AgX = 4,         // AgX as glTF viewers (Filament, three.js) ship it
};

struct ToneMapping {
  float exposure = 1.0f;
  ToneMapOperator toneOperator = ToneMapOperator::Clamp;
  bool operator==(const ToneMapping&) const = default;
};

// Names: the tonemap setting's choices (batch/render_settings.h).

}  // namespace penumbra::render
