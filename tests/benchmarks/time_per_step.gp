# Time per step against the number of boxes, Lamina and Box2D, log-log (docs/performance.md).
#   gnuplot -e "data='images/performance/scaling.csv'; output='images/performance/time_per_step.png'" \
#           tests/benchmarks/time_per_step.gp
# `data` is the benchmarks' scaling.csv: base, boxes, lamina_ms_per_step, box2d_ms_per_step, ...
set datafile separator ','
set terminal pngcairo size 640,420 font 'DejaVu Sans,10'
set output output
set logscale xy
set xlabel 'boxes in the pyramid'
set ylabel 'CPU time per step (ms)'
set title 'Pyramids of boxes, 8 velocity / 3 position sweeps'
set key top left
set grid
plot data using 2:3 skip 1 with linespoints pointtype 7 title 'Lamina', \
     data using 2:4 skip 1 with linespoints pointtype 5 title 'Box2D 2.4.1'
