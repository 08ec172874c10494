#version 460
#extension GL_GOOGLE_include_directive : require
#line 1 "passes/sat_common.glsl"
#line 27
uvec4 shadowc_satEncode(vec4 v){ return uvec4(roundEven(clamp(v, 0.0, 1.0)* 65536.0));}
#line 12 "templates/passes/sat_columns.comp"

layout(local_size_x = 64, local_size_y = 1, local_size_z = 1)in;
layout(set = 0, binding = 0, rg32ui)uniform uimage2DArray sat;

void main(){
  const ivec2 size = imageSize(sat). xy;
  const int x = int(gl_GlobalInvocationID . x);
  if(x >= size . x)return;
  for(int layer = 0;layer < 1;++ layer){
                    uvec4 sum = uvec4(0);
    int y = 0;
    for(;y + 8 <= size . y;y += 8){
                      uvec4 v[8];
      for(int i = 0;i < 8;++ i)v[i]= imageLoad(sat, ivec3(x, y + i, layer));
      for(int i = 0;i < 8;++ i){
        sum += v[i];
        imageStore(sat, ivec3(x, y + i, layer), sum);
      }
    }
    for(;y < size . y;++ y){
      sum += imageLoad(sat, ivec3(x, y, layer));
      imageStore(sat, ivec3(x, y, layer), sum);
    }
  }
}
