// Camera G-buffer: world position and normal per pixel.
#version 460
#extension GL_GOOGLE_include_directive : require
#include "raster_push.glsl"

layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 0) out vec3 worldPosition;
layout(location = 1) out vec3 worldNormal;

void main() {
  worldPosition = position;
  worldNormal = normal;
  gl_Position = raster.viewProj * vec4(position, 1.0);
}
