#version 460
#extension GL_GOOGLE_include_directive : require
#include "rhi_test_common.glsl"

// A second miss shader with different code: marks its tag with bit 16.
layout(location = 0) rayPayloadInEXT ProbePayload gPayload;
layout(shaderRecordEXT, std430) buffer Record { uint gTag; };

void main() {
  gPayload.tag = gTag | 0x10000u;
  gPayload.hitT = -1.0;
}
