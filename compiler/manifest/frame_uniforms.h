// ShadowcFrame, the frame block every pass and lookup reads: defined once, in the installed
// integration header include/shadowc/frame.h (std140 offsets asserted there, and checked against
// templates/frame_block.glsl by tests/engine/frame_header_test.cpp). The runtime fills it with
// the same functions an engine uses (runtime/scene/frame_setup.cpp, cascade_setup.cpp).
#pragma once

#include "shadowc/frame.h"
