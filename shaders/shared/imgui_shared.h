// Host/shader interface of the viewer's Dear ImGui renderer
// (apps/viewer/imgui_renderer.h, shaders/stages/imgui.vert and imgui.frag):
// its registers and push-constant block.
#ifndef PENUMBRA_IMGUI_SHARED_H
#define PENUMBRA_IMGUI_SHARED_H

#ifdef __cplusplus
#include "shader_types.h"
namespace penumbra::gpu {
#endif

#include "bindings.hlsli"

#define IMGUI_T_FONT 0  // the font atlas (or a texture an ImGui::Image names)
#define IMGUI_S_FONT 0  // its linear, clamping sampler

// ImGui's pixel coordinates to clip space: clip = position * scale + translate.
struct ImGuiPush {
  float scaleX;
  float scaleY;
  float translateX;
  float translateY;
};

#ifdef __cplusplus
static_assert(sizeof(ImGuiPush) == 16);
}  // namespace penumbra::gpu
#endif
#endif
