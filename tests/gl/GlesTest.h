// The GLSL ES tests' two contexts, made once per test process (GlesTestMain.cpp): Mesa's
// OpenGL ES context, whose strict `#version 300 es` compiler stands in for WebGL2's, and an
// OpenGL 4.5 one to compare with. use*() makes one current and activates its capabilities.
#pragma once

#include "gl/Caps.h"

namespace gnomon::test {

void useEs();
void useNative();
const gl::Caps& esCaps();

}  // namespace gnomon::test
