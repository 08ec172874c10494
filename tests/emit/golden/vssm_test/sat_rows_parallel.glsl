#version 460
#extension GL_GOOGLE_include_directive : require
#line 1 "passes/sat_tiles.glsl"
#line 1 "passes/sat_common.glsl"
#line 27
uvec4 shadowc_satEncode(vec4 v){ return uvec4(roundEven(clamp(v, 0.0, 1.0)* 65536.0));}
#line 14 "passes/sat_tiles.glsl"

shared uvec4 shadowc_satChunks[256];
shared uvec4 shadowc_satGroups[16];
shared uvec4 shadowc_satTileTotal;
#line 22
                uvec4 shadowc_satTileCarry(uint i, uvec4 total, inout uvec4 tileCarry){
  shadowc_satChunks[i]= total;
  barrier();
  if(i < 16){
    precise uvec4 c = uvec4(0);
    for(uint k = 0;k < 16;++ k){
      const uint at = i * 16 + k;
      const uvec4 t = shadowc_satChunks[at];
      shadowc_satChunks[at]= c;
      c = c + t;
    }
    shadowc_satGroups[i]= c;
  }
  barrier();
  if(i == 0){
    precise uvec4 g = uvec4(0);
    for(uint k = 0;k < 16;++ k){
      const uvec4 t = shadowc_satGroups[k];
      shadowc_satGroups[k]= g;
      g = g + t;
    }
    shadowc_satTileTotal = g;
  }
  barrier();
  precise uvec4 carry =(tileCarry + shadowc_satGroups[i / 16])+ shadowc_satChunks[i];
  precise uvec4 next = tileCarry + shadowc_satTileTotal;
  tileCarry = next;
  barrier();
  return carry;
}
#line 23 "templates/passes/sat_rows_parallel.comp"

layout(local_size_x = 256, local_size_y = 1, local_size_z = 1)in;

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
#line 31 "templates/passes/sat_rows_parallel.comp"
#line 34
layout(set = 0, binding = 1, rg32ui)writeonly uniform uimage2DArray satOut;

                uvec4 encodedTexel(int x, int y, int layer){

  return shadowc_satEncode(shadowc_layerMoments(texelFetch(shadowDepth, ivec2(x, y), 0). r, layer));
#line 42
}

void main(){

  const ivec2 size = textureSize(shadowDepth, 0);
#line 50
  const int y = int(gl_WorkGroupID . x);
  if(y >= size . y)return;
  const uint i = gl_LocalInvocationID . x;
  for(int layer = 0;layer < 1;++ layer){
                    uvec4 tileCarry = uvec4(0);
    for(int tile = 0;tile < size . x;tile += 256 * 8){
      const int x = tile + int(i)* 8;
      const int n = clamp(size . x - x, 0, 8);
                      uvec4 local[8];
      precise uvec4 run = uvec4(0);
      for(int k = 0;k < 8;++ k){
        if(k < n)run += encodedTexel(x + k, y, layer);
        local[k]= run;
      }
      const uvec4 carry = shadowc_satTileCarry(i, run, tileCarry);
      for(int k = 0;k < n;++ k){
        precise uvec4 s = carry + local[k];
        imageStore(satOut, ivec3(x + k, y, layer), s);
      }
    }
  }
}
