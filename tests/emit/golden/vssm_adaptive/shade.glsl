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
#line 23
layout(set = 0, binding = 6)uniform usampler2DArray shadowc_summedArea;
#line 31
layout(set = 0, binding = 7)uniform sampler2D shadowc_minMaxPyramid;
#line 38
layout(set = 0, binding = 10, std430)readonly buffer shadowc_QuadtreeTable {
  ivec4 shadowc_qtTable[];
};
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

  return 0.04;
#line 23
}
#line 28
ivec2 shadowc_mapSize(){ return textureSize(shadowc_shadowDepth, 0);}

float shadowc_depthAt(ivec2 t){
  return texelFetch(shadowc_shadowDepth, clamp(t, ivec2(0), shadowc_mapSize()- 1), 0). r;
}
#line 37
float shadowc_clampTexels(float w){ return(w >= 1.0)? min(w, 4096.0): 1.0;}
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
#line 17
float shadowc_litBilinear(vec2 pos, float d){
  vec2 p = pos - 0.5;
  vec2 f = fract(p);
  ivec2 i = ivec2(floor(p));
  float a = shadowc_litTexel(i, d);
  float b = shadowc_litTexel(i + ivec2(1, 0), d);
  float e = shadowc_litTexel(i + ivec2(0, 1), d);
  float g = shadowc_litTexel(i + ivec2(1, 1), d);
  return mix(mix(a, b, f . x), mix(e, g, f . x), f . y);
}
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
#line 57
float shadowc_pcfBilinearGrid(vec2 c, float w, float d, int n){
  float lit = 0.0;
#line 62
  for(int j = 0;j < n;++ j)
    for(int i = 0;i < n;++ i){
      vec2 pos = c +(vec2(i, j)+ 0.5 - 0.5 * float(n))*(w / float(n));
#line 70
      lit += shadowc_litBilinear(pos, d);

    }
#line 76
  return lit / float(n * n);

}
#line 23 "lookup/shadowc_lookup.glsl"
#line 1 "lookup/minmax.glsl"
#line 17
vec2 shadowc_minMaxOfRect(ivec4 rect){
  int w = max(rect . z - rect . x, rect . w - rect . y)+ 1;
  int level = w > 1 ? findMSB(w - 1)+ 1 : 0;
  level = min(level, textureQueryLevels(shadowc_minMaxPyramid)- 1);
  ivec2 last = max(textureSize(shadowc_minMaxPyramid, level)- 1, ivec2(0));
  ivec2 lo = clamp(rect . xy >> level, ivec2(0), last);
  ivec2 hi = clamp(rect . zw >> level, ivec2(0), last);
  vec2 mm = texelFetch(shadowc_minMaxPyramid, lo, level). rg;
#line 27
  for(int y = lo . y;y <= hi . y;++ y)
    for(int x = lo . x;x <= hi . x;++ x){
      vec2 c = texelFetch(shadowc_minMaxPyramid, ivec2(x, y), level). rg;
      mm = vec2(min(mm . x, c . x), max(mm . y, c . y));
    }
  return mm;
}
#line 38
float shadowc_earlyOut(ivec4 rect, float dLo, float dHi){
  vec2 mm = shadowc_minMaxOfRect(rect);
  if(mm . x >= dHi)return 1.0;
  if(mm . y < dLo)return 0.0;
  return - 1.0;
}
#line 29 "lookup/shadowc_lookup.glsl"
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

  return clamp((p - 0.2)/(1.0 - 0.2), 0.0, 1.0);
