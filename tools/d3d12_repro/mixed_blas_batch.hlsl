// Shaders of mixed_blas_batch.c: rays along +z over [-1,1]^2; the payload's
// x is 1 where the triangle is hit, 2 where the box is, 0 on a miss.
RaytracingAccelerationStructure Scene : register(t0, space0);
RWStructuredBuffer<float4> Output : register(u0, space0);
struct Payload { float4 color; };
struct BoxAttributes { float2 unused; };
[shader("raygeneration")] void RayGen() {
  uint2 idx = DispatchRaysIndex().xy, dim = DispatchRaysDimensions().xy;
  float2 uv = (float2(idx) + 0.5) / float2(dim) * 2.0 - 1.0;
  RayDesc ray; ray.Origin = float3(uv.x, -uv.y, -1.0); ray.Direction = float3(0, 0, 1); ray.TMin = 0.001; ray.TMax = 100.0;
  Payload p; p.color = float4(-1, 0, 0, 0);
  TraceRay(Scene, RAY_FLAG_NONE, 0xFF, 0, 1, 0, ray, p);
  Output[idx.y * dim.x + idx.x] = p.color;
}
[shader("miss")] void Miss(inout Payload p) { p.color = float4(0, 0, 0, 1); }
[shader("closesthit")] void TriangleHit(inout Payload p, in BuiltInTriangleIntersectionAttributes a) { p.color = float4(1, 0, 0, 1); }
// The box itself: a hit where the ray enters the AABB (its front face, z = -0.5).
[shader("intersection")] void BoxIntersection() {
  BoxAttributes a; a.unused = float2(0, 0);
  ReportHit(0.5, 0, a);
}
[shader("closesthit")] void BoxHit(inout Payload p, in BoxAttributes a) { p.color = float4(2, 0, 0, 1); }
