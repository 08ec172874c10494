// frame_cascades.glsl — a cascaded sun (`cascades N`, SHADOWC_CASCADES = N): the frame of the
// cascade the lookup is in, so that every orthographic function of frame_ortho.glsl, kernel.glsl
// and bias.glsl works per cascade unchanged. Included at the top of frame_ortho.glsl.
// Design: the N cascades are tiles of ONE atlas map, SHADOWC_CASCADE_GRID tiles
// per side (Godot and Unity pack directional splits the same way), so the light-depth image and
// every pass of the manifest stay one 2D image; the lookup clamps each texel fetch to its
// cascade's tile (lookup/cascade_tile.glsl). Every cascade shares the sun's light view and its
// depth range (one normalized depth for all), and differs only in the xy window it covers:
//  cascade i covers light-view xy in [c_i - h_i, c_i + h_i]^2 and sits in tile t_i = (tx, ty),
//  so its atlas uv is (t_i + 0.5 + 0.5 (p.xy - c_i) / h_i) / G, which is frame_ortho.glsl's
//        uv = 0.5 + 0.5 (p.xy + o_i) / H_i    with  H_i = G h_i,  o_i = h_i (2 t_i + 1 - G) - c_i
// The runtime (runtime/scene/cascade_setup.cpp) stores (o_i, H_i, far split_i) per cascade.
// Because H_i is the cascade's own world-per-uv scale, a world-space penumbra or search width
// (frame_ortho.glsl) becomes texels *of that cascade*: kernels rescale per cascade by
// construction, and a penumbra keeps its world width across a border.
#ifndef SHADOWC_FRAME_CASCADES_GLSL
#define SHADOWC_FRAME_CASCADES_GLSL

#ifndef SHADOWC_CASCADE_GRID
#error "SHADOWC_CASCADES needs SHADOWC_CASCADE_GRID (the planner defines both)"
#endif

// The cascade fields of the frame (frame_block.glsl, or the engine's own with
// SHADOWC_FRAME_EXTERNAL): x count, y camera depth where cascade 0 starts; the camera-depth row;
// per cascade (o.x, o.y, H, far split).
vec4 shadowc_cascadeInfo();
vec4 shadowc_cameraDepthRow();
vec4 shadowc_cascadeData(int i);

// The cascade being looked up; lookup/cascades.glsl sets it before each filter evaluation.
int shadowc_cascade = 0;

shadowc_Frame shadowc_cascadeFrame() {
  shadowc_Frame f = shadowc_frame();
  vec4 c = shadowc_cascadeData(shadowc_cascade);
  f.lightView[3].xy += c.xy;
  f.lightParams.x = c.z;
  return f;
}

// From here on every shadowc_frame() of the lookup is the cascade's; lookup/cascades.glsl undoes
// the three renames at the end of the lookup.
#define shadowc_frame shadowc_cascadeFrame
// kernel.glsl's map-clamped fetch, wrapped by the tile-clamped one (lookup/cascade_tile.glsl).
#define shadowc_depthAt shadowc_depthAtAtlas
// shadowc_lookup.glsl's visibility of one cascade, wrapped by the cascade selection and blend.
#define shadowc_visibility shadowc_visibilityInCascade

#endif