#line 28
}
#line 32 "lookup/shadowc_lookup.glsl"
#line 1 "lookup/sat.glsl"
#line 27
const float shadowc_satVarianceFloor = 2.4e-5;
#line 33
uvec4 shadowc_summedCorner(int x, int y, int layer){
  uvec4 v = texelFetch(shadowc_summedArea, ivec3(max(x, 0), max(y, 0), layer), 0);
  return x < 0 || y < 0 ? uvec4(0u): v;
}
#line 51
vec4 shadowc_satMeanOfSum(uvec4 sum, float area){

  return vec4(sum)/(65536.0 * area);
#line 59
}
#line 75
const int shadowc_satPiece = 255;
#line 78
int shadowc_satCut(int lo, int hi, int i){ return min(lo - 1 + i * shadowc_satPiece, hi);}

vec4 shadowc_summedSum(ivec4 rect, int layer){
  ivec2 pieces =(rect . zw - rect . xy + shadowc_satPiece)/ shadowc_satPiece;
  vec4 sum = vec4(0.0);
  for(int j = 0;j < 17 && j < pieces . y;++ j){
    int y0 = shadowc_satCut(rect . y, rect . w, j);
    int y1 = shadowc_satCut(rect . y, rect . w, j + 1);
    uvec4 lo0 = shadowc_summedCorner(rect . x - 1, y0, layer);
    uvec4 hi0 = shadowc_summedCorner(rect . x - 1, y1, layer);
    for(int i = 1;i <= 17 && i <= pieces . x;++ i){
      int x1 = shadowc_satCut(rect . x, rect . z, i);
      uvec4 lo1 = shadowc_summedCorner(x1, y0, layer);
      uvec4 hi1 = shadowc_summedCorner(x1, y1, layer);
      sum += vec4(hi1 - hi0 - lo1 + lo0);
      lo0 = lo1;
      hi0 = hi1;
    }
  }
  return sum;
}
#line 102
vec4 shadowc_summedMean(ivec4 rect, int layer){
  float area = float((rect . z - rect . x + 1)*(rect . w - rect . y + 1));
  area = max(area, 1.0);

  return shadowc_summedSum(rect, layer)/(65536.0 * area);
#line 113
}
#line 43 "lookup/shadowc_lookup.glsl"

#line 1 "lookup/layered.glsl"
#line 14
float shadowc_split(int i){
#line 22
  return i == 0 ? 0.0 : 1.0;

}

vec2 shadowc_layerRange(int i){
#line 30
  return vec2(0.0, 1.0);

}
#line 35
float shadowc_layerDepth(float d, int i){
#line 40
  return d;

}
#line 45
float shadowc_layerMinVariance(int i){
#line 51
  return 1e-05;

}
#line 56
int shadowc_layerOf(float d){
  int j = 0;
  for(int i = 1;i < 1;++ i)
    if(d >= shadowc_split(i))j = i;
  return j;
}
#line 45 "lookup/shadowc_lookup.glsl"
#line 1 "lookup/moments_filter.glsl"
#line 14
vec4 shadowc_rectMoments(ivec4 rect, int layer){

  return shadowc_summedMean(rect, layer);
#line 22
}
#line 26
vec4 shadowc_boxMoments(vec4 box, int layer){
#line 30
  return shadowc_rectMoments(ivec4(box . xy, box . zw - 1.0), layer);

}
#line 37
vec4 shadowc_kernelMoments(vec2 uv, ivec4 rect, float w, int layer){
#line 41
  return shadowc_summedMean(rect, layer);
#line 45
}
#line 48
float shadowc_estimate(vec4 m, float d, float minVariance){
#line 51
  minVariance = max(minVariance, shadowc_satVarianceFloor);

  return shadowc_reduceBleeding(shadowc_chebyshev(m . x, m . y, d, minVariance));
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
#line 85
  return v;
}
#line 90
float shadowc_momentsTechnique(shadowc_Receiver r){
#line 97
  float w = shadowc_searchTexels(r);
#line 102
  return shadowc_filteredVisibility(r . uv, shadowc_kernelRect(r . texel, w), w, r . d);
}
#line 46 "lookup/shadowc_lookup.glsl"
#line 1 "lookup/vssm.glsl"
#line 31
vec4 shadowc_vRoot;
float shadowc_vD;
float shadowc_vMinVariance;
float shadowc_aEx;
float shadowc_aEx2;
float shadowc_aVsmArea;
float shadowc_aLitArea;
float shadowc_aPcfArea;
float shadowc_aPcfOcc;
float shadowc_aPcfDepth;

