#version 460
#extension GL_GOOGLE_include_directive : require
#line 22
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1)in;
#line 27
layout(set = 0, binding = 0, rg32f)readonly uniform image2D src;

layout(set = 0, binding = 1, rg32f)writeonly uniform image2D dst;

layout(set = 0, binding = 3, rg32f)writeonly uniform image2D mid;
#line 34
ivec2 shadowc_sourceSize(){
#line 38
  return imageSize(src);

}
#line 43
ivec2 shadowc_footprintLast(ivec2 p, ivec2 size, ivec2 below){
  return min(2 * p + 1 + ivec2(equal(p, size - 1))*(below & 1), below - 1);
}
#line 48
vec2 shadowc_reduceSource(ivec2 p, ivec2 size, ivec2 srcSize){
  const ivec2 last = shadowc_footprintLast(p, size, srcSize);
  vec2 mm = vec2(1e30, - 1e30);
  for(int y = 2 * p . y;y <= last . y;++ y)
    for(int x = 2 * p . x;x <= last . x;++ x){
#line 58
      const vec2 v = imageLoad(src, ivec2(x, y)). rg;

      mm = vec2(min(mm . x, v . x), max(mm . y, v . y));
    }
  return mm;
}

void main(){
  const ivec2 dstSize = imageSize(dst);
  const ivec2 p = ivec2(gl_GlobalInvocationID . xy);
  if(any(greaterThanEqual(p, dstSize)))return;
  const ivec2 srcSize = shadowc_sourceSize();

  const ivec2 midSize = imageSize(mid);
  const ivec2 last = shadowc_footprintLast(p, dstSize, midSize);
  vec2 mm = vec2(1e30, - 1e30);
  for(int y = 2 * p . y;y <= last . y;++ y)
    for(int x = 2 * p . x;x <= last . x;++ x){
      const vec2 v = shadowc_reduceSource(ivec2(x, y), midSize, srcSize);
      imageStore(mid, ivec2(x, y), vec4(v, 0.0, 0.0));
      mm = vec2(min(mm . x, v . x), max(mm . y, v . y));
    }
#line 83
  imageStore(dst, p, vec4(mm, 0.0, 0.0));
}
