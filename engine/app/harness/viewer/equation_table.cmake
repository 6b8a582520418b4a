# The statements of the text's equations as docs/the-text.md states them: the rows
# "| 3-16 | statement | cited in |" of its section "Every numbered equation" (the figures' table
# above it has rows of the same shape). One reader for the two that need them:
# embed_page.cmake puts them into the viewer's page, tests/language/check_catalogue.cmake lists
# them as messages of the catalogue (the viewer shows them in the run's language).
#
#   equation_statements(<the-text.md> <json> <calls>)
# sets <json> to a JSON object {"3-16": "statement", …} and <calls> to one JavaScript line
# t("statement"); per row, each statement escaped alike for both.
function(equation_statements text_file json_var calls_var)
  file(READ "${text_file}" text)
  string(FIND "${text}" "## Every numbered equation" first)
  string(FIND "${text}" "## Where the text is wrong" last)
  math(EXPR length "${last} - ${first}")
  string(SUBSTRING "${text}" ${first} ${length} text)
  string(REPLACE ";" "<semicolon>" text "${text}")
  string(REPLACE "\n" ";" lines "${text}")
  set(json "{")
  set(calls "")
  set(separator "")
  foreach(line IN LISTS lines)
    if(line MATCHES "^\\| ([1-5]-[0-9]+) \\| (.*) \\| [^|]*\\|$")
      set(number "${CMAKE_MATCH_1}")
      set(statement "${CMAKE_MATCH_2}")
      string(REPLACE "<semicolon>" ";" statement "${statement}")
      string(REPLACE "\\" "\\\\" statement "${statement}")
      string(REPLACE "\"" "\\\"" statement "${statement}")
      string(APPEND json "${separator}\"${number}\": \"${statement}\"")
      string(APPEND calls "t(\"${statement}\");\n")
      set(separator ",\n")
    endif()
  endforeach()
  string(APPEND json "}")
  set(${json_var} "${json}" PARENT_SCOPE)
  set(${calls_var} "${calls}" PARENT_SCOPE)
endfunction()
