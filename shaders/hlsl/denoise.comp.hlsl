// Every pass of the denoiser (DXC twin of glsl/denoise.comp), compiled -T cs_6_3.
#include "denoiser_shared.h"

[[vk::push_constant]] ConstantBuffer<DenoisePush> gPush : PENUMBRA_PUSH_CONSTANTS;
Texture2D<float4> gBeauty : PENUMBRA_REGISTER_T(DN_T_BEAUTY);
Texture2D<float4> gAlbedo : PENUMBRA_REGISTER_T(DN_T_ALBEDO);
Texture2D<float4> gNormalDepth : PENUMBRA_REGISTER_T(DN_T_NORMAL_DEPTH);
Texture2D<float4> gEmission : PENUMBRA_REGISTER_T(DN_T_EMISSION);
Texture2D<float4> gSampleMoments : PENUMBRA_REGISTER_T(DN_T_SAMPLE_MOMENTS);
Texture2D<float4> gHistoryIllumination : PENUMBRA_REGISTER_T(DN_T_HISTORY_ILLUMINATION);
Texture2D<float4> gHistoryMoments : PENUMBRA_REGISTER_T(DN_T_HISTORY_MOMENTS);
Texture2D<float4> gHistoryNormalDepth : PENUMBRA_REGISTER_T(DN_T_HISTORY_NORMAL_DEPTH);
Texture2D<float4> gIlluminationIn : PENUMBRA_REGISTER_T(DN_T_ILLUMINATION);
StructuredBuffer<DenoiseFrame> gFrame : PENUMBRA_REGISTER_T(DN_T_FRAME);
RWTexture2D<float4> gIlluminationOut : PENUMBRA_REGISTER_U(DN_U_ILLUMINATION);
RWTexture2D<float4> gMoments : PENUMBRA_REGISTER_U(DN_U_MOMENTS);
RWTexture2D<float4> gHistoryIlluminationOut : PENUMBRA_REGISTER_U(DN_U_HISTORY_ILLUMINATION);
RWTexture2D<float4> gHistoryNormalDepthOut : PENUMBRA_REGISTER_U(DN_U_HISTORY_NORMAL_DEPTH);
RWTexture2D<float4> gOutput : PENUMBRA_REGISTER_U(DN_U_OUTPUT);
RWTexture2D<float4> gMotion : PENUMBRA_REGISTER_U(DN_U_MOTION);
Texture2D<float4> gHistoryAlbedo : PENUMBRA_REGISTER_T(DN_T_HISTORY_ALBEDO);
Texture2D<float4> gHistoryEmission : PENUMBRA_REGISTER_T(DN_T_HISTORY_EMISSION);
RWTexture2D<float4> gIntegratedAlbedo : PENUMBRA_REGISTER_U(DN_U_ALBEDO);
RWTexture2D<float4> gIntegratedEmission : PENUMBRA_REGISTER_U(DN_U_EMISSION);

DenoiseFrame loadFrame() { return gFrame[0]; }
float4 loadBeauty(int2 p) { return gBeauty.Load(int3(p, 0)); }
float4 loadAlbedo(int2 p) { return gAlbedo.Load(int3(p, 0)); }
float4 loadNormalDepth(int2 p) { return gNormalDepth.Load(int3(p, 0)); }
float4 loadEmission(int2 p) { return gEmission.Load(int3(p, 0)); }
float4 loadSampleMoments(int2 p) { return gSampleMoments.Load(int3(p, 0)); }
float4 loadHistoryIllumination(int2 p) { return gHistoryIllumination.Load(int3(p, 0)); }
float4 loadHistoryMoments(int2 p) { return gHistoryMoments.Load(int3(p, 0)); }
float4 loadHistoryNormalDepth(int2 p) { return gHistoryNormalDepth.Load(int3(p, 0)); }
float4 loadIllumination(int2 p) { return gIlluminationIn.Load(int3(p, 0)); }
float4 loadMoments(int2 p) { return gMoments[p]; }
void storeIllumination(int2 p, float4 v) { gIlluminationOut[p] = v; }
void storeMoments(int2 p, float4 v) { gMoments[p] = v; }
void storeHistoryIllumination(int2 p, float4 v) { gHistoryIlluminationOut[p] = v; }
void storeHistoryNormalDepth(int2 p, float4 v) { gHistoryNormalDepthOut[p] = v; }
void storeOutput(int2 p, float4 v) { gOutput[p] = v; }
void storeMotion(int2 p, float4 v) { gMotion[p] = v; }
float4 loadHistoryAlbedo(int2 p) { return gHistoryAlbedo.Load(int3(p, 0)); }
float4 loadHistoryEmission(int2 p) { return gHistoryEmission.Load(int3(p, 0)); }
float4 loadIntegratedAlbedo(int2 p) { return gIntegratedAlbedo[p]; }
float4 loadIntegratedEmission(int2 p) { return gIntegratedEmission[p]; }
void storeIntegratedAlbedo(int2 p, float4 v) { gIntegratedAlbedo[p] = v; }
void storeIntegratedEmission(int2 p, float4 v) { gIntegratedEmission[p] = v; }
#include "denoiser.hlsli"

[numthreads(8, 8, 1)]
void main(uint3 id : SV_DispatchThreadID) { denoisePass(int2(id.xy), gPush); }
