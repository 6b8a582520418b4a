# The ctest catalogue_complete: every message the sources pass to tr() (or mark by msg()) is in the Korean catalogue
# (engine/language/ko/*.po), translated, and in one of its files only.
#
#   cmake -DSOURCE=<source dir> -DWORK=<folder> -P check_catalogue.cmake
#
# xgettext (Debian's gettext) lists the messages of the sources and of the viewer's page script
# (its t("…")) as a template; msgcomm finds a message
# two files share (it belongs in common.po, once); msgcat joins the files as the build does,
# msgcmp fails on a message the catalogue lacks, and msgfmt --statistics must count no
# untranslated or fuzzy entry.
cmake_minimum_required(VERSION 3.25)
file(GLOB_RECURSE sources RELATIVE "${SOURCE}" "${SOURCE}/engine/*.cpp" "${SOURCE}/engine/*.h"
     "${SOURCE}/tutorials/*.cpp" "${SOURCE}/tutorials/*.h")
list(SORT sources)
file(MAKE_DIRECTORY "${WORK}")
execute_process(COMMAND xgettext --language=C++ --keyword=tr --keyword=msg --from-code=UTF-8 --no-location
                        -o "${WORK}/lamina.pot" ${sources}
                WORKING_DIRECTORY "${SOURCE}" RESULT_VARIABLE status ERROR_VARIABLE error)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "xgettext failed: ${error}")
endif()
if(NOT EXISTS "${WORK}/lamina.pot")
  message(FATAL_ERROR "xgettext found no tr(\"...\") in the sources")
endif()
# the step-through viewer's page: its script's t("…"), read as JavaScript
file(READ "${SOURCE}/engine/app/harness/viewer/index.html" page)
string(FIND "${page}" "<script>" first REVERSE)
string(FIND "${page}" "</script>" last REVERSE)
math(EXPR first "${first} + 8")
math(EXPR length "${last} - ${first}")
string(SUBSTRING "${page}" ${first} ${length} script)
file(WRITE "${WORK}/viewer.js" "${script}")
# the statements of the text's equations, which the viewer lists (equation_table.cmake reads the
# rows of docs/the-text.md): each a message, written out as JavaScript t("…") for xgettext
include("${SOURCE}/engine/app/harness/viewer/equation_table.cmake")
equation_statements("${SOURCE}/docs/the-text.md" json statements)
file(WRITE "${WORK}/equations.js" "${statements}")
execute_process(COMMAND xgettext --language=JavaScript --keyword=t --from-code=UTF-8 --no-location
                        --join-existing -o "${WORK}/lamina.pot" "${WORK}/viewer.js" "${WORK}/equations.js"
                RESULT_VARIABLE status ERROR_VARIABLE error)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "xgettext (the viewer's script, the equations' statements) failed: ${error}")
endif()
file(STRINGS "${WORK}/lamina.pot" ids ENCODING UTF-8 REGEX "^msgid \".+\"$")
list(LENGTH ids count)
file(GLOB parts "${SOURCE}/engine/language/ko/*.po")
list(SORT parts)
file(REMOVE "${WORK}/shared.po")
execute_process(COMMAND msgcomm --more-than=1 --no-location -o "${WORK}/shared.po" ${parts}
                RESULT_VARIABLE status ERROR_VARIABLE error)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "msgcomm failed: ${error}")
endif()
if(EXISTS "${WORK}/shared.po")
  file(STRINGS "${WORK}/shared.po" shared ENCODING UTF-8 REGEX "^msgid \".+\"$")
  if(shared)
    list(JOIN shared "\n  " shared)
    message(FATAL_ERROR "messages in more than one file of engine/language/ko/ (keep each once, "
                        "in common.po when parts share it):\n  ${shared}")
  endif()
endif()
execute_process(COMMAND msgcat --use-first -o "${WORK}/ko.po" ${parts}
                RESULT_VARIABLE status ERROR_VARIABLE error)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "msgcat failed: ${error}")
endif()
execute_process(COMMAND msgcmp "${WORK}/ko.po" "${WORK}/lamina.pot"
                RESULT_VARIABLE status ERROR_VARIABLE error)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "engine/language/ko/ lacks messages of the sources (add them, translated):\n${error}")
endif()
execute_process(COMMAND msgfmt --check --statistics -o /dev/null "${WORK}/ko.po"
                RESULT_VARIABLE status ERROR_VARIABLE statistics)
if(NOT status EQUAL 0 OR statistics MATCHES "untranslated|fuzzy")
  message(FATAL_ERROR "engine/language/ko/: ${statistics}")
endif()
message(STATUS "catalogue_complete: ${count} messages of the sources, all in engine/language/ko/; ${statistics}")
