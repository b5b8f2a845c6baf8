// Shared declarations of the RHI conformance shaders (tests/rhi/test_ray_tracing.cpp).
#extension GL_EXT_ray_tracing : require

struct ProbeRay {
  vec4 origin;     // xyz; w = tMax
  vec4 direction;  // xyz; w = miss shader index (as a float)
};

struct ProbeResult {
  uvec4 ids;   // x record tag of the shader that ran, y InstanceCustomIndex, z PrimitiveID, w hit kind
  vec4 hit;    // x hitT (-1 on a miss), yzw object-space hit position
};

struct ProbePayload {
  uint tag;
  uint instanceId;
  uint primitiveId;
  uint hitKind;
  float hitT;
  vec3 objectPosition;
};
