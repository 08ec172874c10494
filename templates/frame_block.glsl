// frame_block.glsl — the ShadowcFrame uniform block the runtime harness fills (std140, mirrored
// byte for byte by compiler/manifest/frame_uniforms.h) and shadowc_frame() over it (frame.glsl).
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
  vec4 lightParams;   // x tanHalfFov, y near, z far, w lightWidth (world units)
  vec4 lightShape;    // x 0 rect / 1 disk / 2 point, yzw unused
  vec4 mapInfo;       // x map size (texels), y 1/size, zw unused
  vec4 screenInfo;    // x width, y height, z 1/width, w 1/height
} shadowc_frameBlock;

shadowc_Frame shadowc_frame() { return shadowc_Frame(shadowc_frameBlock.lightView, shadowc_frameBlock.lightParams); }

#endif
