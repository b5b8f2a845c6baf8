#pragma once
// The GPU form of scene::Environment (shaders/shared/environment.hlsli): the
// texels with each one's probability, and the cumulative tables the sampler
// searches. The density is proportional to luminance x sin(theta) of the
// texel's centre, so sampling follows what each texel contributes to the
// sphere.
#include <vector>

#include "path_tracer_shared.h"
#include "penumbra/scene/environment.h"

namespace penumbra::render {

struct EnvironmentTables {
  gpu::EnvironmentData info;        // size and placement
  std::vector<gpu::float4> texels;  // rgb radiance, w the texel's probability
  // `height` cumulative row probabilities, then per row its `width`
  // cumulative column probabilities (each table ends in exactly 1).
  std::vector<float> cdf;
};

// Without an environment: a 1x1 black map (the buffers stay bound).
EnvironmentTables buildEnvironmentTables(const scene::Environment& environment);
// The placement alone (rotation, intensity), for a map already uploaded.
gpu::EnvironmentData environmentInfo(const scene::Environment& environment);

}  // namespace penumbra::render
