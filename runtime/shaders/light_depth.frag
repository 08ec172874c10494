// Normalized linear depth d = (z - near) / (far - near) (templates/frame.glsl). The hardware
// depth buffer only decides visibility; the stored value is computed here in fp32.
#version 460
#extension GL_GOOGLE_include_directive : require
#include "raster_push.glsl"

layout(location = 0) in float viewZ;
layout(location = 0) out float depth;

void main() { depth = (viewZ - raster.depthRange.x) / (raster.depthRange.y - raster.depthRange.x); }
