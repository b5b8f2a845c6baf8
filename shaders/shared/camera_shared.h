// The camera as the host hands it to the shaders (FrameConstants.camera,
// DenoiseFrame's cameras).
#ifndef PENUMBRA_CAMERA_SHARED_H
#define PENUMBRA_CAMERA_SHARED_H

#ifdef __cplusplus
#include <cstddef>  // offsetof

#include "shader_types.h"
namespace penumbra::gpu {
#endif

// The camera as the shaders see it (shaders/shared/camera.hlsli): a pinhole
// at `position`, or a thin lens when apertureRadius > 0; rays fan out from it
// (perspective), or leave the film plane along `forward` where the frame's
// PT_SCENE_ORTHOGRAPHIC / DenoiseFrame.orthographic says so. Each float3 and
// the float after it fill one 16-byte row, laid out alike in C++, std430,
// HLSL constant buffers and structured buffers (FrameConstants has no room
// for a row more: push constants stop at 128 bytes).
struct CameraData {
  float3 position;       // render space: relative to the render origin
  // Half the film's height: at unit distance ahead, tan(vertical field of
  // view / 2), for a perspective camera; in world units for an orthographic one.
  float filmHalfHeight;
  float3 right;          // unit
  float aspectRatio;     // width / height
  float3 up;             // unit
  float apertureRadius;  // thin lens; 0: pinhole
  float3 forward;        // unit
  float focusDistance;   // along forward, to the plane in focus
};

#ifdef __cplusplus
// The offsets std430 and HLSL packing give: each float3 opens a 16-byte row.
static_assert(sizeof(CameraData) == 64 && offsetof(CameraData, filmHalfHeight) == 12 &&
              offsetof(CameraData, right) == 16 && offsetof(CameraData, forward) == 48);
}  // namespace penumbra::gpu
#endif
#endif
