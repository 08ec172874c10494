// frame_light_samples.glsl — a spot light seen from N points on it (`light_samples N`,
// SHADOWC_LIGHT_SAMPLES = N): the frame of the light view the lookup is in, so that every function
// of frame.glsl, kernel.glsl and bias.glsl works per view unchanged. Included at the top of
// frame.glsl's spot branch.
// Design: view i is the light's own view moved to the point s_i = W o_i of the light (W its width,
// o_i = shadowc_lightSampleOffsets[i], docs/dsl.md "light_samples"): same axes, same tanHalfFov,
// near and far (the runtime fits tanHalfFov so that every view covers the scene, and the
// normalized depth, a function of z alone, is the light's). Its hard map is tile
// (i mod G, i div G) of ONE atlas, as the cascades' are (frame_cascades.glsl), so the light-depth
// image stays one 2D image; kernel.glsl reads the tile as the map (lookup/light_sample_tile.glsl).
// A view's frame keeps the light's width: its fixed kernel never reads it, and its backface test
// (shadowc_lookup.glsl) is then only weaker than the views' own facing test (light_samples.glsl).
#ifndef SHADOWC_FRAME_LIGHT_SAMPLES_GLSL
#define SHADOWC_FRAME_LIGHT_SAMPLES_GLSL

#ifndef SHADOWC_LIGHT_SAMPLE_GRID
#error "SHADOWC_LIGHT_SAMPLES needs SHADOWC_LIGHT_SAMPLE_GRID and shadowc_lightSampleOffsets (the planner defines them)"
#endif

// The view being looked up and its point on the light (world units in the light view's xy);
// lookup/light_samples.glsl sets both before each view's evaluation, reading the offsets table once
// per view (a const array indexed by a variable is copied to memory on some compilers per read).
int shadowc_lightSample = 0;
vec2 shadowc_lightSamplePoint = vec2(0.0);

shadowc_Frame shadowc_lightSampleFrame() {
  shadowc_Frame f = shadowc_frame();
  f.lightView[3].xy -= shadowc_lightSamplePoint;
  return f;
}

// From here on every shadowc_frame() of the lookup is the view's; lookup/light_samples.glsl undoes
// the two renames at the end of the lookup.
#define shadowc_frame shadowc_lightSampleFrame
// shadowc_lookup.glsl's visibility of one view, wrapped by the weighted sum over the views.
#define shadowc_visibility shadowc_visibilityFromSample

#endif
