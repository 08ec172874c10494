#version 460
#extension GL_GOOGLE_include_directive : require
#line 1 "passes/sat_common.glsl"
#line 27
uvec4 shadowc_satEncode(vec4 v){ return uvec4(roundEven(clamp(v, 0.0, 1.0)* 65536.0));}
#line 77
void shadowc_satCarry(int chunk, uvec4 total, inout uvec4 tileCarry,
                      inout uvec4 groupCarry, inout uvec4 chunkCarry){
  precise uvec4 c = chunkCarry + total;
  chunkCarry = c;
  if((chunk + 1)% 16 != 0)return;
  precise uvec4 g = groupCarry + chunkCarry;
  groupCarry = g;
  chunkCarry = uvec4(0);
  if((chunk + 1)% 256 != 0)return;
  precise uvec4 t = tileCarry + groupCarry;
  tileCarry = t;
  groupCarry = uvec4(0);
}
#line 28 "templates/passes/sat_rows.comp"

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
#line 36 "templates/passes/sat_rows.comp"
#line 39
layout(set = 0, binding = 1, rg32ui)writeonly uniform uimage2DArray satOut;

void main(){

  const ivec2 size = textureSize(shadowDepth, 0);
#line 47
  const int y = int(gl_GlobalInvocationID . x);
  if(y >= size . y)return;
#line 52
                  uvec4 tileCarry[1], groupCarry[1], chunkCarry[1];
  for(int layer = 0;layer < 1;++ layer)
    tileCarry[layer]= groupCarry[layer]= chunkCarry[layer]= uvec4(0);
  int x = 0, chunk = 0;
  for(;x + 8 <= size . x;x += 8, ++ chunk){
    float d[8];
    for(int i = 0;i < 8;++ i)d[i]= texelFetch(shadowDepth, ivec2(x + i, y), 0). r;
                    uvec4 base[1], local[1];
    for(int layer = 0;layer < 1;++ layer){
      precise uvec4 b =(tileCarry[layer]+ groupCarry[layer])+ chunkCarry[layer];
      base[layer]= b;
      local[layer]= uvec4(0);
    }
    for(int i = 0;i < 8;++ i)
      for(int layer = 0;layer < 1;++ layer){
        precise uvec4 l = local[layer]+ shadowc_satEncode(shadowc_layerMoments(d[i], layer));
        local[layer]= l;
        precise uvec4 s = base[layer]+ l;
        imageStore(satOut, ivec3(x + i, y, layer), s);
      }
    for(int layer = 0;layer < 1;++ layer)
      shadowc_satCarry(chunk, local[layer], tileCarry[layer], groupCarry[layer], chunkCarry[layer]);
  }

                  uvec4 base[1], local[1];
  for(int layer = 0;layer < 1;++ layer){
    precise uvec4 b =(tileCarry[layer]+ groupCarry[layer])+ chunkCarry[layer];
    base[layer]= b;
    local[layer]= uvec4(0);
  }
  for(;x < size . x;++ x){
    const float d = texelFetch(shadowDepth, ivec2(x, y), 0). r;
    for(int layer = 0;layer < 1;++ layer){
      precise uvec4 l = local[layer]+ shadowc_satEncode(shadowc_layerMoments(d, layer));
      local[layer]= l;
      precise uvec4 s = base[layer]+ l;
      imageStore(satOut, ivec3(x, y, layer), s);
    }
  }
#line 117
}
