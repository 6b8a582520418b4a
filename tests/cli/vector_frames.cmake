# The vector frames of `lamina run` as a lecturer gets them (docs/slides.md): --format svg gives
# one well-formed SVG per frame, --format pdf --pdf-pages one PDF with a page per frame, its
# caption searchable.
#   cmake -DLAMINA=<lamina> -DOUT=<folder> -P vector_frames.cmake
file(REMOVE_RECURSE ${OUT})
# 30 steps, a frame every 10: frames of steps 0, 10, 20
execute_process(COMMAND ${LAMINA} run box-on-ground-tilted --steps 30 --every 10 --size 320x180
                        --frames ${OUT}/svg --format svg RESULT_VARIABLE code)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "lamina --format svg: exit code ${code}")
endif()
file(GLOB svgs ${OUT}/svg/*.svg)
list(LENGTH svgs count)
if(NOT count EQUAL 3)
  message(FATAL_ERROR "--format svg wrote ${count} SVG files, not 3")
endif()
foreach(svg IN LISTS svgs)
  execute_process(COMMAND xmllint --noout ${svg} RESULT_VARIABLE code)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "${svg} is not well-formed XML")
  endif()
endforeach()
execute_process(COMMAND ${LAMINA} run box-on-ground-tilted --steps 30 --every 10 --size 320x180
                        --frames ${OUT}/pdf --format pdf --pdf-pages RESULT_VARIABLE code)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "lamina --format pdf --pdf-pages: exit code ${code}")
endif()
execute_process(COMMAND pdfinfo ${OUT}/pdf/box-on-ground-tilted.pdf OUTPUT_VARIABLE info)
if(NOT info MATCHES "Pages: +3\n")
  message(FATAL_ERROR "the PDF should have 3 pages: ${info}")
endif()
execute_process(COMMAND pdftotext ${OUT}/pdf/box-on-ground-tilted.pdf - OUTPUT_VARIABLE text)
if(NOT text MATCHES "box-on-ground-tilted")
  message(FATAL_ERROR "the PDF's caption is not text: ${text}")
endif()
message(STATUS "3 SVG frames, well-formed; one PDF of 3 pages with its caption as text")
