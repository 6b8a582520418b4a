# Time per step against the number of boxes, Lamina (pgs and islands), Box2D 2.4.1 and Box2D v3
# (when the benchmarks were built with it), log-log (docs/performance.md).
#   gnuplot -e "data='images/performance/scaling.csv'; output='images/performance/time_per_step.png'" \
#           tests/benchmarks/time_per_step.gp
# `data` is the benchmarks' scaling.csv: base, boxes, lamina_ms_per_step, box2d_ms_per_step, ...,
# islands_ms_per_step, box2d_v3_ms_per_step (NaN where not measured: skipped).
set datafile separator ','
set terminal pngcairo size 640,420 font 'DejaVu Sans,10'
set output output
set logscale xy
set xlabel 'boxes in the pyramid'
set ylabel 'CPU time per step (ms)'
set title 'Pyramids of boxes, one thread each'
set key top left
set grid
plot data using 2:3 skip 1 with linespoints pointtype 7 title 'Lamina pgs, 8 / 3 sweeps', \
     data using 2:9 skip 1 with linespoints pointtype 6 title 'Lamina islands, 10 / 3 sweeps', \
     data using 2:4 skip 1 with linespoints pointtype 5 title 'Box2D 2.4.1, 8 / 3 iterations', \
     data using 2:10 skip 1 with linespoints pointtype 9 title 'Box2D v3.1.1, 4 substeps'
