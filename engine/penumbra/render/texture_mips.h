#pragma once
// Mip chains of 8-bit RGBA textures, made on the host when a scene's textures
// are uploaded: rays pick a level by their footprint (ray cones,
// textures.hlsli), so minified textures are filtered instead of aliased.
#include <cstdint>
#include <vector>

namespace penumbra::render {

// sRGB's transfer function (IEC 61966-2-1), on [0, 1].
float srgbToLinear(float c);
float linearToSrgb(float c);

// Every level of a width x height RGBA8 image down to 1x1, largest first,
// tightly packed (level i is max(1, width >> i) x max(1, height >> i)), as
// rhi::ICommandList::writeTexture takes them. Each texel of a level is the
// box-filtered mean of the area of the level above that it covers: 2x2
// texels where that level's sizes are even, fractions of three texels along
// an odd one, so every level keeps the image's mean. Means are taken in
// linear light: sRGB colour is
// decoded before averaging and encoded after; alpha and non-sRGB data are
// averaged as they are. Levels are computed from the level above in float,
// so rounding does not accumulate.
std::vector<uint8_t> mipChainRgba8(const uint8_t* rgba8, uint32_t width, uint32_t height,
                                   bool srgb);

}  // namespace penumbra::render
