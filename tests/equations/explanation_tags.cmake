# Runs every explanation a reader can print — each tutorial's `--explain 2` and `lamina run
# SCENE --explain 40` for scenes with contacts and joints, by both solvers — as JSON into OUT,
# then `equation_links --tags` checks that every equation tag names an equation of
# docs/the-text.md.
#   cmake -DCHECKER=… -DSOURCE=… -DOUT=… -DTUTORIALS="a;b" -DLAMINA=… -P explanation_tags.cmake
file(MAKE_DIRECTORY "${OUT}")
set(files "")
foreach(program IN LISTS TUTORIALS)
  get_filename_component(name "${program}" NAME)
  set(commands_${name} "${program};--explain;2;--explain-format;json")
  list(APPEND runs ${name})
endforeach()
foreach(scene IN ITEMS box-on-ground-tilted pendulum chain bridge angle-limit incline-constraint)
  foreach(solver IN ITEMS text pgs)
    set(name "lamina_${scene}_${solver}")
    set(commands_${name} "${LAMINA};run;${scene};--solver;${solver};--explain;40;--explain-format;json")
    list(APPEND runs ${name})
  endforeach()
endforeach()
foreach(name IN LISTS runs)
  execute_process(COMMAND ${commands_${name}} OUTPUT_FILE "${OUT}/${name}.json"
                  RESULT_VARIABLE result)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "${name}: the explanation failed (${result})")
  endif()
  list(APPEND files "${OUT}/${name}.json")
endforeach()
execute_process(COMMAND "${CHECKER}" --tags "${SOURCE}" ${files} RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "an explanation cites an equation the text does not have (above)")
endif()
