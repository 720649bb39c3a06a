#pragma once
// Loading GL entry points (glad) from whichever backend made the context, and
// checking that the context can draw shadow volumes.

#include <string>

namespace umbra {

using GlProc = void (*)();
using GlProcLoader = GlProc (*)(const char* name);

// Loads every GL 3.3 core function; throws std::runtime_error naming `backend`
// when the context offers less than GL 3.3.
void load_gl_functions(GlProcLoader loader, const std::string& backend);

// Throws std::runtime_error unless the bound default framebuffer has at least
// 8 stencil bits (z-fail counting) and 24 depth bits.
void require_shadow_volume_framebuffer(const std::string& backend);

// "Mesa llvmpipe (LLVM 15.0.6, 256 bits), OpenGL 4.5 (Core Profile) Mesa 22.3.6"
std::string gl_description();

}  // namespace umbra
