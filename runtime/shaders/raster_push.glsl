// Push constants shared by the raster shaders (runtime/raster/rasterizer.cpp fills them).
layout(push_constant) uniform RasterPush {
  mat4 viewProj;    // world -> Vulkan clip (FrameSetup::lightViewProj or cameraViewProj)
  vec4 lightZRow;   // row 2 of the world -> light view matrix: view z = dot(lightZRow, vec4(p, 1))
  vec4 depthRange;  // x near, y far of the light frustum
} raster;
