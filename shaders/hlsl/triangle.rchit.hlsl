// Triangle closest hit (DXR twin of glsl/triangle.rchit): which triangle
// and where on it; the ray generation shader rebuilds the surface.
#include "path_trace_common.hlsli"

[shader("closesthit")]
void main(inout HitRecord hit, in BuiltInTriangleIntersectionAttributes attributes) {
  hit.hitT = RayTCurrent();
  // A TLAS instance holds one mesh, or (the merged BLAS) one per geometry.
  hit.instance = InstanceID() + GeometryIndex();
  hit.primitive = PrimitiveIndex();
  hit.attributes = float3(attributes.barycentrics, 0.0);
}
