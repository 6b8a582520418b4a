# Runs lamina and checks that it fails as documented (docs/lamina-command.md, "Exit codes"):
# exit code EXIT, nothing on standard output, standard error exactly one line that starts with
# MESSAGE, none of the ABSENT paths (nor their temporary "<path>.tmp") left behind, and below
# each CLEAN folder no temporary file and no PNG cut short (each ends with its IEND chunk).
# WRAP is a command lamina runs under, e.g. `sh -c "ulimit -f 8 && exec \"$@\"" sh`.
#
#   cmake -DLAMINA=<binary> -DARGS=<arg|arg|...> -DEXIT=2 -DMESSAGE=<start of the line>
#         [-DABSENT=<path|path|...>] [-DCLEAN=<folder|...>] [-DWRAP=<arg|arg|...>]
#         -P expect_failure.cmake
string(REPLACE "|" ";" args "${ARGS}")
string(REPLACE "|" ";" absent "${ABSENT}")
string(REPLACE "|" ";" clean "${CLEAN}")
string(REPLACE "|" ";" wrap "${WRAP}")
foreach(path IN LISTS absent)
  file(REMOVE_RECURSE "${path}" "${path}.tmp")
endforeach()

execute_process(COMMAND ${wrap} "${LAMINA}" ${args}
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
list(JOIN args " " shown)
set(run "lamina ${shown}")
if(NOT code STREQUAL "${EXIT}")
  message(FATAL_ERROR "${run}\nexit code ${code}, expected ${EXIT}\nstderr: ${err}")
endif()
if(NOT out STREQUAL "")
  message(FATAL_ERROR "${run}\nwrote to standard output:\n${out}")
endif()
string(FIND "${err}" "${MESSAGE}" at)
if(NOT at EQUAL 0)
  message(FATAL_ERROR "${run}\nstderr:   ${err}expected: ${MESSAGE}...")
endif()
string(REGEX MATCHALL "\n" breaks "${err}")
list(LENGTH breaks lines)
if(NOT lines EQUAL 1 OR NOT err MATCHES "\n$")
  message(FATAL_ERROR "${run}\nstderr is not one line:\n${err}")
endif()
foreach(path IN LISTS absent)
  if(EXISTS "${path}" OR EXISTS "${path}.tmp")
    message(FATAL_ERROR "${run}\nleft ${path} behind")
  endif()
endforeach()
foreach(folder IN LISTS clean)
  file(GLOB_RECURSE temporaries "${folder}/*.tmp")
  if(temporaries)
    message(FATAL_ERROR "${run}\nleft temporary files behind: ${temporaries}")
  endif()
  file(GLOB_RECURSE pngs "${folder}/*.png")
  foreach(png IN LISTS pngs)
    file(SIZE "${png}" size)
    math(EXPR end "${size} - 12")
    if(end LESS 0)
      message(FATAL_ERROR "${run}\n${png} is cut short (${size} bytes)")
    endif()
    file(READ "${png}" iend OFFSET ${end} HEX)
    if(NOT iend STREQUAL "0000000049454e44ae426082")
      message(FATAL_ERROR "${run}\n${png} is cut short: it does not end with its IEND chunk")
    endif()
  endforeach()
endforeach()
