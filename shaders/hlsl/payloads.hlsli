// Ray payloads of the path tracer's DXR entry points. The radiance ray
// carries a HitRecord (24 bytes: RayTracingPipelineDesc::maxPayloadBytes);
// the shadow ray a visibility flag, set only by its miss shader (the twins
// of GLSL payload locations 0 and 1).
#ifndef PENUMBRA_PAYLOADS_HLSLI
#define PENUMBRA_PAYLOADS_HLSLI
#include "hit_record.hlsli"

struct ShadowPayload {
  uint visible;
};

#endif
