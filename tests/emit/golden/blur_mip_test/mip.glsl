#version 460
#extension GL_GOOGLE_include_directive : require
#line 18
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1)in;
layout(set = 0, binding = 0, rgba32f)readonly uniform image2DArray src;
layout(set = 0, binding = 1, rgba32f)writeonly uniform image2DArray dst;

void main(){
  const ivec2 srcSize = imageSize(src). xy;
  const ivec2 dstSize = imageSize(dst). xy;
  const ivec2 p = ivec2(gl_GlobalInvocationID . xy);
  if(any(greaterThanEqual(p, dstSize)))return;

  const ivec2 first = 2 * p;
  const ivec2 last = min(2 * p + 1 + ivec2(equal(p, dstSize - 1))*(srcSize & 1), srcSize - 1);
  for(int layer = 0;layer < 1;++ layer){
    vec4 sum = vec4(0.0);
    float lo = 1e30, hi = - 1e30;
    for(int y = first . y;y <= last . y;++ y)
      for(int x = first . x;x <= last . x;++ x){
        vec4 v = imageLoad(src, ivec3(x, y, layer));
        sum += v;
        lo = min(lo, v . r);
        hi = max(hi, v . g);
      }
    const ivec2 n = last - first + 1;
    vec4 mean = sum / float(n . x * n . y);

    mean . r = lo;
    mean . g = hi;

    imageStore(dst, ivec3(p, layer), mean);
  }
}
