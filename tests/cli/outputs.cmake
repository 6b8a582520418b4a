# `lamina run` puts its outputs where they are asked for: frames at step 0 and every --every
# steps, a CSV trace as two files with one row per dynamic body (or contact) per step.
#
#   cmake -DLAMINA=<binary> -DOUT=<scratch folder> -P outputs.cmake
file(REMOVE_RECURSE "${OUT}")
execute_process(COMMAND "${LAMINA}" run vertical-stack --steps 5 --every 2 --frames "${OUT}/frames"
                        --size 160x90 --overlay all --trace "${OUT}/stack.csv"
                RESULT_VARIABLE code ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "lamina run: exit code ${code}: ${err}")
endif()
file(GLOB frames RELATIVE "${OUT}/frames" "${OUT}/frames/*")
set(expected vertical-stack_0000.png vertical-stack_0001.png vertical-stack_0002.png)
if(NOT frames STREQUAL expected)
  message(FATAL_ERROR "frames: ${frames}\nexpected: ${expected} (steps 0, 2, 4 of 5)")
endif()
file(STRINGS "${OUT}/stack.csv" bodies)
list(LENGTH bodies rows)
if(NOT rows EQUAL 26)  # header + 5 steps × 5 boxes
  message(FATAL_ERROR "stack.csv has ${rows} lines, expected 26")
endif()
file(STRINGS "${OUT}/stack.contacts.csv" contacts LIMIT_COUNT 1)
if(NOT contacts MATCHES "^step,time,body1,body2,")
  message(FATAL_ERROR "stack.contacts.csv starts with '${contacts}'")
endif()
