// Mip chains made on the host (engine/penumbra/render/texture_mips.h): the
// levels' sizes against the RHI's, and their texels against box filters
// worked out here, in linear light.
#include <catch2/catch_test_macros.hpp>
#include <cmath>
#include <random>

#include "penumbra/render/texture_mips.h"
#include "penumbra/rhi/resources.h"

using namespace penumbra;

namespace {

double srgbDecode(double c) {
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}
double srgbEncode(double c) {
  return c <= 0.0031308 ? c * 12.92 : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
}

// Where level `level` of a w x h chain starts, in bytes.
size_t levelOffset(uint32_t w, uint32_t h, uint32_t level) {
  size_t offset = 0;
  for (uint32_t i = 0; i < level; ++i)
    offset += size_t(std::max(1u, w >> i)) * std::max(1u, h >> i) * 4;
  return offset;
}

}  // namespace

TEST_CASE("mip chains: every level down to 1x1, in the sizes writeTexture takes",
          "[render][textures]") {
  CHECK(rhi::mipLevelCount(1, 1) == 1);
  CHECK(rhi::mipLevelCount(2, 1) == 2);
  CHECK(rhi::mipLevelCount(256, 256) == 9);
  CHECK(rhi::mipLevelCount(5, 3) == 3);      // 5x3, 2x1, 1x1
  CHECK(rhi::mipLevelCount(1, 1000) == 10);  // 1x1000 ... 1x1
  for (auto [w, h] :
       {std::pair{5u, 3u}, std::pair{256u, 1u}, std::pair{7u, 12u}, std::pair{1u, 1u}}) {
    std::vector<uint8_t> texels(size_t(w) * h * 4, 100);
    rhi::TextureDesc desc;
    desc.width = w;
    desc.height = h;
    desc.format = rhi::Format::RGBA8_SRGB;
    desc.mipLevels = rhi::mipLevelCount(w, h);
    const auto chain = render::mipChainRgba8(texels.data(), w, h, true);
    INFO(w << "x" << h);
    CHECK(chain.size() == rhi::textureByteSize(desc));
    CHECK(chain.size() == levelOffset(w, h, desc.mipLevels));
    // A uniform texture stays uniform at every level.
    for (uint8_t v : chain) CHECK(v == 100);
  }
}

TEST_CASE("mip chains: texels are box-filtered means in linear light", "[render][textures]") {
  // A black and white checker: level 1 is linear grey 0.5, which sRGB
  // stores as 188 (averaging the stored values would give 128, linear
  // 0.22) and linear data as 128 (127.5 rounded).
  std::vector<uint8_t> checker;
  for (uint32_t y = 0; y < 4; ++y)
    for (uint32_t x = 0; x < 4; ++x) {
      const uint8_t v = (x + y) % 2 == 0 ? 255 : 0;
      checker.insert(checker.end(), {v, v, v, uint8_t(255 - v)});
    }
  const auto srgb = render::mipChainRgba8(checker.data(), 4, 4, true);
  const auto linear = render::mipChainRgba8(checker.data(), 4, 4, false);
  const auto grey = uint8_t(std::lround(srgbEncode(0.5) * 255.0));
  REQUIRE(grey == 188);
  for (uint32_t level : {1u, 2u})
    for (size_t i = levelOffset(4, 4, level); i < levelOffset(4, 4, level + 1); i += 4) {
      INFO("level " << level << " byte " << i);
      CHECK(srgb[i] == grey);
      CHECK(srgb[i + 2] == grey);
      CHECK(srgb[i + 3] == 128);  // alpha is linear in an sRGB texture
      CHECK(linear[i] == 128);
    }

  // An odd size: a 3x1 row (0, 90, 255) of linear data has one texel at
  // level 1 (max(1, 3 / 2)), covering the whole row: its mean, 115.
  const std::vector<uint8_t> row = {0, 0, 0, 0, 90, 90, 90, 90, 255, 255, 255, 255};
  const auto rowChain = render::mipChainRgba8(row.data(), 3, 1, false);
  REQUIRE(rowChain.size() == 16);
  CHECK(rowChain[12] == 115);
}

TEST_CASE("mip chains: every level keeps the image's mean, odd sizes included",
          "[render][textures]") {
  // Random data: each level's mean is level 0's, within the 8-bit rounding
  // of its own texels (each level is made from the float level above it, so
  // rounding does not carry): half a step, 0.5/255, for linear data; for
  // sRGB half a step times the decode's steepest slope (2.27, at white),
  // 0.0045. A filter that dropped an odd size's last column would be off by
  // about 0.02 here (7x5, 13x1).
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> byte(0, 255);
  for (const auto& size : {std::pair{7u, 5u}, std::pair{13u, 1u}, std::pair{64u, 33u}}) {
    // Named copies, not structured bindings: clang's C++20 does not let the
    // lambda below capture those.
    const uint32_t w = size.first, h = size.second;
    std::vector<uint8_t> texels(size_t(w) * h * 4);
    for (auto& t : texels) t = uint8_t(byte(rng));
    for (bool srgb : {false, true}) {
      const auto chain = render::mipChainRgba8(texels.data(), w, h, srgb);
      auto meanOf = [&](uint32_t level, int channel) {
        const uint32_t lw = std::max(1u, w >> level), lh = std::max(1u, h >> level);
        double sum = 0;
        for (size_t i = 0; i < size_t(lw) * lh; ++i) {
          const double v = chain[levelOffset(w, h, level) + i * 4 + channel] / 255.0;
          sum += srgb && channel != 3 ? srgbDecode(v) : v;
        }
        return sum / (double(lw) * lh);
      };
      for (uint32_t level = 1; level < rhi::mipLevelCount(w, h); ++level)
        for (int c = 0; c < 4; ++c) {
          INFO(w << "x" << h << (srgb ? " sRGB" : " linear") << ", level " << level << ", channel "
                 << c);
          CHECK(std::abs(meanOf(level, c) - meanOf(0, c)) < (srgb ? 0.005 : 0.5 / 255 + 1e-9));
        }
    }
  }
}
