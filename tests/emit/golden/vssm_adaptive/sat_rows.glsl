#version 460
#extension GL_GOOGLE_include_directive : require
#line 1 "passes/sat_common.glsl"
#line 25
uvec4 shadowc_satEncode(vec4 v){ return uvec4(roundEven(clamp(v, 0.0, 1.0)* 65536.0));}
#line 15 "templates/passes/sat_rows.comp"

layout(local_size_x = 64, local_size_y = 1, local_size_z = 1)in;
layout(set = 0, binding = 0, rg32f)readonly uniform image2DArray momentsIn;
layout(set = 0, binding = 1, rg32ui)writeonly uniform uimage2DArray satOut;

void main(){
  const ivec2 size = imageSize(momentsIn). xy;
  const int y = int(gl_GlobalInvocationID . x);
  if(y >= size . y)return;
  for(int layer = 0;layer < 1;++ layer){
                    uvec4 sum = uvec4(0);
    for(int x = 0;x < size . x;++ x){
      sum += shadowc_satEncode(imageLoad(momentsIn, ivec3(x, y, layer)));
      imageStore(satOut, ivec3(x, y, layer), sum);
    }
  }
}
