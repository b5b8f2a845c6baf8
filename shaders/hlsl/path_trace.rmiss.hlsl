// Radiance-ray miss (DXR twin of glsl/path_trace.rmiss): no environment yet.
#include "payloads.hlsli"

[shader("miss")]
void main(inout HitRecord hit) { hit = hitRecordMiss(); }
