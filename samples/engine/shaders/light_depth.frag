#version 450
// d = (z - near) / (far - near): what a filter reading linear depth samples. A depth_input
// filter reads the depth attachment of the same draw instead.
layout(push_constant) uniform Push {
  mat4 viewProj;
  vec4 zRow;
  vec4 depthRange;
} push;
layout(location = 0) in float viewZ;
layout(location = 0) out float depth;

void main() { depth = (viewZ - push.depthRange.x) / (push.depthRange.y - push.depthRange.x); }
