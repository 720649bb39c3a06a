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
foreach(file bin/umbra share/doc/umbra/LICENSE share/doc/umbra/README.md share/doc/umbra/docs/check.md)
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
