# The ctest catalogue_complete: every message the sources pass to tr() is in ko.po, translated.
#
#   cmake -DSOURCE=<source dir> -DWORK=<folder> -P check_catalogue.cmake
#
# xgettext (Debian's gettext) lists the sources' messages as a template, msgcmp fails on one that
# ko.po lacks, and msgfmt --statistics must count no untranslated or fuzzy entry.
cmake_minimum_required(VERSION 3.25)
file(GLOB_RECURSE sources RELATIVE "${SOURCE}" "${SOURCE}/engine/*.cpp" "${SOURCE}/engine/*.h"
     "${SOURCE}/tutorials/*.cpp" "${SOURCE}/tutorials/*.h")
list(SORT sources)
file(MAKE_DIRECTORY "${WORK}")
execute_process(COMMAND xgettext --language=C++ --keyword=tr --from-code=UTF-8 --no-location
                        -o "${WORK}/lamina.pot" ${sources}
                WORKING_DIRECTORY "${SOURCE}" RESULT_VARIABLE status ERROR_VARIABLE error)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "xgettext failed: ${error}")
endif()
if(NOT EXISTS "${WORK}/lamina.pot")
  message(FATAL_ERROR "xgettext found no tr(\"...\") in the sources")
endif()
file(STRINGS "${WORK}/lamina.pot" ids ENCODING UTF-8 REGEX "^msgid \".+\"$")
list(LENGTH ids count)
execute_process(COMMAND msgcmp "${SOURCE}/engine/language/ko.po" "${WORK}/lamina.pot"
                RESULT_VARIABLE status ERROR_VARIABLE error)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "ko.po lacks messages of the sources (add them, translated):\n${error}")
endif()
execute_process(COMMAND msgfmt --check --statistics -o /dev/null "${SOURCE}/engine/language/ko.po"
                RESULT_VARIABLE status ERROR_VARIABLE statistics)
if(NOT status EQUAL 0 OR statistics MATCHES "untranslated|fuzzy")
  message(FATAL_ERROR "ko.po: ${statistics}")
endif()
message(STATUS "catalogue_complete: ${count} messages of the sources, all in ko.po; ${statistics}")
