#version 460
#extension GL_GOOGLE_include_directive : require
#line 12
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1)in;
#line 16
layout(set = 0, binding = 0, rg32f)readonly uniform image2D src;

layout(set = 0, binding = 1, rg32f)writeonly uniform image2D dst;

void main(){
  const ivec2 dstSize = imageSize(dst);
  const ivec2 p = ivec2(gl_GlobalInvocationID . xy);
  if(any(greaterThanEqual(p, dstSize)))return;
#line 28
  const ivec2 srcSize = imageSize(src);
  const ivec2 first = 2 * p;
  const ivec2 last = min(2 * p + 1 + ivec2(equal(p, dstSize - 1))*(srcSize & 1), srcSize - 1);
  vec2 mm = vec2(1e30, - 1e30);
  for(int y = first . y;y <= last . y;++ y)
    for(int x = first . x;x <= last . x;++ x){
      const vec2 v = imageLoad(src, ivec2(x, y)). rg;
      mm = vec2(min(mm . x, v . x), max(mm . y, v . y));
    }
  imageStore(dst, p, vec4(mm, 0.0, 0.0));

}
