#version 460
#extension GL_GOOGLE_include_directive : require
#include "hlsl_prelude.glsl"
#include "denoiser_shared.h"

// Every pass of the denoiser (engine/render/denoiser.h); the push constant
// picks one. The kernels are in shaders/shared/denoiser.hlsli.
layout(local_size_x = 8, local_size_y = 8) in;
layout(push_constant, std430) uniform Push { DenoisePush gPush; };
layout(set = 0, binding = PENUMBRA_T(DN_T_BEAUTY), rgba32f) readonly uniform image2D gBeauty;
layout(set = 0, binding = PENUMBRA_T(DN_T_ALBEDO), rgba32f) readonly uniform image2D gAlbedo;
layout(set = 0, binding = PENUMBRA_T(DN_T_NORMAL_DEPTH), rgba32f) readonly uniform image2D gNormalDepth;
layout(set = 0, binding = PENUMBRA_T(DN_T_EMISSION), rgba32f) readonly uniform image2D gEmission;
layout(set = 0, binding = PENUMBRA_T(DN_T_SAMPLE_MOMENTS), rgba32f) readonly uniform image2D gSampleMoments;
layout(set = 0, binding = PENUMBRA_T(DN_T_HISTORY_ILLUMINATION), rgba32f) readonly uniform image2D gHistoryIllumination;
layout(set = 0, binding = PENUMBRA_T(DN_T_HISTORY_MOMENTS), rgba32f) readonly uniform image2D gHistoryMoments;
layout(set = 0, binding = PENUMBRA_T(DN_T_HISTORY_NORMAL_DEPTH), rgba32f) readonly uniform image2D gHistoryNormalDepth;
layout(set = 0, binding = PENUMBRA_T(DN_T_ILLUMINATION), rgba32f) readonly uniform image2D gIlluminationIn;
layout(set = 0, binding = PENUMBRA_T(DN_T_FRAME), std430) readonly buffer DenoiseFrameBlock { DenoiseFrame gFrame[]; };
layout(set = 0, binding = PENUMBRA_U(DN_U_ILLUMINATION), rgba32f) writeonly uniform image2D gIlluminationOut;
layout(set = 0, binding = PENUMBRA_U(DN_U_MOMENTS), rgba32f) uniform image2D gMoments;
layout(set = 0, binding = PENUMBRA_U(DN_U_HISTORY_ILLUMINATION), rgba32f) writeonly uniform image2D gHistoryIlluminationOut;
layout(set = 0, binding = PENUMBRA_U(DN_U_HISTORY_NORMAL_DEPTH), rgba32f) writeonly uniform image2D gHistoryNormalDepthOut;
layout(set = 0, binding = PENUMBRA_U(DN_U_OUTPUT), rgba32f) writeonly uniform image2D gOutput;
layout(set = 0, binding = PENUMBRA_U(DN_U_MOTION), rgba32f) writeonly uniform image2D gMotion;
layout(set = 0, binding = PENUMBRA_T(DN_T_HISTORY_ALBEDO), rgba32f) readonly uniform image2D gHistoryAlbedo;
layout(set = 0, binding = PENUMBRA_T(DN_T_HISTORY_EMISSION), rgba32f) readonly uniform image2D gHistoryEmission;
layout(set = 0, binding = PENUMBRA_U(DN_U_ALBEDO), rgba32f) uniform image2D gIntegratedAlbedo;
layout(set = 0, binding = PENUMBRA_U(DN_U_EMISSION), rgba32f) uniform image2D gIntegratedEmission;

DenoiseFrame loadFrame() { return gFrame[0]; }
float4 loadBeauty(int2 p) { return imageLoad(gBeauty, p); }
float4 loadAlbedo(int2 p) { return imageLoad(gAlbedo, p); }
float4 loadNormalDepth(int2 p) { return imageLoad(gNormalDepth, p); }
float4 loadEmission(int2 p) { return imageLoad(gEmission, p); }
float4 loadSampleMoments(int2 p) { return imageLoad(gSampleMoments, p); }
float4 loadHistoryIllumination(int2 p) { return imageLoad(gHistoryIllumination, p); }
float4 loadHistoryMoments(int2 p) { return imageLoad(gHistoryMoments, p); }
float4 loadHistoryNormalDepth(int2 p) { return imageLoad(gHistoryNormalDepth, p); }
float4 loadIllumination(int2 p) { return imageLoad(gIlluminationIn, p); }
float4 loadMoments(int2 p) { return imageLoad(gMoments, p); }
void storeIllumination(int2 p, float4 v) { imageStore(gIlluminationOut, p, v); }
void storeMoments(int2 p, float4 v) { imageStore(gMoments, p, v); }
void storeHistoryIllumination(int2 p, float4 v) { imageStore(gHistoryIlluminationOut, p, v); }
void storeHistoryNormalDepth(int2 p, float4 v) { imageStore(gHistoryNormalDepthOut, p, v); }
void storeOutput(int2 p, float4 v) { imageStore(gOutput, p, v); }
void storeMotion(int2 p, float4 v) { imageStore(gMotion, p, v); }
float4 loadHistoryAlbedo(int2 p) { return imageLoad(gHistoryAlbedo, p); }
float4 loadHistoryEmission(int2 p) { return imageLoad(gHistoryEmission, p); }
float4 loadIntegratedAlbedo(int2 p) { return imageLoad(gIntegratedAlbedo, p); }
float4 loadIntegratedEmission(int2 p) { return imageLoad(gIntegratedEmission, p); }
void storeIntegratedAlbedo(int2 p, float4 v) { imageStore(gIntegratedAlbedo, p, v); }
void storeIntegratedEmission(int2 p, float4 v) { imageStore(gIntegratedEmission, p, v); }
#include "denoiser.hlsli"

void main() { denoisePass(int2(gl_GlobalInvocationID.xy), gPush); }
