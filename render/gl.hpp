#pragma once
// The one way render/ reaches OpenGL: the glad loader generated at build time.
#include <glad/gl.h>
