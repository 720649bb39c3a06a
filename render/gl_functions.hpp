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

// Throws std::runtime_error ("BACKEND: the image may be at most WxH") unless
// the current context can draw `width` x `height` pixels into a framebuffer
// object (FrameTarget).
void require_image_size(int width, int height, const std::string& backend);

// "llvmpipe (LLVM 15.0.6, 256 bits), OpenGL 4.5 (Core Profile) Mesa 22.3.6"
std::string gl_description();
// The first part of that: "llvmpipe (LLVM 15.0.6, 256 bits)"
std::string gl_renderer();

}  // namespace umbra
