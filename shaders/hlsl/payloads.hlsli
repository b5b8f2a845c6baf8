// Ray payloads of the path tracer's DXR entry points: every ray, radiance
// or shadow, carries a HitRecord (24 bytes: RayTracingPipelineDesc::
// maxPayloadBytes; the twin of GLSL payload location 0), so the any-hit and
// miss shaders are the same for both.
#ifndef PENUMBRA_PAYLOADS_HLSLI
#define PENUMBRA_PAYLOADS_HLSLI
#include "hit_record.hlsli"

#endif
