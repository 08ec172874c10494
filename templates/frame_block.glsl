// frame_block.glsl — the ShadowcFrame uniform block the runtime harness fills (std140; its one C++
// definition is the installed include/shadowc/frame.h, checked member by member against this
// block by tests/engine/frame_header_test.cpp) and shadowc_frame() over it (frame.glsl).
// The emitter ships it inside <filter>_lookup.glsl under #ifndef SHADOWC_FRAME_EXTERNAL, placed
// by `shadowc compile --lookup-set/--lookup-binding-base`.
#ifndef SHADOWC_FRAME_BLOCK_GLSL
#define SHADOWC_FRAME_BLOCK_GLSL

#ifndef SHADOWC_SET
#define SHADOWC_SET 0
#endif
#ifndef SHADOWC_BINDING_FRAME
#define SHADOWC_BINDING_FRAME 0
#endif

layout(set = SHADOWC_SET, binding = SHADOWC_BINDING_FRAME, std140) uniform shadowc_FrameBlock {
  mat4 lightView;     // world -> light view
  vec4 lightParams;   // x tanHalfFov (sun: halfExtent), y near, z far, w lightWidth (sun: 2 tan(angle/2))
  vec4 lightShape;    // x 0 rect / 1 disk / 2 point / 3 sun / 4 cube (point light), yzw unused
  vec4 mapInfo;       // x map size (texels), y 1/size, zw unused
  vec4 screenInfo;    // x width, y height, z 1/width, w 1/height
#ifdef SHADOWC_CASCADES  // a cascaded sun (templates/lookup/cascades.glsl); other filters end above
  vec4 cascadeInfo;    // x cascade count, y camera depth where cascade 0 starts, zw unused
  vec4 cameraDepth;    // camera view depth of a world point p: dot(xyz, p) + w
  vec4 cascades[8];    // per cascade: xy light-view offset and z halfExtent of its atlas frame, w far split
#endif
} shadowc_frameBlock;

shadowc_Frame shadowc_frame() { return shadowc_Frame(shadowc_frameBlock.lightView, shadowc_frameBlock.lightParams); }
#ifdef SHADOWC_CASCADES
// The cascade fields, for frame_cascades.glsl (an engine with SHADOWC_FRAME_EXTERNAL defines these).
vec4 shadowc_cascadeInfo() { return shadowc_frameBlock.cascadeInfo; }
vec4 shadowc_cameraDepthRow() { return shadowc_frameBlock.cameraDepth; }
vec4 shadowc_cascadeData(int i) { return shadowc_frameBlock.cascades[i]; }
#endif

#endif
