#version 460
#extension GL_GOOGLE_include_directive : require
#include "rhi_test_common.glsl"

layout(location = 0) rayPayloadInEXT ProbePayload gPayload;
layout(shaderRecordEXT, std430) buffer Record { uint gTag; };

void main() {
  gPayload.tag = gTag;
  gPayload.hitT = -1.0;
}
