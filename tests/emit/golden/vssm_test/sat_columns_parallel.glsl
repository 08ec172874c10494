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
#line 13 "templates/passes/sat_columns_parallel.comp"

layout(local_size_x = 256, local_size_y = 1, local_size_z = 1)in;
layout(set = 0, binding = 0, rg32ui)uniform uimage2DArray sat;

void main(){
  const ivec2 size = imageSize(sat). xy;
  const int x = int(gl_WorkGroupID . x);
  if(x >= size . x)return;
  const uint i = gl_LocalInvocationID . x;
  for(int layer = 0;layer < 1;++ layer){
                    uvec4 tileCarry = uvec4(0);
    for(int tile = 0;tile < size . y;tile += 256 * 8){
      const int y = tile + int(i)* 8;
      const int n = clamp(size . y - y, 0, 8);
                      uvec4 local[8];
      precise uvec4 run = uvec4(0);
      for(int k = 0;k < 8;++ k){
        if(k < n)run += imageLoad(sat, ivec3(x, y + k, layer));
        local[k]= run;
      }
      const uvec4 carry = shadowc_satTileCarry(i, run, tileCarry);
      for(int k = 0;k < n;++ k){
        precise uvec4 s = carry + local[k];
        imageStore(sat, ivec3(x, y + k, layer), s);
      }
    }
  }
}
