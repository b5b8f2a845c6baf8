// Every pass of the denoiser (engine/penumbra/render/denoiser.h); the push constant
// picks one. The kernels are in shaders/shared/denoiser.hlsli.
#include "denoiser_shared.h"

PT_PUSH_CONSTANTS(DenoisePush, denoisePush);
PT_TEXTURE(gBeauty, DN_T_BEAUTY);
PT_TEXTURE(gAlbedo, DN_T_ALBEDO);
PT_TEXTURE(gNormalDepth, DN_T_NORMAL_DEPTH);
PT_TEXTURE(gEmission, DN_T_EMISSION);
PT_TEXTURE(gSampleMoments, DN_T_SAMPLE_MOMENTS);
PT_TEXTURE(gHistoryIllumination, DN_T_HISTORY_ILLUMINATION);
PT_TEXTURE(gHistoryMoments, DN_T_HISTORY_MOMENTS);
PT_TEXTURE(gHistoryNormalDepth, DN_T_HISTORY_NORMAL_DEPTH);
PT_TEXTURE(gIlluminationIn, DN_T_ILLUMINATION);
PT_BUFFER(DenoiseFrame, gFrame, DN_T_FRAME);
PT_TEXTURE(gHistoryAlbedo, DN_T_HISTORY_ALBEDO);
PT_TEXTURE(gHistoryEmission, DN_T_HISTORY_EMISSION);
PT_RW_TEXTURE(gIlluminationOut, DN_U_ILLUMINATION);
PT_RW_TEXTURE(gMoments, DN_U_MOMENTS);
PT_RW_TEXTURE(gHistoryIlluminationOut, DN_U_HISTORY_ILLUMINATION);
PT_RW_TEXTURE(gHistoryNormalDepthOut, DN_U_HISTORY_NORMAL_DEPTH);
PT_RW_TEXTURE(gOutput, DN_U_OUTPUT);
PT_RW_TEXTURE(gMotion, DN_U_MOTION);
PT_RW_TEXTURE(gIntegratedAlbedo, DN_U_ALBEDO);
PT_RW_TEXTURE(gIntegratedEmission, DN_U_EMISSION);

DenoiseFrame loadFrame() { return gFrame[0]; }
float4 loadBeauty(int2 p) { return PT_LOAD_TEXTURE(gBeauty, p); }
float4 loadAlbedo(int2 p) { return PT_LOAD_TEXTURE(gAlbedo, p); }
float4 loadNormalDepth(int2 p) { return PT_LOAD_TEXTURE(gNormalDepth, p); }
float4 loadEmission(int2 p) { return PT_LOAD_TEXTURE(gEmission, p); }
float4 loadSampleMoments(int2 p) { return PT_LOAD_TEXTURE(gSampleMoments, p); }
float4 loadHistoryIllumination(int2 p) { return PT_LOAD_TEXTURE(gHistoryIllumination, p); }
float4 loadHistoryMoments(int2 p) { return PT_LOAD_TEXTURE(gHistoryMoments, p); }
float4 loadHistoryNormalDepth(int2 p) { return PT_LOAD_TEXTURE(gHistoryNormalDepth, p); }
float4 loadIllumination(int2 p) { return PT_LOAD_TEXTURE(gIlluminationIn, p); }
float4 loadHistoryAlbedo(int2 p) { return PT_LOAD_TEXTURE(gHistoryAlbedo, p); }
float4 loadHistoryEmission(int2 p) { return PT_LOAD_TEXTURE(gHistoryEmission, p); }
float4 loadMoments(int2 p) { return PT_LOAD_RW_TEXTURE(gMoments, p); }
float4 loadIntegratedAlbedo(int2 p) { return PT_LOAD_RW_TEXTURE(gIntegratedAlbedo, p); }
float4 loadIntegratedEmission(int2 p) { return PT_LOAD_RW_TEXTURE(gIntegratedEmission, p); }
void storeIllumination(int2 p, float4 v) { PT_STORE_RW_TEXTURE(gIlluminationOut, p, v); }
void storeMoments(int2 p, float4 v) { PT_STORE_RW_TEXTURE(gMoments, p, v); }
void storeHistoryIllumination(int2 p, float4 v) { PT_STORE_RW_TEXTURE(gHistoryIlluminationOut, p, v); }
void storeHistoryNormalDepth(int2 p, float4 v) { PT_STORE_RW_TEXTURE(gHistoryNormalDepthOut, p, v); }
void storeOutput(int2 p, float4 v) { PT_STORE_RW_TEXTURE(gOutput, p, v); }
void storeMotion(int2 p, float4 v) { PT_STORE_RW_TEXTURE(gMotion, p, v); }
void storeIntegratedAlbedo(int2 p, float4 v) { PT_STORE_RW_TEXTURE(gIntegratedAlbedo, p, v); }
void storeIntegratedEmission(int2 p, float4 v) { PT_STORE_RW_TEXTURE(gIntegratedEmission, p, v); }
#include "denoiser.hlsli"

PT_COMPUTE(main, 8, 8) { denoisePass(int2(PT_DISPATCH_THREAD_ID.xy), denoisePush()); }
