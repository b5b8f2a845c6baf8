// The ray probe's result record (ProbeHit in path_tracer_shared.h).
#ifndef PENUMBRA_PROBE_HLSLI
#define PENUMBRA_PROBE_HLSLI
#include "surface_hit.hlsli"

ProbeHit packProbeHit(SurfaceHit hit) {
  ProbeHit p;
  p.position = float4(hit.position, hit.hitT);
  p.normal = float4(hit.geometricNormal, 0.0);
  p.ids = uint4(hit.instanceIndex, hit.primitiveIndex, 0u, 0u);
  return p;
}

#endif
