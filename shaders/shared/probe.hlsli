// The ray probe's result record (ProbeHit in path_tracer_shared.h).
#ifndef PENUMBRA_PROBE_HLSLI
#define PENUMBRA_PROBE_HLSLI
#include "surface_hit.hlsli"

ProbeHit packProbeHit(SurfaceHit hit) {
  ProbeHit p;
  p.position = hit.position;
  p.hitT = hit.hitT;
  p.normal = hit.geometricNormal;
  p.unused0 = 0.0;
  p.instanceIndex = hit.instanceIndex;
  p.primitiveIndex = hit.primitiveIndex;
  p.unused1 = 0u;
  p.unused2 = 0u;
  return p;
}

#endif