void shadowc_vssmBegin(vec4 root, float d){
  shadowc_vRoot = root;
  shadowc_vD = d;

  shadowc_vMinVariance = max(1e-05, shadowc_satVarianceFloor);
#line 50
  shadowc_aEx = 0.0;
  shadowc_aEx2 = 0.0;
  shadowc_aVsmArea = 0.0;
  shadowc_aLitArea = 0.0;
  shadowc_aPcfArea = 0.0;
  shadowc_aPcfOcc = 0.0;
  shadowc_aPcfDepth = 0.0;
}
#line 61
vec4 shadowc_subBox(ivec3 node){
#line 67
  ivec2 root = ivec2(shadowc_vRoot . xy);
  ivec2 size = ivec2(shadowc_vRoot . zw)- root;
  return vec4(root +(node . xy * size)/ node . z, root +((node . xy + 1)* size)/ node . z);

}
#line 77
vec4 shadowc_qtBox(ivec3 node){
#line 81
  ivec2 root = ivec2(shadowc_vRoot . xy);
  ivec2 size = ivec2(shadowc_vRoot . zw)- root;
  int s = findLSB(node . z);
  return vec4(root +((node . xy * size)>> s), root +(((node . xy + 1)* size)>> s));

}

float shadowc_boxArea(vec4 box){ return(box . z - box . x)*(box . w - box . y);}
#line 94
float shadowc_boxWeight(vec4 box){
#line 98
  return shadowc_boxArea(box);

}
#line 111
int shadowc_classify(vec4 m, float area, bool acceptNormal){
  bool there = area > 0.0;
  float variance = m . y - m . x * m . x;
  bool lit = there && m . x >= shadowc_vD && variance < 0.0001;
  bool normal = there && acceptNormal && ! lit && m . x < shadowc_vD;
  shadowc_aLitArea += lit ? area : 0.0;
  shadowc_aEx += normal ? m . x * area : 0.0;
  shadowc_aEx2 += normal ? m . y * area : 0.0;
  shadowc_aVsmArea += normal ? area : 0.0;
  return there && ! lit && ! normal ? 1 : 0;
}
#line 124
int shadowc_qtAccept(vec4 m, float area){ return shadowc_classify(m, area, true);}
#line 127
int shadowc_qtClassifyBox(vec4 box){
  return shadowc_qtAccept(shadowc_boxMoments(box, 0), shadowc_boxWeight(box));
}
#line 134
int shadowc_qtClassifyNode(vec4 box, bool leaf){
#line 138
  return shadowc_qtClassifyBox(box);

}
#line 143
void shadowc_qtResolveLeaf(vec4 box){
  float area = shadowc_boxWeight(box);

  const int n = 2;
  vec2 size = box . zw - box . xy;
  float occluded = 0.0;
  float depthSum = 0.0;
  for(int j = 0;j < n;++ j)
    for(int i = 0;i < n;++ i){
#line 155
      ivec2 t = ivec2(box . xy)+ ivec2(floor((vec2(i, j)+ 0.5)* size / float(n)));

      float z = shadowc_depthAt(t);
      if(z < shadowc_vD){
        occluded += 1.0;
        depthSum += z;
      }
    }
  float scale = area / float(n * n);
  shadowc_aPcfArea += area;
  shadowc_aPcfOcc += occluded * scale;
  shadowc_aPcfDepth += depthSum * scale;
#line 170
}
#line 173
void shadowc_qtLeafBox(vec4 box){
  if(shadowc_qtClassifyBox(box)== 1)shadowc_qtResolveLeaf(box);
}
#line 180
void shadowc_markSet(inout uint lo, inout uint hi, int b, bool on){
  uint m = on ? 1u <<(b & 31): 0u;
  lo |= b < 32 ? m : 0u;
  hi |= b >= 32 ? m : 0u;
}
#line 191
int shadowc_markPop(inout uint lo, inout uint hi){
  int b = lo != 0u ? findLSB(lo): hi != 0u ? 32 + findLSB(hi): - 1;
  if(b < 32)lo &= lo - 1u;
  else hi &= hi - 1u;
  return b;
}
#line 199
void shadowc_markResolve(int b, vec4 box){ shadowc_qtResolveLeaf(b < 0 ? vec4(0.0, 0.0, 1.0, 1.0): box);}
#line 203
bool shadowc_qtVisit(ivec3 node){ return shadowc_qtClassifyNode(shadowc_qtBox(node), false)== 1;}
void shadowc_qtLeaf(ivec3 node){ shadowc_qtLeafBox(shadowc_qtBox(node));}

