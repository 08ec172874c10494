#version 460
#extension GL_GOOGLE_include_directive : require
#line 15
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1)in;
layout(set = 0, binding = 0)uniform sampler2D shadowDepth;
layout(set = 0, binding = 1, rgba16)writeonly uniform image2DArray momentsOut;
#line 1 "passes/layer_moments.glsl"
#line 1 "passes/moments_warp.glsl"
#line 1 "passes/msm_moments.glsl"
#line 21
const mat4 shadowc_msmTheta = mat4(- 2.07224649, 13.7948857237, 0.105877704, 9.7924062118,
                                   32.23703778, - 59.4683975703, - 1.9077466311, - 33.7652110555,
                                   - 68.571074599, 82.0359750338, 9.3496555107, 47.9456096605,
                                   39.3703274134, - 35.364903257, - 6.6543490743, - 23.9728048165
);
const mat4 shadowc_msmThetaInverse = mat4(0.2227744146, 0.1549679261, 0.1451988946, 0.163127443,
                                          0.0771972861, 0.1394629426, 0.2120202157, 0.2591432266,
                                          0.7926986636, 0.7963415838, 0.7258694464, 0.6539092497,
                                          0.0319417555, - 0.1722823173, - 0.2758014811, - 0.3376131734
);
const vec4 shadowc_msmOffset = vec4(0.035955884801, 0.0, 0.0, 0.0);

vec4 shadowc_msmPowerMoments(float z){
  float z2 = z * z;
  return vec4(z, z2, z2 * z, z2 * z2);
}
#line 39
vec4 shadowc_msmEncode(float z){

  return shadowc_msmTheta * shadowc_msmPowerMoments(z)+ shadowc_msmOffset;
#line 45
}
#line 48
vec4 shadowc_msmDecode(vec4 stored){

  return shadowc_msmThetaInverse *(stored - shadowc_msmOffset);
#line 54
}
#line 27 "passes/moments_warp.glsl"
#line 29
vec4 shadowc_warpMoments(float d){
#line 42
  return shadowc_msmEncode(d);
#line 46
}
#line 49
float shadowc_layerRemap(float d, float p, float q){ return clamp((d - p)/ max(q - p, 1e-6), 0.0, 1.0);}
#line 24 "passes/layer_moments.glsl"

vec4 shadowc_layerMoments(float d, int layer){

  return shadowc_warpMoments(d);
#line 38
}
#line 22 "templates/passes/moments.comp"

void main(){
  const ivec2 size = textureSize(shadowDepth, 0);
  const ivec2 p = ivec2(gl_GlobalInvocationID . xy);
  if(any(greaterThanEqual(p, size)))return;
  const float d = texelFetch(shadowDepth, p, 0). r;
  for(int i = 0;i < 1;++ i)imageStore(momentsOut, ivec3(p, i), shadowc_layerMoments(d, i));
}
