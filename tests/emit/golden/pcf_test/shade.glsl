#version 460
#extension GL_GOOGLE_include_directive : require
#line 1 "frame.glsl"
#line 20
struct shadowc_Frame {
  mat4 lightView;
  vec4 lightParams;
};
shadowc_Frame shadowc_frame();

#line 1 "frame_block.glsl"
#line 16
layout(set = 0, binding = 0, std140)uniform shadowc_FrameBlock {
  mat4 lightView;
  vec4 lightParams;
  vec4 lightShape;
  vec4 mapInfo;
  vec4 screenInfo;
#line 27
} shadowc_frameBlock;

shadowc_Frame shadowc_frame(){ return shadowc_Frame(shadowc_frameBlock . lightView, shadowc_frameBlock . lightParams);}
#line 27 "frame.glsl"
#line 33
vec4 shadowc_lightSpace(vec3 worldPos){
  vec3 p =(shadowc_frame(). lightView * vec4(worldPos, 1.0)). xyz;
  vec2 uv = 0.5 + 0.5 * p . xy /(p . z * shadowc_frame(). lightParams . x);
  float d =(p . z - shadowc_frame(). lightParams . y)/(shadowc_frame(). lightParams . z - shadowc_frame(). lightParams . y);
  return vec4(uv, d, p . z);
}

float shadowc_viewZ(float d){ return shadowc_frame(). lightParams . y + d *(shadowc_frame(). lightParams . z - shadowc_frame(). lightParams . y);}
#line 43
float shadowc_lightSizeUV(float lightWidth){
  return lightWidth /(2.0 * shadowc_frame(). lightParams . y * shadowc_frame(). lightParams . x);
}
#line 49
float shadowc_searchWidthUV(float lightWidth, float zr){
  return shadowc_lightSizeUV(lightWidth)*(zr - shadowc_frame(). lightParams . y)/ zr;
}
#line 55
float shadowc_penumbraWidthUV(float lightWidth, float zr, float zb){
  return shadowc_lightSizeUV(lightWidth)* shadowc_frame(). lightParams . y *(zr - zb)/(zb * zr);
}
#line 11 "templates/shade.comp"
#line 1 "lookup/shadowc_lookup.glsl"
#line 1 "lookup/defaults.glsl"
#line 14 "lookup/shadowc_lookup.glsl"
#line 1 "frame.glsl"
#line 15 "lookup/shadowc_lookup.glsl"
#line 1 "lookup/resources.glsl"
#line 11
layout(set = 0, binding = 4)uniform sampler2D shadowc_shadowDepth;
#line 16 "lookup/shadowc_lookup.glsl"
#line 1 "lookup/kernel.glsl"
#line 8
struct shadowc_Receiver {
  vec2 uv;
  vec2 texel;
  float d;
  float zr;
  vec3 worldPos;
  float lightWidth;
};

float shadowc_lightWidth(){
#line 21
  return max(shadowc_frame(). lightParams . w, 0.0);

}
#line 28
ivec2 shadowc_mapSize(){ return textureSize(shadowc_shadowDepth, 0);}

float shadowc_depthAt(ivec2 t){
  return texelFetch(shadowc_shadowDepth, clamp(t, ivec2(0), shadowc_mapSize()- 1), 0). r;
}
#line 37
float shadowc_clampTexels(float w){ return(w >= 1.0)? min(w, 64.0): 1.0;}
#line 41
ivec4 shadowc_kernelRect(vec2 c, float w){
  int n = int(shadowc_clampTexels(w)+ 0.5);
  ivec2 lo = ivec2(floor(c - 0.5 * float(n)+ 0.5));
  ivec2 hi = lo + ivec2(n - 1);
  ivec2 last = shadowc_mapSize()- 1;
  return ivec4(clamp(lo, ivec2(0), last), clamp(hi, ivec2(0), last));
}
#line 52
vec4 shadowc_kernelBox(vec2 c, float w){
#line 60
  ivec4 r = shadowc_kernelRect(c, w);
  return vec4(r . xy, r . zw + 1);

}
#line 66
float shadowc_searchTexels(shadowc_Receiver r){
  return shadowc_clampTexels(shadowc_searchWidthUV(r . lightWidth, r . zr)* float(shadowc_mapSize(). x));
}
#line 72
float shadowc_penumbraTexels(shadowc_Receiver r, float zBlocker){
  float zb = max(shadowc_viewZ(clamp(zBlocker, 0.0, 1.0)), shadowc_frame(). lightParams . y);
  return shadowc_clampTexels(shadowc_penumbraWidthUV(r . lightWidth, r . zr, zb)* float(shadowc_mapSize(). x));
}
#line 124
float shadowc_unit(float v){ return(v >= 0.0)? min(v, 1.0): 0.0;}
#line 17 "lookup/shadowc_lookup.glsl"
#line 1 "lookup/bias.glsl"
#line 17
vec4 shadowc_biasedLightPosition(vec3 worldPos, vec3 worldNormal){
  vec3 p = worldPos;
#line 24
  vec3 pl =(shadowc_frame(). lightView * vec4(p, 1.0)). xyz;
  return vec4(p, pl . z > 0.0 ? 1.0 : 0.0);
}