#line 1 "lookup/uniform_walk.glsl"
#line 14
bool shadowc_rootNeedsWalk(vec4 m, float area, bool nonPlanarOnly){
  return shadowc_classify(m, area, nonPlanarOnly)== 1;
}
#line 74
vec4 shadowc_walkMean(vec2 sum, float area){

  return vec4(sum /(65536.0 * area), 0.0, 0.0);
#line 80
}
#line 85
void shadowc_uniformResolveMarks(uint marksLo, uint marksHi, int den){
  while((marksLo | marksHi)!= 0u){
    int b = shadowc_markPop(marksLo, marksHi);
    int j = b / den;
    shadowc_markResolve(b, shadowc_subBox(ivec3(b - j * den, j, den)));
  }
}
#line 156
void shadowc_uniformWalk(int den, bool nonPlanarOnly){
  vec4 whole = shadowc_subBox(ivec3(0, 0, 1));
  if(den == 1){
    shadowc_qtLeafBox(whole);
    return;
  }
#line 213
  ivec2 root = ivec2(shadowc_vRoot . xy);
  ivec2 size = ivec2(shadowc_vRoot . zw)- root;
  int subs = den * den;
  const int piece = shadowc_satPiece;
#line 219
  bool wideSubs = 17 > den && max(size . x, size . y)> piece * den;

  uint marksLo = 0u;
  uint marksHi = 0u;

  int k = - 1;
  int j = 0;
  int c = 0;
  vec2 acc = vec2(0.0);
                uvec2 lo = uvec2(0);
                uvec2 hi = uvec2(0);
  int xc = 0;
  bool more = true;
  const int limit =(1 + 5 * 5)* 17 *
                        (17 / 2 + 1)+ 5 *(5 / 2 + 1);
  for(int step = 0;step < limit && more;++ step){
    bool grid = k == subs;

    ivec4 box = k < 0 || ! wideSubs ? ivec4(root, root + size): ivec4(shadowc_subBox(ivec3(k % den, k / den, den)));
    ivec2 cells = max((box . zw - box . xy + piece - 1)/ piece, 1);
#line 241
    int ncol = grid ? den + 1 : cells . x + 1;
    int cb = min(c + 1, ncol - 1);
    int y0 = grid ? root . y +(j * size . y)/ den : min(box . y + j * piece, box . w);
    int y1 = grid ? root . y +((j + 1)* size . y)/ den : min(box . y +(j + 1)* piece, box . w);
    int xa = grid ? root . x +(c * size . x)/ den : min(box . x + c * piece, box . z);
    int xb = grid ? root . x +(cb * size . x)/ den : min(box . x + cb * piece, box . z);
                  uvec2 la = shadowc_summedCorner(xa - 1, y0 - 1, 0). xy;
                  uvec2 ha = shadowc_summedCorner(xa - 1, y1 - 1, 0). xy;
                  uvec2 lb = shadowc_summedCorner(xb - 1, y0 - 1, 0). xy;
                  uvec2 hb = shadowc_summedCorner(xb - 1, y1 - 1, 0). xy;
                  uvec2 s1 = ha - hi - la + lo;
                  uvec2 s2 = hb - ha - lb + la;
    bool cell1 = c > 0 && xa > xc && y1 > y0;
    bool cell2 = cb > c && xb > xa && y1 > y0;
    float area1 = float((xa - xc)*(y1 - y0));
    float area2 = float((xb - xa)*(y1 - y0));

    if(! grid){
      acc += cell1 ? vec2(s1): vec2(0.0);
      acc += cell2 ? vec2(s2): vec2(0.0);
    }
    int bit = j * den + c;
    c += 2;
    bool bandEnd = c >= ncol;
    if(bandEnd){
      c = 0;
      ++ j;
    }
#line 272
    bool on1 = grid && cell1;
    bool nonPlanar1 = shadowc_classify(shadowc_walkMean(vec2(s1), max(area1, 1.0)), on1 ? area1 : 0.0, true)== 1;

    shadowc_markSet(marksLo, marksHi, bit - 1, nonPlanar1);
#line 280
    float area = grid ? area2 : float((box . z - box . x)*(box . w - box . y));
    bool on2 = grid ? cell2 : bandEnd && j >= cells . y && area > 0.0;
    vec4 m = shadowc_walkMean(grid ? vec2(s2): acc, max(area, 1.0));
#line 285
    bool nonPlanar = shadowc_classify(m, on2 ? area : 0.0, k >= 0 || nonPlanarOnly)== 1;

    shadowc_markSet(marksLo, marksHi, grid ? bit : k, k >= 0 && nonPlanar);
#line 291
    lo = lb;
    hi = hb;
    xc = xb;
    if(bandEnd && j >=(grid ? den : cells . y)){
      more = k < 0 ? nonPlanar : k + 1 < subs;
      k = k < 0 && ! wideSubs ? subs : k + 1;
      j = 0;
      acc = vec2(0.0);
    }
  }

  shadowc_uniformResolveMarks(marksLo, marksHi, den);
#line 312
}
#line 207 "lookup/vssm.glsl"
#line 228
int shadowc_qtMorton(ivec2 p){
  ivec2 s =(p & 1)|((p & 2)<< 1)|((p & 4)<< 2);
  return s . x |(s . y << 1);
}
int shadowc_qtUnmorton(int b){ return(b & 1)|((b >> 1)& 2)|((b >> 2)& 4);}
#line 240
bool shadowc_qtDefers(int height){

  return height <= 3;
#line 246
}
#line 250
bool shadowc_qtStep(ivec3 n, int height, bool defer, inout uint marksLo, inout uint marksHi){
  vec4 box = shadowc_qtBox(n);
  bool leaf = n . z >=(1 << height);
  bool nonPlanar = shadowc_qtClassifyNode(box, leaf)== 1;

  if(defer){
    shadowc_markSet(marksLo, marksHi, shadowc_qtMorton(n . xy), nonPlanar && leaf);
  } else

  if(nonPlanar && leaf)shadowc_qtResolveLeaf(box);
  return nonPlanar && ! leaf;
}
#line 264
void shadowc_qtResolveMarked(int height, uint marksLo, uint marksHi){

  while((marksLo | marksHi)!= 0u){
    int b = shadowc_markPop(marksLo, marksHi);
    shadowc_markResolve(b, shadowc_qtBox(ivec3(shadowc_qtUnmorton(b), shadowc_qtUnmorton(b >> 1), 1 << height)));
  }

}
#line 293
void shadowc_qtTableWalk(int height){
  int i = 0;
  bool defer = shadowc_qtDefers(height);
  uint marksLo = 0u;
  uint marksHi = 0u;
  for(int step = 0;step < 85 && i >= 0;++ step){
    ivec4 t = shadowc_qtTable[i];
    i = shadowc_qtStep(ivec3(t . x & 0xffff, t . x >> 16, t . y), height, defer, marksLo, marksHi)? t . z : t . w;
  }
  shadowc_qtResolveMarked(height, marksLo, marksHi);
}
#line 308
float shadowc_vssmBlocker(vec4 searchBox, float d){
  shadowc_vssmBegin(searchBox, d);
#line 319
  shadowc_uniformWalk(5, 0 != 0);
#line 324
  float a1 = 0.0;
  float z1 = 0.0;
  if(shadowc_aVsmArea > 0.0){
    float mean = shadowc_aEx / shadowc_aVsmArea;
    float meanSq = shadowc_aEx2 / shadowc_aVsmArea;
    float p = shadowc_chebyshev(mean, meanSq, d, shadowc_vMinVariance);
    if(1.0 - p > 1e-4){
      z1 = clamp((mean - p * d)/(1.0 - p), 0.0, d);
      a1 =(1.0 - p)* shadowc_aVsmArea;
    }
  }

  float a = a1 + shadowc_aPcfOcc;
  if(!(a > 1e-6))return - 1.0;
  return clamp((z1 * a1 + shadowc_aPcfDepth)/ a, 0.0, d);
}
#line 342
float shadowc_vssmVisibility(vec4 box, float d){
  shadowc_vssmBegin(box, d);
#line 348
  shadowc_qtTableWalk(3);
#line 357
  float l = 1.0;
  if(shadowc_aVsmArea > 0.0)
    l = shadowc_reduceBleeding(shadowc_chebyshev(shadowc_aEx / shadowc_aVsmArea, shadowc_aEx2 / shadowc_aVsmArea, d,
                                                 shadowc_vMinVariance));
  float l1 = shadowc_aPcfArea > 0.0 ? 1.0 - shadowc_aPcfOcc / shadowc_aPcfArea : 1.0;
  float total = shadowc_aVsmArea + shadowc_aLitArea + shadowc_aPcfArea;
  if(!(total > 0.0))return 1.0;
  return shadowc_unit((l * shadowc_aVsmArea + shadowc_aLitArea + l1 * shadowc_aPcfArea)/ total);
}

