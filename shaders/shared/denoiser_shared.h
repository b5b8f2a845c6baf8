// Host/shader interface of the denoiser (engine/penumbra/render/denoiser.h): one
// compute shader (denoise.comp) whose push constant selects the pass, the
// images it reads and writes, and the per-frame constants.
#ifndef PENUMBRA_DENOISER_SHARED_H
#define PENUMBRA_DENOISER_SHARED_H

#include "camera_shared.h"  // its own namespace: before this file's

#ifdef __cplusplus
#include <cstddef>  // offsetof

#include "shader_types.h"
namespace penumbra::gpu {
#endif

#include "bindings.hlsli"

// Read-only images (t registers): the path tracer's outputs, then history.
#define DN_T_BEAUTY 0               // the path tracer's accumulation (radiance)
#define DN_T_ALBEDO 1               // guide buffers (PT_U_GUIDE_* in path_tracer_shared.h)
#define DN_T_NORMAL_DEPTH 2
#define DN_T_EMISSION 3
#define DN_T_SAMPLE_MOMENTS 4
#define DN_T_HISTORY_ILLUMINATION 5  // last frame's first a-trous iteration
#define DN_T_HISTORY_MOMENTS 6       // last frame's integrated moments and history length
#define DN_T_HISTORY_NORMAL_DEPTH 7  // last frame's normal and depth guide
#define DN_T_ILLUMINATION 8          // the illumination a pass filters (ping)
#define DN_T_FRAME 9                 // DenoiseFrame
#define DN_T_HISTORY_ALBEDO 10       // last frame's integrated albedo
#define DN_T_HISTORY_EMISSION 11     // last frame's integrated emission
// Read-write images (u registers).
#define DN_U_ILLUMINATION 0          // what a pass writes (pong): rgb illumination, a variance
#define DN_U_MOMENTS 1               // this frame's integrated moments: x m1, y m2, z history length, w samples behind it
#define DN_U_HISTORY_ILLUMINATION 2  // next frame's DN_T_HISTORY_ILLUMINATION
#define DN_U_HISTORY_NORMAL_DEPTH 3  // next frame's DN_T_HISTORY_NORMAL_DEPTH
#define DN_U_OUTPUT 4                // the denoised radiance
#define DN_U_MOTION 5                // xy: where the pixel was in the previous frame, minus where it is (pixels)
// This frame's albedo and emission guides, integrated over the history like
// the illumination (a 1 spp guide is noisy at edges): what the later passes
// and the re-modulation use, and next frame's DN_T_HISTORY_ALBEDO/EMISSION.
#define DN_U_ALBEDO 6
#define DN_U_EMISSION 7

#define DN_PASS_TEMPORAL 0u  // demodulate, reproject, integrate history
#define DN_PASS_VARIANCE 1u  // spatial variance where too few samples lie behind a pixel
#define DN_PASS_ATROUS 2u    // one a-trous iteration (push constant stepWidth)
#define DN_PASS_COMPOSE 3u   // re-modulate, add emission back

#define DN_FLAG_TEMPORAL 1u         // reproject and integrate history (else: single frame)
#define DN_FLAG_HISTORY_VALID 2u    // the history images hold a previous frame
#define DN_FLAG_FIREFLY_CLAMP 4u    // clamp illumination to the brightest of the 8 neighbours
#define DN_FLAG_WRITE_HISTORY 8u    // this a-trous iteration also writes the history illumination

struct DenoisePush {
  uint pass;
  uint stepWidth;  // a-trous: 1, 2, 4, ...
  uint flags;
  uint padding;
};

// A camera as FrameConstants holds it (path tracer's recordFrame).
struct DenoiseFrame {
  CameraData camera;
  CameraData previousCamera;  // the camera of the history
  uint width;
  uint height;
  uint samplesPerPixel;  // in the inputs
  uint maxHistory;       // frames of history at most
  float depthSigma;      // scale on the depth gradient (SVGF's sigma_z); 0: off
  float normalExponent;  // (n . n_q)^exponent (SVGF's sigma_n); 0: off
  float luminanceSigma;  // luminance difference in standard deviations (SVGF's sigma_l); 0: off
  float albedoFloor;     // demodulation never divides by less
  // 1: both cameras are orthographic (their filmHalfHeight in world units;
  // the path tracer's PT_SCENE_ORTHOGRAPHIC), 0: both perspective.
  uint orthographic;
  uint unused0;
  uint unused1;
  uint unused2;
};

#ifdef __cplusplus
static_assert(sizeof(DenoisePush) == 16);
static_assert(sizeof(DenoiseFrame) == 176 && offsetof(DenoiseFrame, width) == 128);
}  // namespace penumbra::gpu
#endif
#endif
