#version 460
#extension GL_GOOGLE_include_directive : require
#line 1 "passes/sat_common.glsl"
#line 27
uvec4 shadowc_satEncode(vec4 v){ return uvec4(roundEven(clamp(v, 0.0, 1.0)* 65536.0));}
#line 29 "templates/passes/sat_rows.comp"

layout(local_size_x = 64, local_size_y = 1, local_size_z = 1)in;

layout(set = 0, binding = 0)uniform sampler2D shadowDepth;
#line 1 "passes/layer_moments.glsl"
#line 1 "passes/moments_warp.glsl"
#line 29
vec4 shadowc_warpMoments(float d){

  return vec4(d, d * d, 0.0, 0.0);
#line 46
}
#line 49
float shadowc_layerRemap(float d, float p, float q){ return clamp((d - p)/ max(q - p, 1e-6), 0.0, 1.0);}
#line 24 "passes/layer_moments.glsl"

vec4 shadowc_layerMoments(float d, int layer){

  return shadowc_warpMoments(d);
#line 38
}
#line 37 "templates/passes/sat_rows.comp"
#line 40
layout(set = 0, binding = 1, rg32ui)writeonly uniform uimage2DArray satOut;

void main(){

  const ivec2 size = textureSize(shadowDepth, 0);
#line 48
  const int y = int(gl_GlobalInvocationID . x);
  if(y >= size . y)return;
#line 52
                  uvec4 sum[1];
  for(int layer = 0;layer < 1;++ layer)sum[layer]= uvec4(0);
  int x = 0;
  for(;x + 8 <= size . x;x += 8){
    float d[8];
    for(int i = 0;i < 8;++ i)d[i]= texelFetch(shadowDepth, ivec2(x + i, y), 0). r;
    for(int i = 0;i < 8;++ i)
      for(int layer = 0;layer < 1;++ layer){
        sum[layer]+= shadowc_satEncode(shadowc_layerMoments(d[i], layer));
        imageStore(satOut, ivec3(x + i, y, layer), sum[layer]);
      }
  }
  for(;x < size . x;++ x){
    const float d = texelFetch(shadowDepth, ivec2(x, y), 0). r;
    for(int layer = 0;layer < 1;++ layer){
      sum[layer]+= shadowc_satEncode(shadowc_layerMoments(d, layer));
      imageStore(satOut, ivec3(x, y, layer), sum[layer]);
    }
  }
#line 89
}
