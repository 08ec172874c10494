#version 460
#extension GL_GOOGLE_include_directive : require
#line 29
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1)in;
layout(set = 0, binding = 0, rgba16)readonly uniform image2DArray src;
layout(set = 0, binding = 1, rgba16)writeonly uniform image2DArray dst;

void main(){
  const ivec2 size = imageSize(src). xy;
  const ivec2 p = ivec2(gl_GlobalInvocationID . xy);
  if(any(greaterThanEqual(p, size)))return;
  const float w[2 + 1]= float[](0.402619958, 0.244201347, 0.054488685);
  const ivec2 axis = 0 == 0 ? ivec2(1, 0): ivec2(0, 1);
  for(int layer = 0;layer < 1;++ layer){
    vec4 centre = imageLoad(src, ivec3(p, layer));
    vec4 sum = w[0]* centre;
#line 45
    for(int k = 1;k <= 2;++ k){
      vec4 a = imageLoad(src, ivec3(clamp(p - k * axis, ivec2(0), size - 1), layer));
      vec4 b = imageLoad(src, ivec3(clamp(p + k * axis, ivec2(0), size - 1), layer));
      sum += w[k]*(a + b);
#line 53
    }
#line 58
    imageStore(dst, ivec3(p, layer), sum);
  }
}