float shadowc_bias(vec3 worldPos, vec3 worldNormal){
#line 37
  return 0.001;

}
#line 18 "lookup/shadowc_lookup.glsl"
#line 1 "lookup/pcf.glsl"
#line 14
float shadowc_litTexel(ivec2 t, float d){ return shadowc_depthAt(t)< d ? 0.0 : 1.0;}
#line 32
float shadowc_pcfGrid(vec2 c, float w, float d, int n){
  float lit = 0.0;
#line 37
  for(int j = 0;j < n;++ j)
    for(int i = 0;i < n;++ i){
      vec2 pos = c +(vec2(i, j)+ 0.5 - 0.5 * float(n))*(w / float(n));
#line 45
      lit += shadowc_litTexel(ivec2(floor(pos)), d);

    }
#line 51
  return lit / float(n * n);

}
#line 107
float shadowc_pcf(shadowc_Receiver r, float w){
#line 116
  return shadowc_pcfGrid(r . texel, w, r . d, 3);

}
#line 23 "lookup/shadowc_lookup.glsl"
#line 54
bool shadowc_receiver(vec3 worldPos, vec3 worldNormal, out shadowc_Receiver r){
  vec4 p = shadowc_biasedLightPosition(worldPos, worldNormal);
  r . worldPos = worldPos;
  r . lightWidth = shadowc_lightWidth();
#line 61
  if(p . w == 0.0)return false;
  vec4 ls = shadowc_lightSpace(p . xyz);
  r . uv = ls . xy;
  r . texel = ls . xy * vec2(shadowc_mapSize());
#line 68
  r . d = ls . z - shadowc_bias(worldPos, worldNormal);
  r . zr = max(ls . w, shadowc_frame(). lightParams . y);

  return all(greaterThanEqual(ls . xy, vec2(0.0)))&& all(lessThanEqual(ls . xy, vec2(1.0)));
}
#line 102
bool shadowc_lightBehind(vec3 worldPos, vec3 worldNormal){
  vec3 p =(shadowc_frame(). lightView * vec4(worldPos, 1.0)). xyz;
  vec3 n = mat3(shadowc_frame(). lightView)* worldNormal;
  float h = 0.5 * shadowc_lightWidth();
#line 112
  return dot(n, - p)+ h *(abs(n . x)+ abs(n . y))<= 0.0;

}
#line 117
float shadowc_visibility(vec3 worldPos, vec3 worldNormal){

  if(shadowc_lightBehind(worldPos, worldNormal))return 0.0;

  shadowc_Receiver r;
  if(! shadowc_receiver(worldPos, worldNormal, r))return 1.0;
#line 144
  float v = shadowc_pcf(r, 3.0);
#line 147
  return shadowc_unit(v);
}
#line 12 "templates/shade.comp"

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1)in;

layout(set = 0, binding = 1, rgba32f)readonly uniform image2D gbuffer_position;
layout(set = 0, binding = 2, rgba32f)readonly uniform image2D gbuffer_normal;
layout(set = 0, binding = 3, r32f)writeonly uniform image2D visibility;

void main(){
  ivec2 pixel = ivec2(gl_GlobalInvocationID . xy);
  ivec2 size = imageSize(visibility);
  if(any(greaterThanEqual(pixel, size)))return;
  vec4 position = imageLoad(gbuffer_position, pixel);
  float v = 1.0;
  if(position . w != 0.0){
    vec3 normal = imageLoad(gbuffer_normal, pixel). xyz;
    v = shadowc_visibility(position . xyz, normal);
  }
#line 31
  v =(v >= 0.0)? min(v, 1.0): 0.0;
  imageStore(visibility, pixel, vec4(v, 0.0, 0.0, 0.0));
}
