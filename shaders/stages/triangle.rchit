// Triangle closest hit: which triangle and where on it. The ray generation
// shader rebuilds the surface (surface_from_record.hlsli).
#include "path_trace_resources.hlsli"

PT_CLOSEST_HIT_TRIANGLES(main, HitRecord, hit) {
  hit.hitT = PT_HIT_T;
  // A TLAS instance holds one mesh, or (the merged BLAS) one per geometry.
  hit.instance = PT_INSTANCE_ID + PT_GEOMETRY_INDEX;
  hit.primitive = PT_PRIMITIVE_INDEX;
  hit.attributes = float3(PT_TRIANGLE_BARYCENTRICS, 0.0);
}
