// Internal to render/: the OpenGL API as Mesa's libOSMesa exports it. libOSMesa exports every GL
// entry point up to 4.6 as a plain symbol dispatching to the current context, so prototypes link
// directly (no loader, no GLEW, no OSMesaGetProcAddress). Include only from render/*.cpp.
#pragma once

#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES 1
#endif
#include <GL/osmesa.h>
