// Host/shader interface of the two tone-mapping passes (engine/penumbra/render/
// tonemapper.h: RGBA8 pixels for PNG files; engine/penumbra/render/display_pass.h: the
// viewer's window image): their registers and push-constant blocks, read by
// the C++ and by shaders/stages/tonemap.comp and display.comp.
#ifndef PENUMBRA_DISPLAY_SHARED_H
#define PENUMBRA_DISPLAY_SHARED_H

#ifdef __cplusplus
#include "shader_types.h"
namespace penumbra::gpu {
#endif

#include "bindings.hlsli"

#define TM_T_INPUT 0   // RGBA32F radiance (both passes)
#define TM_U_OUTPUT 0  // tonemap.comp: uint RGBA8 per pixel, row-major; display.comp: an RGBA8 image

struct TonemapPush {
  uint width;
  uint height;
  float exposure;      // stops
  uint toneOperator;   // render::ToneOperator
};

struct DisplayPush {
  uint sourceWidth;  // the radiance image
  uint sourceHeight;
  uint targetWidth;  // the window image (nearest texel: scale 1 is a 1:1 copy)
  uint targetHeight;
  float exposure;
  uint toneOperator;
  uint channels;  // render::DisplayChannels: beauty or one guide buffer
};

#ifdef __cplusplus
static_assert(sizeof(TonemapPush) == 16);
static_assert(sizeof(DisplayPush) == 28);
}  // namespace penumbra::gpu
#endif
#endif
