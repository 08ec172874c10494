#version 460
#extension GL_GOOGLE_include_directive : require
#line 51
const float shadowc_splitTable[4]= float[](0.0, 0.25, 0.6, 1.0);
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
#line 17
layout(set = 0, binding = 5)uniform sampler2DArray shadowc_moments;
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
#line 1 "lookup/chebyshev.glsl"
#line 14
float shadowc_chebyshev(float mean, float meanSq, float t, float minVariance){
  float variance = max(meanSq - mean * mean, minVariance);
  float dt = t - mean;
  float denom = variance + dt * dt;
  float p = denom > 0.0 ? shadowc_unit(variance / denom): 0.0;
  return t <= mean ? 1.0 : p;
}

float shadowc_reduceBleeding(float p){
#line 26
  return p;

}
#line 32 "lookup/shadowc_lookup.glsl"
#line 1 "lookup/evsm.glsl"
#line 14
float shadowc_evsm(vec4 m, float d, float minVariance){
  float dc = clamp(d, 0.0, 1.0);
  float ep = exp(5.0 *(dc - 1.0));
  float sp = 5.0 * ep;
  float v = shadowc_reduceBleeding(shadowc_chebyshev(m . x, m . y, ep, minVariance * sp * sp));

  float en = exp(- 5.0 *(dc - 1.0));
  float sn = 5.0 * en;
  v = min(v, shadowc_reduceBleeding(shadowc_chebyshev(m . z, m . w, - en, minVariance * sn * sn)));

  return v;
}
#line 36 "lookup/shadowc_lookup.glsl"
#line 1 "lookup/layered.glsl"
#line 14
float shadowc_split(int i){
#line 19
  return shadowc_splitTable[i];
#line 24
}

vec2 shadowc_layerRange(int i){

  return vec2(shadowc_split(i)- 0.02, shadowc_split(i + 1)+ 0.02);
#line 32
}
#line 35
float shadowc_layerDepth(float d, int i){

  vec2 r = shadowc_layerRange(i);
  return clamp((d - r . x)/ max(r . y - r . x, 1e-6), 0.0, 1.0);
#line 42
}
#line 45
float shadowc_layerMinVariance(int i){

  vec2 r = shadowc_layerRange(i);
  float w = max(r . y - r . x, 1e-6);
  return 1e-05 /(w * w);
#line 53
}
#line 56
int shadowc_layerOf(float d){
  int j = 0;
  for(int i = 1;i < 3;++ i)
    if(d >= shadowc_split(i))j = i;
  return j;
}
#line 45 "lookup/shadowc_lookup.glsl"
#line 1 "lookup/moments_filter.glsl"
#line 37
vec4 shadowc_kernelMoments(vec2 uv, ivec4 rect, float w, int layer){
#line 43
  return textureLod(shadowc_moments, vec3(uv, float(layer)), 0 != 0 ? log2(max(w, 1.0)): 0.0);

}
#line 48
float shadowc_estimate(vec4 m, float d, float minVariance){
#line 57
  return shadowc_evsm(m, d, minVariance);
#line 63
}

float shadowc_layerVisibility(vec2 uv, ivec4 rect, float w, float d, int layer){
  return shadowc_estimate(shadowc_kernelMoments(uv, rect, w, layer), shadowc_layerDepth(d, layer),
                          shadowc_layerMinVariance(layer));
}
#line 71
float shadowc_filteredVisibility(vec2 uv, ivec4 rect, float w, float d){
  int j = shadowc_layerOf(d);
  float v = shadowc_layerVisibility(uv, rect, w, d, j);
#line 76
  const float delta = 0.02;
  if(j + 1 < 3 && d > shadowc_split(j + 1)- delta){
    float t = clamp((d -(shadowc_split(j + 1)- delta))/(2.0 * delta), 0.0, 1.0);
    v = mix(v, shadowc_layerVisibility(uv, rect, w, d, j + 1), t);
  } else if(j > 0 && d < shadowc_split(j)+ delta){
    float t = clamp((d -(shadowc_split(j)- delta))/(2.0 * delta), 0.0, 1.0);
    v = mix(shadowc_layerVisibility(uv, rect, w, d, j - 1), v, t);
  }

  return v;
}
#line 90
float shadowc_momentsTechnique(shadowc_Receiver r){
#line 100
  float w = 3.0;

  return shadowc_filteredVisibility(r . uv, shadowc_kernelRect(r . texel, w), w, r . d);
}
#line 46 "lookup/shadowc_lookup.glsl"
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
#line 137
  float v = shadowc_momentsTechnique(r);
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
