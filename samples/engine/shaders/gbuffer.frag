#version 450
// xyz world position / unit normal, w = 1 on geometry (the clear leaves 0 elsewhere).
layout(location = 0) in vec3 worldPosition;
layout(location = 1) in vec3 worldNormal;
layout(location = 0) out vec4 position;
layout(location = 1) out vec4 normal;

void main() {
  position = vec4(worldPosition, 1.0);
  normal = vec4(normalize(worldNormal), 1.0);
}
