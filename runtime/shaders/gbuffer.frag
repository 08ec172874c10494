// gbuffer_position: xyz world, w = 1 where there is geometry (cleared to 0 elsewhere).
// gbuffer_normal: xyz unit world normal (the mesh's own orientation, not flipped to the camera),
// w = 1 on geometry like gbuffer_position (and runtime/reference/cpu_gbuffer.h); 0 background.
#version 460

layout(location = 0) in vec3 worldPosition;
layout(location = 1) in vec3 worldNormal;
layout(location = 0) out vec4 position;
layout(location = 1) out vec4 normal;

void main() {
  position = vec4(worldPosition, 1.0);
  normal = vec4(normalize(worldNormal), 1.0);
}
