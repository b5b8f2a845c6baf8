// Dear ImGui's pixels: the vertex colour times the font atlas (white where
// ImGui draws solid shapes), alpha-blended by the pipeline.
#include "imgui_shared.h"

PT_SAMPLED_TEXTURE(gFont, IMGUI_T_FONT);
PT_SAMPLER(gFontSampler, IMGUI_S_FONT);

PT_PIXEL(main, PT_PIXEL_INPUT(0, float2, uv) PT_PIXEL_INPUT(1, float4, color)) {
  PT_TARGET = color * PT_SAMPLE(gFont, gFontSampler, uv);
}
