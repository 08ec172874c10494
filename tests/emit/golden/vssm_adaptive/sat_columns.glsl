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
#line 12 "templates/passes/sat_columns.comp"

layout(local_size_x = 64, local_size_y = 1, local_size_z = 1)in;
layout(set = 0, binding = 0, rg32ui)uniform uimage2DArray sat;

void main(){
  const ivec2 size = imageSize(sat). xy;
  const int x = int(gl_GlobalInvocationID . x);
  if(x >= size . x)return;

  for(int layer = 0;layer < 1;++ layer){
                    uvec4 tileCarry = uvec4(0), groupCarry = tileCarry, chunkCarry = tileCarry;
    int y = 0, chunk = 0;
    for(;y + 8 <= size . y;y += 8, ++ chunk){
                      uvec4 v[8];
      for(int i = 0;i < 8;++ i)v[i]= imageLoad(sat, ivec3(x, y + i, layer));
      precise uvec4 base =(tileCarry + groupCarry)+ chunkCarry;
      precise uvec4 local = uvec4(0);
      for(int i = 0;i < 8;++ i){
        local += v[i];
        precise uvec4 s = base + local;
        imageStore(sat, ivec3(x, y + i, layer), s);
      }
      shadowc_satCarry(chunk, local, tileCarry, groupCarry, chunkCarry);
    }

    precise uvec4 base =(tileCarry + groupCarry)+ chunkCarry;
    precise uvec4 local = uvec4(0);
    for(;y < size . y;++ y){
      local += imageLoad(sat, ivec3(x, y, layer));
      precise uvec4 s = base + local;
      imageStore(sat, ivec3(x, y, layer), s);
    }
  }
}
