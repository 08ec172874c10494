#version 460
#extension GL_GOOGLE_include_directive : require
#line 43
const vec2 shadowc_poissonPcf[32]= vec2[](vec2(- 0.0841346765, - 0.637574607), vec2(- 0.298654647, 0.909686429), vec2(0.909073413, 0.268397074), vec2(- 0.847625263, 0.0325486921), vec2(0.780809036, - 0.603617518), vec2(0.0369577091, 0.164983138), vec2(0.453231299, 0.888497225), vec2(- 0.694310779, - 0.627848962), vec2(0.519970057, - 0.103337728), vec2(- 0.35179077, - 0.179725706), vec2(- 0.44169117, 0.388021544), vec2(0.307776472, - 0.913085568), vec2(0.429814712, 0.400962943), vec2(0.0520009757, 0.645435175), vec2(0.952093652, - 0.19628198), vec2(- 0.871295919, 0.461486305), vec2(0.113922792, - 0.252060138), vec2(- 0.404048443, - 0.910818834), vec2(0.720645251, 0.609744658), vec2(0.373048485, - 0.507597016), vec2(- 0.859507703, - 0.322146399), vec2(- 0.613262083, 0.720926204), vec2(- 0.0170520793, - 0.982231213), vec2(0.0273825855, 0.976643885), vec2(- 0.379473427, - 0.517019399), vec2(- 0.536449851, 0.0648677918), vec2(- 0.166350226, 0.462073235), vec2(- 0.252368084, 0.151256353), vec2(0.633120335, 0.203177418), vec2(0.554466486, - 0.773794902), vec2(0.704001422, - 0.342162973), vec2(0.331310386, 0.133089444));

const vec2 shadowc_poissonBlocker[16]= vec2[](vec2(0.0958530825, - 0.595546058), vec2(0.33019398, 0.934204178), vec2(- 0.923934603, 0.307299889), vec2(0.870788861, 0.000214432748), vec2(- 0.752278945, - 0.583465332), vec2(- 0.134503773, 0.216850642), vec2(- 0.315759173, 0.852034183), vec2(0.648619334, - 0.711916121), vec2(0.416443818, 0.335460411), vec2(0.3979976, - 0.176631552), vec2(- 0.354441991, - 0.929124403), vec2(- 0.600433688, - 0.0948364334), vec2(0.812060969, 0.546462762), vec2(- 0.513792422, 0.45951067), vec2(- 0.255871891, - 0.344512652), vec2(0.0727314297, 0.577132379));
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
float shadowc_clampTexels(float w){ return(w >= 1.0)? min(w, 48.0): 1.0;}
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

  float z0 =(shadowc_frame(). lightView * vec4(worldPos, 1.0)). z;
  float texelWorld = 2.0 * max(z0, 0.0)* shadowc_frame(). lightParams . x / float(shadowc_mapSize(). x);
  p += worldNormal *(2.0 * texelWorld);

  vec3 pl =(shadowc_frame(). lightView * vec4(p, 1.0)). xyz;
  return vec4(p, pl . z > 0.0 ? 1.0 : 0.0);
}

float shadowc_bias(vec3 worldPos, vec3 worldNormal){
#line 37
  return 0.001;

}
#line 42
vec2 shadowc_rpGradient;
vec2 shadowc_rpCentre;
#line 51
void shadowc_receiverPlaneBegin(vec3 worldPos, vec3 worldNormal, vec2 texel){
  vec3 pl =(shadowc_frame(). lightView * vec4(worldPos, 1.0)). xyz;
  vec3 nl = mat3(shadowc_frame(). lightView)* worldNormal;
#line 70
  vec3 ray = vec3(pl . xy / pl . z, 1.0);
  float texelWorld = 2.0 * pl . z * shadowc_frame(). lightParams . x / float(shadowc_mapSize(). x);

  float den = dot(nl, ray);
  float lim = max(length(nl . xy)/ 20.0, 1e-20);
  den =(den < 0.0 ? - 1.0 : 1.0)* max(abs(den), lim);
  float range = shadowc_frame(). lightParams . z - shadowc_frame(). lightParams . y;
  shadowc_rpGradient = - nl . xy / den *(texelWorld / range);
  shadowc_rpCentre = texel;
}
#line 83
float shadowc_tapDepth(ivec2 t, float d){ return d + dot(shadowc_rpGradient, vec2(t)+ 0.5 - shadowc_rpCentre);}
#line 88
vec2 shadowc_receiverPlaneRange(ivec4 rect){
  vec2 a = shadowc_rpGradient *(vec2(rect . xy)+ 0.5 - shadowc_rpCentre);
  vec2 b = shadowc_rpGradient *(vec2(rect . zw)+ 0.5 - shadowc_rpCentre);
  vec2 lo = min(a, b);
  vec2 hi = max(a, b);
  return vec2(lo . x + lo . y, hi . x + hi . y);
}
#line 18 "lookup/shadowc_lookup.glsl"

