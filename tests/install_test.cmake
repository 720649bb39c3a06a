# Installs the build into a fresh prefix and runs the installed umbra from
# there: its --help, and a render of a bundled scene in a folder outside the
# build tree; the loader must find nothing in the build tree.
#   cmake -DBUILD=... -DSOURCE=... -P install_test.cmake
set(prefix "${BUILD}/install-test")
file(REMOVE_RECURSE "${prefix}")
execute_process(COMMAND "${CMAKE_COMMAND}" --install "${BUILD}" --prefix "${prefix}" RESULT_VARIABLE status OUTPUT_QUIET)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "cmake --install failed (${status})")
endif()
foreach(file bin/umbra share/doc/umbra/LICENSE share/doc/umbra/README.md share/doc/umbra/docs/check.md
             share/man/man1/umbra.1 share/umbra/scenes/demo.scene share/umbra/scenes/meshes/torus.obj)
  if(NOT EXISTS "${prefix}/${file}")
    message(FATAL_ERROR "the install has no ${file}")
  endif()
endforeach()
execute_process(COMMAND "${prefix}/bin/umbra" render --help RESULT_VARIABLE status OUTPUT_VARIABLE help)
if(NOT status EQUAL 0 OR NOT help MATCHES "usage: umbra render")
  message(FATAL_ERROR "the installed umbra render --help failed (${status}): ${help}")
endif()
file(MAKE_DIRECTORY "${prefix}/work")
execute_process(COMMAND "${prefix}/bin/umbra" render "${SOURCE}/scenes/demo.scene" -o demo.png --size 64x64
                WORKING_DIRECTORY "${prefix}/work" RESULT_VARIABLE status ERROR_VARIABLE err)
if(NOT status EQUAL 0 OR NOT EXISTS "${prefix}/work/demo.png")
  message(FATAL_ERROR "the installed umbra could not render the demo (${status}): ${err}")
endif()
# The man page is the commands' help.
file(READ "${prefix}/share/man/man1/umbra.1" man)
if(NOT man MATCHES "\\.SH \"UMBRA RENDER\"" OR NOT man MATCHES "--save-scene FILE")
  message(FATAL_ERROR "the installed man page lacks umbra render's help")
endif()
# The installed example scenes render from the install (their meshes too),
# and umbra bench finds them where the current folder has none.
execute_process(COMMAND "${prefix}/bin/umbra" render "${prefix}/share/umbra/scenes/mesh_torus.scene" -o torus.png --size 32x32
                WORKING_DIRECTORY "${prefix}/work" RESULT_VARIABLE status ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "the installed mesh_torus.scene did not render (${status}): ${err}")
endif()
execute_process(COMMAND "${prefix}/bin/umbra" bench --size 16x16 --frames 1 --segments 8 --map-sizes 16
                WORKING_DIRECTORY "${prefix}/work" RESULT_VARIABLE status OUTPUT_VARIABLE table ERROR_VARIABLE err)
if(NOT status EQUAL 0 OR NOT table MATCHES "camera_in_shadow")
  message(FATAL_ERROR "the installed umbra bench did not find the installed scenes (${status}): ${err}")
endif()
# What the loader reads (RPATH, RUNPATH, NEEDED) must not lead into the build
# tree; the debugging information may name where it was compiled.
execute_process(COMMAND readelf -d "${prefix}/bin/umbra" RESULT_VARIABLE status OUTPUT_VARIABLE dynamic)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "readelf failed on the installed umbra (${status})")
endif()
string(FIND "${dynamic}" "${BUILD}" at)
if(NOT at EQUAL -1)
  message(FATAL_ERROR "the installed umbra's dynamic section names the build tree:\n${dynamic}")
endif()
