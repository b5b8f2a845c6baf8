#version 460
// The raster tests' pixel shader: the interpolated vertex colour.
layout(location = 0) in vec4 color;
layout(location = 0) out vec4 target;
void main() {
  target = color;
}
