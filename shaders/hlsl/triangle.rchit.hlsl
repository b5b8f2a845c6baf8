// Triangle closest hit (DXR twin of glsl/triangle.rchit): which triangle
// and where on it; the ray generation shader rebuilds the surface.
#include "path_trace_common.hlsli"

[shader("closesthit")]
void main(inout HitRecord hit, in BuiltInTriangleIntersectionAttributes attributes) {
  hit.hitT = RayTCurrent();
  hit.instance = InstanceID();
  hit.primitive = PrimitiveIndex();
  hit.attributes = float3(attributes.barycentrics, 0.0);
}
