// The one OpenGL header of src/gl: libepoxy's loader natively (OpenGL 4.5 core, or ES through
// the same entry points), Emscripten's OpenGL ES 3.0 headers in the web build (WebGL2), where
// Gl45Only.h declares the 4.5 calls the wrappers make on their OpenGL 4.5 path only.
#pragma once

#ifdef __EMSCRIPTEN__
#include <GLES3/gl3.h>

#include "gl/Gl45Only.h"
#else
#include <epoxy/gl.h>
#endif
