#version 460
#extension GL_GOOGLE_include_directive : require
#include "rhi_test_common.glsl"

layout(location = 0) rayPayloadInEXT ProbePayload gPayload;
layout(shaderRecordEXT, std430) buffer Record { uint gTag; };

void main() {
  gPayload.tag = gTag;
  gPayload.instanceId = uint(gl_InstanceCustomIndexEXT);
  gPayload.primitiveId = uint(gl_PrimitiveID);
  gPayload.hitKind = gl_HitKindEXT;
  gPayload.hitT = gl_HitTEXT;
  gPayload.objectPosition = gl_ObjectRayOriginEXT + gl_HitTEXT * gl_ObjectRayDirectionEXT;
}