#line 1 "lookup/rotation.glsl"
#line 10
uvec3 shadowc_pcg3d(uvec3 v){
  v = v * 1664525u + 1013904223u;
  v . x += v . y * v . z;
  v . y += v . z * v . x;
  v . z += v . x * v . y;
  v ^= v >> 16u;
  v . x += v . y * v . z;
  v . y += v . z * v . x;
  v . z += v . x * v . y;
  return v;
}
#line 23
vec2 shadowc_rotation(vec3 worldPos){
#line 26
  vec3 cell = clamp(floor(worldPos * 4096.0), vec3(- 2.0e9), vec3(2.0e9));
  uint h = shadowc_pcg3d(uvec3(ivec3(cell))). x;
  float a = float(h >> 8u)*(6.28318530718 / 16777216.0);
  return vec2(cos(a), sin(a));
#line 33
}

vec2 shadowc_rotate(vec2 tap, vec2 rot){ return vec2(rot . x * tap . x - rot . y * tap . y, rot . y * tap . x + rot . x * tap . y);}
#line 20 "lookup/shadowc_lookup.glsl"
#line 1 "lookup/pcf.glsl"
#line 14
float shadowc_litTexel(ivec2 t, float d){ return shadowc_depthAt(t)< shadowc_tapDepth(t, d)? 0.0 : 1.0;}
#line 82
float shadowc_pcfPoisson(vec2 c, float w, float d, vec2 rot){
  float lit = 0.0;
#line 87
  for(int i = 0;i < 32;++ i){
    vec2 o = shadowc_rotate(shadowc_poissonPcf[i], rot)* 0.5;
#line 94
    lit += shadowc_litTexel(ivec2(floor(c + o * w)), d);

  }
#line 100
  return lit / float(32);

}
#line 107
float shadowc_pcf(shadowc_Receiver r, float w){
#line 112
  return shadowc_pcfPoisson(r . texel, w, r . d, shadowc_rotation(r . worldPos));
#line 118
}
#line 23 "lookup/shadowc_lookup.glsl"
#line 1 "lookup/pcss.glsl"
#line 14
float shadowc_blockerSearch(shadowc_Receiver r, float w){
  float sum = 0.0;
  float count = 0.0;
#line 21
  vec2 rot = shadowc_rotation(r . worldPos);
  for(int i = 0;i < 16;++ i){
    vec2 o = shadowc_rotate(shadowc_poissonBlocker[i], rot)* 0.5;
    ivec2 t = ivec2(floor(r . texel + o * w));
    float z = shadowc_depthAt(t);
#line 33
    if(z < shadowc_tapDepth(t, r . d)){
      sum += z;
      count += 1.0;
    }

  }
#line 60
  return count > 0.0 ? sum / count : - 1.0;
}
#line 64
float shadowc_pcss(shadowc_Receiver r){
  float zb = shadowc_blockerSearch(r, shadowc_searchTexels(r));
  if(zb < 0.0)return 1.0;
  return shadowc_pcf(r, shadowc_penumbraTexels(r, zb));
}
#line 26 "lookup/shadowc_lookup.glsl"
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

  shadowc_receiverPlaneBegin(p . xyz, worldNormal, r . texel);

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
#line 139
  float v = shadowc_pcss(r);
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
