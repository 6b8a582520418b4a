# Runs lamina and checks that it fails as documented (docs/lamina-command.md, "Exit codes"):
# exit code EXIT, nothing on standard output, standard error exactly one line that starts with
# MESSAGE, and none of the ABSENT paths (nor their temporary "<path>.tmp") left behind.
#
#   cmake -DLAMINA=<binary> -DARGS=<arg|arg|...> -DEXIT=2 -DMESSAGE=<start of the line>
#         [-DABSENT=<path|path|...>] -P expect_failure.cmake
string(REPLACE "|" ";" args "${ARGS}")
string(REPLACE "|" ";" absent "${ABSENT}")
foreach(path IN LISTS absent)
  file(REMOVE_RECURSE "${path}" "${path}.tmp")
endforeach()

execute_process(COMMAND "${LAMINA}" ${args}
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
