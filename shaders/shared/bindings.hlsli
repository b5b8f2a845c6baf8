// The register-to-binding shift table, defined here once: HLSL register(tN)
// is Vulkan binding PENUMBRA_T(N), and so on (render::kShaderBindingOffsets,
// engine/penumbra/render/shader_binding_offsets.h, reads the same macros and
// hands them to the device as rhi::BindingOffsets). Plain macros, so C++,
// GLSL layout qualifiers and HLSL attributes can all use them.
#ifndef PENUMBRA_BINDINGS_HLSLI
#define PENUMBRA_BINDINGS_HLSLI
#define PENUMBRA_B(n) (0 + (n))
#define PENUMBRA_T(n) (32 + (n))
#define PENUMBRA_U(n) (64 + (n))
#define PENUMBRA_S(n) (96 + (n))

// D3D12 root constants (engine/penumbra/rhi/root_signature_layout.h): the push-constant
// block of a DXR/compute entry point and a shader's local record data. HLSL:
//   [[vk::push_constant]] ConstantBuffer<T> gPush : PENUMBRA_PUSH_CONSTANTS;
//   [[vk::shader_record_ext]] ConstantBuffer<R> gRecord : PENUMBRA_SHADER_RECORD;
// The spaces are numbers here once; render::kShaderBindingOffsets gives them
// to the device, whose D3D12 root signatures use them
// (root_signature_layout.h), so the two sides cannot disagree.
#define PENUMBRA_PUSH_CONSTANT_SPACE 900
#define PENUMBRA_SHADER_RECORD_SPACE 901
#define PENUMBRA_PUSH_CONSTANTS register(b0, PENUMBRA_CAT(space, PENUMBRA_PUSH_CONSTANT_SPACE))
// register(tN) etc. from a macro that expands to the number N, so DXR entry
// points take register numbers from the same *_shared.h defines as the host.
#define PENUMBRA_CAT_(a, b) a##b
#define PENUMBRA_CAT(a, b) PENUMBRA_CAT_(a, b)
#define PENUMBRA_REGISTER_B(n) register(PENUMBRA_CAT(b, n))
#define PENUMBRA_REGISTER_T(n) register(PENUMBRA_CAT(t, n))
#define PENUMBRA_REGISTER_U(n) register(PENUMBRA_CAT(u, n))
#define PENUMBRA_REGISTER_S(n) register(PENUMBRA_CAT(s, n))
#define PENUMBRA_SHADER_RECORD register(b0, PENUMBRA_CAT(space, PENUMBRA_SHADER_RECORD_SPACE))
#endif
