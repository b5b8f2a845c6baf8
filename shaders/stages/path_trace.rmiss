// The one miss shader, of radiance and shadow rays alike: the record says
// "no hit" (hitT < 0); the ray-generation shader looks up the environment.
#include "hit_record.hlsli"

PT_MISS(main, HitRecord, hit) { hit = hitRecordMiss(); }
