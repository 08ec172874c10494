// Light depth pass: coverage from the light's perspective projection (FrameSetup, which follows
// frame.glsl's uv mapping); the light-view z travels to the fragment shader, where the stored
// value is computed.
#version 460
#extension GL_GOOGLE_include_directive : require
#include "raster_push.glsl"

layout(location = 0) in vec3 position;
layout(location = 0) out float viewZ;

void main() {
  // View z is affine in the triangle, so perspective-correct interpolation reproduces it exactly.
  viewZ = dot(raster.lightZRow, vec4(position, 1.0));
  gl_Position = raster.viewProj * vec4(position, 1.0);
}
