#version 460
#extension GL_GOOGLE_include_directive : require
#line 15
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1)in;
layout(set = 0, binding = 0)uniform sampler2D shadowDepth;
layout(set = 0, binding = 1, rgba32f)writeonly uniform image2DArray momentsOut;
#line 1 "passes/layer_moments.glsl"
#line 1 "passes/moments_warp.glsl"
#line 29
vec4 shadowc_warpMoments(float d){
#line 44
  return vec4(d, d, d, 0.0);

}
#line 49
float shadowc_layerRemap(float d, float p, float q){ return clamp((d - p)/ max(q - p, 1e-6), 0.0, 1.0);}
#line 24 "passes/layer_moments.glsl"

vec4 shadowc_layerMoments(float d, int layer){

  return shadowc_warpMoments(d);
#line 38
}
#line 22 "templates/passes/moments.comp"

void main(){
  const ivec2 size = textureSize(shadowDepth, 0);
  const ivec2 p = ivec2(gl_GlobalInvocationID . xy);
  if(any(greaterThanEqual(p, size)))return;
  const float d = texelFetch(shadowDepth, p, 0). r;
  for(int i = 0;i < 1;++ i)imageStore(momentsOut, ivec3(p, i), shadowc_layerMoments(d, i));
}
