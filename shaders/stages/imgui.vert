// Dear ImGui's vertices (ImDrawVert: position in pixels, font-atlas uv,
// packed RGBA8 colour) to clip space.
#include "imgui_shared.h"

PT_PUSH_CONSTANTS(ImGuiPush, imguiPush);

PT_VERTEX(main, PT_VERTEX_INPUT(0, float2, position) PT_VERTEX_INPUT(1, float2, uv)
                    PT_VERTEX_INPUT(2, float4, color) PT_VERTEX_OUTPUT(0, float2, outUv)
                        PT_VERTEX_OUTPUT(1, float4, outColor)) {
  ImGuiPush push = imguiPush();
  outUv = uv;
  outColor = color;
  PT_POSITION = float4(position.x * push.scaleX + push.translateX,
                       position.y * push.scaleY + push.translateY, 0.0, 1.0);
}
