// The viewer's ImGui renderer on the RHI's raster subset (apps/viewer/
// imgui_renderer.h): an ImGui frame of known shapes against hand-worked
// pixels -- coverage of solid rectangles (drawn through the font atlas's
// white texel), alpha blending of a translucent one, and a clip rectangle
// becoming the scissor.
#include <imgui.h>

#include <catch2/catch_test_macros.hpp>
#include <cstdlib>
#include <vector>

#include "imgui_renderer.h"
#include "test_device.h"

using namespace penumbra;

namespace {

constexpr uint32_t kWidth = 96, kHeight = 64;

struct ImGuiContextGuard {
  ImGuiContextGuard() { ImGui::CreateContext(); }
  ~ImGuiContextGuard() { ImGui::DestroyContext(); }
};

}  // namespace

TEST_CASE("imgui renderer: rectangles, blending and clip rectangles give the expected pixels",
          "[viewer][raster]") {
  auto device = test::makeTestDevice();
  ImGuiContextGuard context;
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;
  io.DisplaySize = ImVec2(float(kWidth), float(kHeight));
  io.DeltaTime = 1.0f / 60.0f;
  viewer::ImGuiRenderer renderer(*device, 2);

  ImGui::NewFrame();
  ImDrawList* draw = ImGui::GetForegroundDrawList();
  // Rectangles with square corners are drawn without anti-aliased fringes:
  // [x0, x1) x [y0, y1) covers exactly the pixels whose centres lie inside.
  draw->AddRectFilled(ImVec2(8, 8), ImVec2(40, 24), IM_COL32(255, 0, 0, 255));
  draw->AddRectFilled(ImVec2(48, 8), ImVec2(80, 24), IM_COL32(0, 255, 0, 128));
  draw->PushClipRect(ImVec2(10, 40), ImVec2(30, 50));
  draw->AddRectFilled(ImVec2(0, 32), ImVec2(96, 64), IM_COL32(0, 0, 255, 255));
  draw->PopClipRect();
  ImGui::Render();

  rhi::TextureDesc t;
  t.width = kWidth;
  t.height = kHeight;
  t.format = rhi::Format::RGBA8_UNORM;
  t.usage = rhi::TextureUsage::RenderTarget | rhi::TextureUsage::CopySource;
  t.debugName = "ui target";
  auto target = device->createTexture(t);
  rhi::BufferDesc b;
  b.byteSize = kWidth * kHeight * 4;
  b.usage = rhi::BufferUsage::CopyDest;
  b.memory = rhi::MemoryLocation::Readback;
  b.debugName = "ui readback";
  auto readback = device->createBuffer(b);

  auto list = device->createCommandList("ui test");
  list->open();
  const float grey[4] = {0.2f, 0.2f, 0.2f, 1.0f};  // 51 in 8 bits
  list->beginRendering(target.get(), grey);
  list->endRendering();
  renderer.render(*list, *target);
  list->copyTextureToBuffer(target.get(), readback.get());
  list->close();
  device->submit(list.get());
  device->waitForIdle();

  const auto* pixels = static_cast<const uint8_t*>(readback->mappedData());
  size_t bad = 0;
  for (uint32_t y = 0; y < kHeight; ++y)
    for (uint32_t x = 0; x < kWidth; ++x) {
      int want[4] = {51, 51, 51, 255};
      if (x >= 8 && x < 40 && y >= 8 && y < 24) {
        want[0] = 255, want[1] = 0, want[2] = 0;  // opaque red
      } else if (x >= 48 && x < 80 && y >= 8 && y < 24) {
        // green at alpha 128/255 over grey: 255 a + 51 (1 - a) = 153, 51 (1 - a) = 25.4
        want[0] = 25, want[1] = 153, want[2] = 25;
      } else if (x >= 10 && x < 30 && y >= 40 && y < 50) {
        want[0] = 0, want[1] = 0, want[2] = 255;  // the blue rectangle, clipped
      }
      const uint8_t* p = pixels + (size_t(y) * kWidth + x) * 4;
      for (int c = 0; c < 4; ++c)
        if (std::abs(int(p[c]) - want[c]) > 1) {
          ++bad;
          break;
        }
    }
  CHECK(bad == 0);
  REQUIRE_NO_VALIDATION_MESSAGES(device);
}
