#version 450
// The engine's light-depth pass: clip position from the view's matrix; the light-view z goes to
// the fragment shader, which stores normalized linear depth (templates/frame.glsl convention).
layout(push_constant) uniform Push {
  mat4 viewProj;   // world -> Vulkan clip of this light view
  vec4 zRow;       // light-view z = dot(zRow, vec4(p, 1))
  vec4 depthRange; // x near, y far
} push;
layout(location = 0) in vec3 position;
layout(location = 0) out float viewZ;

void main() {
  viewZ = dot(push.zRow, vec4(position, 1.0));  // affine in the triangle: interpolated exactly
  gl_Position = push.viewProj * vec4(position, 1.0);
}
