#version 450
// The engine's G-buffer pass: world position and normal per pixel.
layout(push_constant) uniform Push {
  mat4 viewProj;  // world -> Vulkan clip of the camera
  vec4 zRow;
  vec4 depthRange;
} push;
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 0) out vec3 worldPosition;
layout(location = 1) out vec3 worldNormal;

void main() {
  worldPosition = position;
  worldNormal = normal;
  gl_Position = push.viewProj * vec4(position, 1.0);
}
