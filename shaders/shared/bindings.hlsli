// Register-to-binding shift table (engine/rhi/register_shifts.h): HLSL
// register(tN) is Vulkan binding PENUMBRA_T(N), and so on. Plain macros, so
// C++, GLSL layout qualifiers and HLSL attributes can all use them.
#ifndef PENUMBRA_BINDINGS_HLSLI
#define PENUMBRA_BINDINGS_HLSLI
#define PENUMBRA_B(n) (0 + (n))
#define PENUMBRA_T(n) (32 + (n))
#define PENUMBRA_U(n) (64 + (n))
#define PENUMBRA_S(n) (96 + (n))
#endif
