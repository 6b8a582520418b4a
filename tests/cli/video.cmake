# `lamina run --video` as a lecturer gets it (docs/slides.md): MP4, WebM and GIF decoded back by
# ffprobe and ffmpeg (Debian's ffmpeg, not Lamina's code) — frame count, size and rate as asked,
# and the first decoded frame against the first PNG frame of the same run by PSNR.
#   cmake -DLAMINA=<lamina> -DOUT=<folder> -P video.cmake
# Tolerances (PSNR over RGB, dB): measured 42.7 (MP4, H.264 at CRF 18, 4:2:0 colour), 43.6
# (WebM, VP9 at CRF 30) and 80.0 (GIF, the clip's own palette, no dithering); two neighbouring
# frames of this run (3 steps apart) are 31 dB apart, so 38 dB tells the first frame from the
# second for the lossy two, and 60 dB asks the GIF's palette to keep the colours clean.
file(REMOVE_RECURSE ${OUT})
# 90 steps, a frame every 3: 30 frames, 1 s at 30 frames/s (one at 25 for the rate)
foreach(case mp4:38:30 webm:38:30 gif:60:25)
  string(REPLACE ":" ";" parts ${case})
  list(GET parts 0 ext)
  list(GET parts 1 psnr_bound)
  list(GET parts 2 fps)
  execute_process(COMMAND ${LAMINA} run box-on-ground-tilted --steps 90 --every 3 --size 640x360
                          --frames ${OUT}/${ext} --video ${OUT}/drop.${ext} --fps ${fps}
                  RESULT_VARIABLE code ERROR_VARIABLE error)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "lamina --video drop.${ext}: exit code ${code}: ${error}")
  endif()
  execute_process(COMMAND ffprobe -v error -count_frames -select_streams v:0
                          -show_entries stream=nb_read_frames,width,height,r_frame_rate -of csv=p=0
                          ${OUT}/drop.${ext}
                  OUTPUT_VARIABLE probe OUTPUT_STRIP_TRAILING_WHITESPACE)
  string(REPLACE "," ";" probe_fields "${probe}")
  list(GET probe_fields 0 width)
  list(GET probe_fields 1 height)
  list(GET probe_fields 2 rate)
  list(GET probe_fields 3 frames)
  if(NOT width EQUAL 640 OR NOT height EQUAL 360 OR NOT frames EQUAL 30)
    message(FATAL_ERROR "drop.${ext}: ${width}x${height}, ${frames} frames; asked 640x360, 30 frames")
  endif()
  # GIF keeps a frame's delay in hundredths of a second: 1/25 s exactly, 1/30 s not
  if(NOT rate STREQUAL "${fps}/1")
    message(FATAL_ERROR "drop.${ext}: ${rate} frames/s, asked ${fps}")
  endif()
  execute_process(COMMAND ffmpeg -hide_banner -i ${OUT}/drop.${ext} -i ${OUT}/${ext}/box-on-ground-tilted_0000.png
                          -lavfi "[0:v]trim=end_frame=1,format=rgb24[a];[1:v]format=rgb24[b];[a][b]psnr"
                          -f null -
                  ERROR_VARIABLE log)
  if(NOT log MATCHES "average:([0-9.]+|inf)")
    message(FATAL_ERROR "drop.${ext}: no PSNR from ffmpeg: ${log}")
  endif()
  set(psnr ${CMAKE_MATCH_1})
  if(NOT psnr STREQUAL "inf" AND psnr LESS ${psnr_bound})
    message(FATAL_ERROR "drop.${ext}: the first frame is ${psnr} dB from the first PNG (at least ${psnr_bound})")
  endif()
  message(STATUS "drop.${ext}: ${width}x${height}, ${frames} frames at ${rate}/s, first frame ${psnr} dB from the PNG")
endforeach()
