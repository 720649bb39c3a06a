# GL entry points come from a loader generated at build time by Debian's
# python3-glad (docs/design.md): one binary can then load them through either
# OSMesaGetProcAddress or glfwGetProcAddress without libGL/libOSMesa clashes.
# Debian installs it as /usr/bin/glad; prefer that over any other glad on PATH.
find_program(GLAD_EXECUTABLE glad HINTS /usr/bin REQUIRED)

set(UMBRA_GLAD_DIR ${CMAKE_BINARY_DIR}/glad)
add_custom_command(
  OUTPUT ${UMBRA_GLAD_DIR}/src/gl.c ${UMBRA_GLAD_DIR}/include/glad/gl.h
  # --reproducible: use the GL registry shipped in the package, never the network.
  COMMAND ${GLAD_EXECUTABLE} --quiet --reproducible --api gl:core=3.3
          --out-path ${UMBRA_GLAD_DIR} c
  COMMENT "Generating the OpenGL 3.3 core loader with glad"
  VERBATIM)

add_library(umbra_glad STATIC ${UMBRA_GLAD_DIR}/src/gl.c)
target_include_directories(umbra_glad SYSTEM PUBLIC ${UMBRA_GLAD_DIR}/include)
set_target_properties(umbra_glad PROPERTIES POSITION_INDEPENDENT_CODE ON)
target_compile_options(umbra_glad PRIVATE -w)
