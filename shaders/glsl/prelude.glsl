// The GLSL side of the shared dialect (docs/ARCHITECTURE.md, "Shaders"):
// maps HLSL's types and intrinsics, and the PT_* entry points, built-ins and
// resource declarations of shaders/stages, onto GLSL for glslang. The build
// includes it before every stage (cmake/Shaders.cmake), with PT_STAGE_* naming
// the stage; its HLSL twin is shaders/hlsl/prelude.hlsli.
#ifndef PENUMBRA_PRELUDE
#define PENUMBRA_PRELUDE
#if defined(PT_STAGE_RAY_TRACING)
#extension GL_EXT_ray_tracing : require
#endif
#extension GL_EXT_nonuniform_qualifier : require
#define PENUMBRA_GLSL 1

// --- HLSL types and intrinsics -------------------------------------------
#define float2 vec2
#define float3 vec3
#define float4 vec4
#define int2 ivec2
#define int3 ivec3
#define int4 ivec4
#define uint2 uvec2
#define uint3 uvec3
#define uint4 uvec4
#define static
#define lerp mix
#define frac fract
#define rsqrt inversesqrt
#define atan2 atan
#define asuint floatBitsToUint
#define reversebits bitfieldReverse
#define asint floatBitsToInt
float asfloat(uint x) { return uintBitsToFloat(x); }
float asfloat(int x) { return intBitsToFloat(x); }
float3 asfloat(uint3 x) { return uintBitsToFloat(x); }
float3 asfloat(int3 x) { return intBitsToFloat(x); }
float saturate(float x) { return clamp(x, 0.0, 1.0); }
float3 saturate(float3 x) { return clamp(x, float3(0.0, 0.0, 0.0), float3(1.0, 1.0, 1.0)); }
#define PT_ATOMIC_ADD(destination, value) atomicAdd(destination, value)

#include "bindings.hlsli"

// --- Resources, by HLSL register number (bindings.hlsli shifts them) -------
// A T-class buffer or image is read-only, a U-class one read-write. Buffers
// are arrays (a single value is name[0]), so both APIs index them alike.
#define PT_ACCELERATION_STRUCTURE(name, t) \
  layout(set = 0, binding = PENUMBRA_T(t)) uniform accelerationStructureEXT name
#define PT_BUFFER(type, name, t) \
  layout(set = 0, binding = PENUMBRA_T(t), std430) readonly buffer name##Block { type name[]; }
#define PT_RW_BUFFER(type, name, u) \
  layout(set = 0, binding = PENUMBRA_U(u), std430) buffer name##Block { type name[]; }
// RGBA32F images: read-only (D3D12 SRV) and read-write (UAV).
#define PT_TEXTURE(name, t) layout(set = 0, binding = PENUMBRA_T(t), rgba32f) readonly uniform image2D name
#define PT_RW_TEXTURE(name, u) layout(set = 0, binding = PENUMBRA_U(u), rgba32f) uniform image2D name
#define PT_RW_TEXTURE_RGBA8(name, u) layout(set = 0, binding = PENUMBRA_U(u), rgba8) uniform image2D name
#define PT_LOAD_TEXTURE(name, p) imageLoad(name, int2(p))
#define PT_LOAD_RW_TEXTURE(name, p) imageLoad(name, int2(p))
#define PT_STORE_RW_TEXTURE(name, p, value) imageStore(name, int2(p), value)
// Bindless: unbounded arrays of sampled textures and of samplers; indices
// differ between neighbouring threads, hence nonuniformEXT.
#define PT_TEXTURE_ARRAY(name, t) layout(set = 0, binding = PENUMBRA_T(t)) uniform texture2D name[]
#define PT_SAMPLER_ARRAY(name, s) layout(set = 0, binding = PENUMBRA_S(s)) uniform sampler name[]
#define PT_SAMPLE_LEVEL(textures, samplers, textureIndex, samplerIndex, uv, level) \
  textureLod(sampler2D(textures[nonuniformEXT(textureIndex)], samplers[nonuniformEXT(samplerIndex)]), uv, level)
