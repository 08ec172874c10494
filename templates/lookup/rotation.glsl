// rotation.glsl — per-position rotation of Poisson taps (pcss-blog): rotating the disk
// turns the banding of a fixed tap set into noise; deriving the angle from the quantized
// world position (not from the pixel or a frame counter) keeps it stable under camera motion
// and from frame to frame. The blog precomputes a 32^3 texture of angles; a hash of the cell
// gives the same stability without an extra resource.
#ifndef SHADOWC_ROTATION_GLSL
#define SHADOWC_ROTATION_GLSL

// 3D integer hash (pcg3d, Jarzynski & Olano 2020), well mixed in all bits.
uvec3 shadowc_pcg3d(uvec3 v) {
  v = v * 1664525u + 1013904223u;
  v.x += v.y * v.z;
  v.y += v.z * v.x;
  v.z += v.x * v.y;
  v ^= v >> 16u;
  v.x += v.y * v.z;
  v.y += v.z * v.x;
  v.z += v.x * v.y;
  return v;
}

// (cos a, sin a) of the rotation for this receiver.
vec2 shadowc_rotation(vec3 worldPos) {
#if SHADOWC_ROTATION_STABLE
  // Clamped before the int conversion: out-of-range float -> int is undefined.
  vec3 cell = clamp(floor(worldPos * SHADOWC_ROTATION_CELLS), vec3(-2.0e9), vec3(2.0e9));
  uint h = shadowc_pcg3d(uvec3(ivec3(cell))).x;
  float a = float(h >> 8u) * (6.28318530718 / 16777216.0);
  return vec2(cos(a), sin(a));
#else
  return vec2(1.0, 0.0);
#endif
}

vec2 shadowc_rotate(vec2 tap, vec2 rot) { return vec2(rot.x * tap.x - rot.y * tap.y, rot.y * tap.x + rot.x * tap.y); }

#endif