float shadowc_vssm(shadowc_Receiver r){
  vec4 searchBox = shadowc_kernelBox(r . texel, shadowc_searchTexels(r));
#line 372
  float zb = shadowc_vssmBlocker(searchBox, r . d);
#line 380
  float zAvg = shadowc_boxMoments(searchBox, 0). x;
  bool touching = r . d - zAvg > 0.0 && r . d - zAvg < 0.01;
  if(touching ||(zb >= 0.0 && abs(r . d - zb)< 0.01)){

    float cw = shadowc_penumbraTexels(r, zb >= 0.0 ? zb : zAvg);
#line 388
    return shadowc_pcfBilinearGrid(r . texel, cw, r . d, 3);
  }

  if(zb < 0.0)return 1.0;

  float w = shadowc_penumbraTexels(r, zb);
#line 400
  return shadowc_vssmVisibility(shadowc_kernelBox(r . texel, w), r . d);
}
#line 49 "lookup/shadowc_lookup.glsl"
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
#line 79
ivec4 shadowc_influenceRect(shadowc_Receiver r){

  ivec4 rect = shadowc_kernelRect(r . texel, shadowc_searchTexels(r));
#line 85
  ivec2 last = shadowc_mapSize()- 1;
  const int grow = 1 + 0;
  return ivec4(max(rect . xy - grow, ivec2(0)), min(rect . zw + grow, last));
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
#line 125
  ivec4 rect = shadowc_influenceRect(r);
#line 129
  vec2 span = vec2(r . d);

  float early = shadowc_earlyOut(rect, span . x, span . y);
  if(early >= 0.0)return early;
#line 135
  float v = shadowc_vssm(r);
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
