// The payload's "no hit" (HitRecord: payloads_shared.h).
#ifndef PENUMBRA_HIT_RECORD_HLSLI
#define PENUMBRA_HIT_RECORD_HLSLI
#include "payloads_shared.h"

HitRecord hitRecordMiss() {
  HitRecord r;
  r.hitT = -1.0;
  r.instance = 0u;
  r.primitive = 0u;
  r.attributes = float3(0.0, 0.0, 0.0);
  return r;
}

#endif
