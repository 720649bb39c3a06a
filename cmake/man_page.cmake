# umbra.1 from the commands' own --help, so that the man page never says
# other than the program: the top-level help as its description, then one
# section per command, each kept as printed (.nf), roff's escape and
# control characters quoted.
#   cmake -DUMBRA=path/to/umbra -DVERSION=x.y.z -DOUT=umbra.1 -P man_page.cmake
function(help_of out)
  execute_process(COMMAND "${UMBRA}" ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE text ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${UMBRA} ${ARGN} failed (${status}): ${err}")
  endif()
  string(REPLACE "\\" "\\e" text "${text}")
  # A line starting with . or ' would be a roff request: \& keeps it text.
  string(REGEX REPLACE "(^|\n)([.'])" "\\1\\\\&\\2" text "${text}")
  set(${out} "${text}" PARENT_SCOPE)
endfunction()

help_of(top --help)
string(CONCAT page ".TH UMBRA 1 \"\" \"umbra ${VERSION}\" \"User Commands\"\n"
                  ".SH NAME\numbra \\- exact hard shadows from stencil shadow volumes, for mesh files and scenes\n"
                  ".SH DESCRIPTION\n.nf\n${top}.fi\n")
foreach(command render check view volume bench formats)
  help_of(text ${command} --help)
  string(TOUPPER "${command}" title)
  string(APPEND page ".SH \"UMBRA ${title}\"\n.nf\n${text}.fi\n")
endforeach()
string(APPEND page ".SH \"SEE ALSO\"\nThe README and docs/ installed with umbra (share/doc/umbra), and the example "
                   "scenes (share/umbra/scenes).\n")
file(WRITE "${OUT}" "${page}")
