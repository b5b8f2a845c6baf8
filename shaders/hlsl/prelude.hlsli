// The HLSL side of the shared dialect (docs/ARCHITECTURE.md, "Shaders"): the
// PT_* entry points, built-ins and resource declarations of shaders/stages in
// HLSL, for DXC (DXIL for D3D12: -T lib_6_3 for the ray-tracing stages,
// cs_6_3 for compute). The build includes it before every stage
// (cmake/Shaders.cmake); its GLSL twin is shaders/glsl/prelude.glsl.
//
// With PENUMBRA_HLSL_CHECK the same stages go through glslang's HLSL
// front-end, which knows no DXR: every stage then compiles as a compute
// shader, its payload and attributes file-scope statics and the DXR
// intrinsics stubs, so everything a stage says in the shared dialect is
// parsed and type-checked here, on Linux, although no DXC is at hand. Only
// the DXR spellings in the #else branches below are left to DXC.
#ifndef PENUMBRA_PRELUDE
#define PENUMBRA_PRELUDE
#define PENUMBRA_HLSL 1
#include "bindings.hlsli"

#define PT_ATOMIC_ADD(destination, value) InterlockedAdd(destination, value)

// --- Resources, by register number ------------------------------------------
// [[vk::binding]] for glslang's HLSL front-end (its shift flags do not class
// registers as DXC's -fvk-*-shift do); DXIL takes the register.
#define PT_BUFFER(type, name, t) \
  [[vk::binding(PENUMBRA_T(t), 0)]] StructuredBuffer<type> name : PENUMBRA_REGISTER_T(t)
#define PT_RW_BUFFER(type, name, u) \
  [[vk::binding(PENUMBRA_U(u), 0)]] RWStructuredBuffer<type> name : PENUMBRA_REGISTER_U(u)
// Read-only images are SRVs in DXIL. In SPIR-V from DXC (-spirv) they are
// the read-only storage images the Vulkan side binds (rhi::BindingSetItem::
// storageTexture at a t slot, as glsl/prelude.glsl declares them), not
// sampled images, which the binding set would refuse.
#if defined(__spirv__) && !defined(PENUMBRA_HLSL_CHECK)
#define PT_TEXTURE(name, t) \
  [[vk::binding(PENUMBRA_T(t), 0)]] [[vk::image_format("rgba32f")]] RWTexture2D<float4> name
#define PT_LOAD_TEXTURE(name, p) name[uint2(p)]
#else
#define PT_TEXTURE(name, t) [[vk::binding(PENUMBRA_T(t), 0)]] Texture2D<float4> name : PENUMBRA_REGISTER_T(t)
#define PT_LOAD_TEXTURE(name, p) name.Load(int3(int2(p), 0))
#endif
#define PT_RW_TEXTURE(name, u) \
  [[vk::binding(PENUMBRA_U(u), 0)]] RWTexture2D<float4> name : PENUMBRA_REGISTER_U(u)
#define PT_RW_TEXTURE_RGBA8(name, u) \
  [[vk::binding(PENUMBRA_U(u), 0)]] RWTexture2D<unorm float4> name : PENUMBRA_REGISTER_U(u)
#define PT_LOAD_RW_TEXTURE(name, p) name[uint2(p)]
#define PT_STORE_RW_TEXTURE(name, p, value) name[uint2(p)] = (value)
#define PT_TEXTURE_ARRAY(name, t) \
  [[vk::binding(PENUMBRA_T(t), 0)]] Texture2D<float4> name[] : PENUMBRA_REGISTER_T(t)
#define PT_SAMPLER_ARRAY(name, s) [[vk::binding(PENUMBRA_S(s), 0)]] SamplerState name[] : PENUMBRA_REGISTER_S(s)
// Indices differ between neighbouring threads, hence NonUniformResourceIndex
// (which glslang's HLSL front-end does not take for a uint).
#if defined(PENUMBRA_HLSL_CHECK)
#define PT_NON_UNIFORM(index) (index)
#else
#define PT_NON_UNIFORM(index) NonUniformResourceIndex(index)
#endif
#define PT_SAMPLE_LEVEL(textures, samplers, textureIndex, samplerIndex, uv, level)               \
  textures[PT_NON_UNIFORM(textureIndex)].SampleLevel(samplers[PT_NON_UNIFORM(samplerIndex)], uv, \
                                                     level)
