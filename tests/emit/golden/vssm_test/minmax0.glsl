#version 460
#extension GL_GOOGLE_include_directive : require
#line 12
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1)in;

layout(set = 0, binding = 0)uniform sampler2D shadowDepth;
#line 18
layout(set = 0, binding = 1, rg32f)writeonly uniform image2D dst;

void main(){
  const ivec2 dstSize = imageSize(dst);
  const ivec2 p = ivec2(gl_GlobalInvocationID . xy);
  if(any(greaterThanEqual(p, dstSize)))return;

  const float d = texelFetch(shadowDepth, p, 0). r;
  imageStore(dst, p, vec4(d, d, 0.0, 0.0));
#line 39
}