// One sampled texture and one sampler (raster stages).
#define PT_SAMPLED_TEXTURE(name, t) layout(set = 0, binding = PENUMBRA_T(t)) uniform texture2D name
#define PT_SAMPLER(name, s) layout(set = 0, binding = PENUMBRA_S(s)) uniform sampler name
#define PT_SAMPLE(tex, smp, uv) texture(sampler2D(tex, smp), uv)
// The push-constant block, read through `loader()` (a copy, as HLSL's
// ConstantBuffer<T> must be read).
#define PT_PUSH_CONSTANTS(type, loader) \
  layout(push_constant, std430) uniform loader##Block { type loader##Value; }; \
  type loader() { return loader##Value; }

// --- Entry points -----------------------------------------------------------
// Payload location 0 carries every ray's HitRecord (radiance and shadow).
#define PT_RAY_GENERATION(name) void main()
#define PT_MISS(name, payloadType, payload) \
  layout(location = 0) rayPayloadInEXT payloadType payload; \
  void main()
#define PT_CLOSEST_HIT(name, payloadType, payload, attributeType, attributes) \
  layout(location = 0) rayPayloadInEXT payloadType payload; \
  hitAttributeEXT attributeType attributes; \
  void main()
// Triangles: the built-in attributes, read as PT_TRIANGLE_BARYCENTRICS.
#define PT_CLOSEST_HIT_TRIANGLES(name, payloadType, payload) \
  layout(location = 0) rayPayloadInEXT payloadType payload; \
  hitAttributeEXT float2 ptTriangleBarycentrics; \
  void main()
#define PT_ANY_HIT_TRIANGLES(name, payloadType, payload) \
  hitAttributeEXT float2 ptTriangleBarycentrics; \
  void main()
#define PT_TRIANGLE_BARYCENTRICS ptTriangleBarycentrics
// An intersection shader's attributes are declared once, at file scope, and
// passed to PT_REPORT_HIT.
#define PT_HIT_ATTRIBUTES(type, name) hitAttributeEXT type name
#define PT_INTERSECTION(name) void main()
#define PT_REPORT_HIT(t, attributes) reportIntersectionEXT(t, 0u)
#define PT_IGNORE_HIT ignoreIntersectionEXT
#define PT_COMPUTE(name, x, y) \
  layout(local_size_x = x, local_size_y = y) in; \
  void main()

// Raster stages (rhi::GraphicsPipelineDesc). The interface is a list of
// PT_VERTEX_INPUT / PT_VERTEX_OUTPUT / PT_PIXEL_INPUT, one macro argument
// without separators: GLSL declares them at file scope, HLSL as the entry
// point's parameters. Location N is HLSL's TEXCOORD<N> (rhi::VertexAttribute).
// The vertex shader writes PT_POSITION (clip space, +y up as in D3D12: the
// RHI flips Vulkan's viewport), the pixel shader PT_TARGET (render target 0).
#define PT_VERTEX_INPUT(index, type, name) layout(location = index) in type name;
#define PT_VERTEX_OUTPUT(index, type, name) layout(location = index) out type name;
#define PT_PIXEL_INPUT(index, type, name) layout(location = index) in type name;
#define PT_VERTEX(name, interface) \
  interface \
  void main()
#define PT_PIXEL(name, interface) \
  interface \
  layout(location = 0) out float4 ptTarget; \
  void main()
#define PT_POSITION gl_Position
#define PT_TARGET ptTarget

// --- Built-ins ------------------------------------------------------------
#define PT_DISPATCH_THREAD_ID gl_GlobalInvocationID
#define PT_LAUNCH_INDEX gl_LaunchIDEXT.xy
#define PT_INSTANCE_ID uint(gl_InstanceCustomIndexEXT)
#define PT_PRIMITIVE_INDEX uint(gl_PrimitiveID)
#define PT_GEOMETRY_INDEX uint(gl_GeometryIndexEXT)
#define PT_WORLD_RAY_ORIGIN gl_WorldRayOriginEXT
#define PT_WORLD_RAY_DIRECTION gl_WorldRayDirectionEXT
#define PT_RAY_TMIN gl_RayTminEXT
// The closest hit so far (intersection), or the hit's distance (closest hit).
#define PT_RAY_TCURRENT gl_RayTmaxEXT
#define PT_HIT_T gl_HitTEXT
#define PT_INCOMING_RAY_SKIPS_CLOSEST_HIT ((gl_IncomingRayFlagsEXT & gl_RayFlagsSkipClosestHitShaderEXT) != 0u)

// --- Tracing ----------------------------------------------------------------
#define PT_RAY_FLAG_NONE gl_RayFlagsNoneEXT
#define PT_RAY_FLAG_SHADOW (gl_RayFlagsTerminateOnFirstHitEXT | gl_RayFlagsSkipClosestHitShaderEXT)
// Declares the payload a ray-generation shader traces with (file scope).
#define PT_TRACE_PAYLOAD(type) layout(location = 0) rayPayloadEXT type ptTracePayload
// Traces `payload` (a variable, read and written) through the scene.
#define PT_TRACE_RAY(scene, flags, hitGroup, hitGroupStride, miss, origin, tMin, direction, tMax, payload) \
  ptTracePayload = payload; \
  traceRayEXT(scene, flags, 0xff, hitGroup, hitGroupStride, miss, origin, tMin, direction, tMax, 0); \
  payload = ptTracePayload
#endif