// One sampled texture and one sampler (raster stages).
#define PT_SAMPLED_TEXTURE(name, t) \
  [[vk::binding(PENUMBRA_T(t), 0)]] Texture2D<float4> name : PENUMBRA_REGISTER_T(t)
#define PT_SAMPLER(name, s) [[vk::binding(PENUMBRA_S(s), 0)]] SamplerState name : PENUMBRA_REGISTER_S(s)
#define PT_SAMPLE(tex, smp, uv) tex.Sample(smp, uv)
// The push constants (D3D12 root constants), wrapped in a struct so that
// `loader()` returns a plain value (a ConstantBuffer<T> is not a T).
#define PT_PUSH_CONSTANTS(type, loader) \
  struct loader##Block { type value; }; \
  [[vk::push_constant]] ConstantBuffer<loader##Block> loader##Buffer : PENUMBRA_PUSH_CONSTANTS; \
  type loader() { return loader##Buffer.value; }

#define PT_COMPUTE(name, x, y) \
  [numthreads(x, y, 1)] void name(uint3 ptDispatchThreadId : SV_DispatchThreadID)
#define PT_DISPATCH_THREAD_ID ptDispatchThreadId

// Raster stages: the interface macros become the entry point's parameters
// (glsl/prelude.glsl says how a stage lists them). SV_Position comes first
// in the vertex shader's outputs and the pixel shader's inputs, so the two
// signatures line up element for element.
#define PT_VERTEX_INPUT(index, type, name) , in type name : TEXCOORD##index
#define PT_VERTEX_OUTPUT(index, type, name) , out type name : TEXCOORD##index
#define PT_PIXEL_INPUT(index, type, name) , in type name : TEXCOORD##index
#define PT_VERTEX(name, interface) void name(out float4 ptPosition : SV_Position interface)
#define PT_PIXEL(name, interface) \
  void name(out float4 ptTarget : SV_Target0, in float4 ptFragCoord : SV_Position interface)
#define PT_POSITION ptPosition
#define PT_TARGET ptTarget

#if defined(PENUMBRA_HLSL_CHECK)
// --- glslang's HLSL front-end: the stages as compute shaders ----------------
#define PT_ACCELERATION_STRUCTURE(name, t) \
  [[vk::binding(PENUMBRA_T(t), 0)]] StructuredBuffer<uint> name : PENUMBRA_REGISTER_T(t)
#define PT_RAY_GENERATION(name) [numthreads(1, 1, 1)] void name()
#define PT_MISS(name, payloadType, payload) \
  static payloadType payload; \
  [numthreads(1, 1, 1)] void name()
#define PT_CLOSEST_HIT(name, payloadType, payload, attributeType, attributes) \
  static payloadType payload; \
  static attributeType attributes; \
  [numthreads(1, 1, 1)] void name()
#define PT_CLOSEST_HIT_TRIANGLES(name, payloadType, payload) \
  static payloadType payload; \
  static float2 ptTriangleBarycentrics; \
  [numthreads(1, 1, 1)] void name()
#define PT_ANY_HIT_TRIANGLES(name, payloadType, payload) PT_CLOSEST_HIT_TRIANGLES(name, payloadType, payload)
#define PT_TRIANGLE_BARYCENTRICS ptTriangleBarycentrics
#define PT_HIT_ATTRIBUTES(type, name) static type name
#define PT_INTERSECTION(name) [numthreads(1, 1, 1)] void name()
static float ptCheckReportedT;
#define PT_REPORT_HIT(t, attributes) ptCheckReportedT = (t)
#define PT_IGNORE_HIT return
static uint3 ptCheckLaunchIndex;
static float3 ptCheckRayOrigin;
static float3 ptCheckRayDirection;
static float ptCheckRayTMin;
static float ptCheckRayTCurrent;
static uint ptCheckRayFlags;
static uint ptCheckInstance;
static uint ptCheckPrimitive;
static uint ptCheckGeometry;
#define PT_LAUNCH_INDEX ptCheckLaunchIndex.xy
#define PT_INSTANCE_ID ptCheckInstance
#define PT_PRIMITIVE_INDEX ptCheckPrimitive
#define PT_GEOMETRY_INDEX ptCheckGeometry
#define PT_WORLD_RAY_ORIGIN ptCheckRayOrigin
#define PT_WORLD_RAY_DIRECTION ptCheckRayDirection
#define PT_RAY_TMIN ptCheckRayTMin
#define PT_RAY_TCURRENT ptCheckRayTCurrent
#define PT_HIT_T ptCheckRayTCurrent
#define PT_INCOMING_RAY_SKIPS_CLOSEST_HIT ((ptCheckRayFlags & 8u) != 0u)
#define PT_RAY_FLAG_NONE 0u
#define PT_RAY_FLAG_SHADOW 12u
#define PT_TRACE_PAYLOAD(type) static uint ptCheckTraceFlags
// The arguments' types are checked by the arithmetic; the payload is written.
#define PT_TRACE_RAY(scene, flags, hitGroup, hitGroupStride, miss, origin, tMin, direction, tMax, payload) \
  ptCheckTraceFlags = (flags) + (hitGroup) + (hitGroupStride) + (miss) + scene[0]; \
  payload.hitT = dot(origin, direction) + (tMin) + (tMax)
#else
// --- DXC: DXR --------------------------------------------------------------
// [[vk::binding]] for DXC's SPIR-V mode (PENUMBRA_SPIRV_COMPILER=dxc); DXIL ignores it.
#define PT_ACCELERATION_STRUCTURE(name, t) \
  [[vk::binding(PENUMBRA_T(t), 0)]] RaytracingAccelerationStructure name : PENUMBRA_REGISTER_T(t)
#define PT_RAY_GENERATION(name) [shader("raygeneration")] void name()
#define PT_MISS(name, payloadType, payload) [shader("miss")] void name(inout payloadType payload)
#define PT_CLOSEST_HIT(name, payloadType, payload, attributeType, attributes) \
  [shader("closesthit")] void name(inout payloadType payload, in attributeType attributes)
#define PT_CLOSEST_HIT_TRIANGLES(name, payloadType, payload) \
  [shader("closesthit")] void name(inout payloadType payload, in BuiltInTriangleIntersectionAttributes ptTriangle)
#define PT_ANY_HIT_TRIANGLES(name, payloadType, payload) \
  [shader("anyhit")] void name(inout payloadType payload, in BuiltInTriangleIntersectionAttributes ptTriangle)
#define PT_TRIANGLE_BARYCENTRICS ptTriangle.barycentrics
// A file-scope static: DXR's ReportHit takes the attributes as an argument.
#define PT_HIT_ATTRIBUTES(type, name) static type name
#define PT_INTERSECTION(name) [shader("intersection")] void name()
#define PT_REPORT_HIT(t, attributes) ReportHit(t, 0u, attributes)
#define PT_IGNORE_HIT IgnoreHit()
#define PT_LAUNCH_INDEX DispatchRaysIndex().xy
#define PT_INSTANCE_ID InstanceID()
#define PT_PRIMITIVE_INDEX PrimitiveIndex()
#define PT_GEOMETRY_INDEX GeometryIndex()
#define PT_WORLD_RAY_ORIGIN WorldRayOrigin()
#define PT_WORLD_RAY_DIRECTION WorldRayDirection()
#define PT_RAY_TMIN RayTMin()
#define PT_RAY_TCURRENT RayTCurrent()
#define PT_HIT_T RayTCurrent()
#define PT_INCOMING_RAY_SKIPS_CLOSEST_HIT ((RayFlags() & RAY_FLAG_SKIP_CLOSEST_HIT_SHADER) != 0u)
#define PT_RAY_FLAG_NONE RAY_FLAG_NONE
#define PT_RAY_FLAG_SHADOW (RAY_FLAG_ACCEPT_FIRST_HIT_AND_END_SEARCH | RAY_FLAG_SKIP_CLOSEST_HIT_SHADER)
#define PT_TRACE_PAYLOAD(type) static const uint ptTracePayloadIsALocal = 0u
#define PT_TRACE_RAY(scene, flags, hitGroup, hitGroupStride, miss, origin, tMin, direction, tMax, payload) \
  { \
    RayDesc ptRay; \
    ptRay.Origin = origin; \
    ptRay.Direction = direction; \
    ptRay.TMin = tMin; \
    ptRay.TMax = tMax; \
    TraceRay(scene, flags, 0xff, hitGroup, hitGroupStride, miss, ptRay, payload); \
  }
#endif
#endif
