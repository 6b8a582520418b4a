# Time per step against the number of boxes, Lamina (pgs and islands), Box2D 2.4.1 and Box2D v3
# (when the benchmarks were built with it), log-log (docs/performance.md).
#   gnuplot -e "data='images/performance/scaling.csv'; output='images/performance/time_per_step.png'" \
#           tests/benchmarks/time_per_step.gp
# `data` is the benchmarks' scaling.csv: base, boxes, lamina_ms_per_step, box2d_ms_per_step, ...,
# islands_ms_per_step, box2d_v3_ms_per_step (NaN where not measured: skipped). Issue 19's two bars
# are drawn dashed beside the engine each is measured against: `pgs` at most 0.5 × Box2D 2.4.1's
# time, `islands` at most 1.5 × Box2D v3's.
set datafile separator ','
set terminal pngcairo size 640,420 font 'DejaVu Sans,10'
set output output
set logscale xy
set xlabel 'boxes in the pyramid'
set ylabel 'CPU time per step (ms)'
set title 'Pyramids of boxes, one thread each'
set key top left
set grid
set xrange [40:5000]
set yrange [0.04:20]
pgs = '#9400d3'; islands = '#009e73'; box2d = '#56b4e9'; v3 = '#e69f00'
plot data using 2:3 skip 1 with linespoints pointtype 7 lc rgb pgs \
          title 'Lamina pgs, 8 / 3 sweeps', \
     data using 2:9 skip 1 with linespoints pointtype 6 lc rgb islands \
          title 'Lamina islands, 10 / 3 sweeps', \
     data using 2:4 skip 1 with linespoints pointtype 5 lc rgb box2d \
          title 'Box2D 2.4.1, 8 / 3 iterations', \
     data using 2:10 skip 1 with linespoints pointtype 9 lc rgb v3 \
          title 'Box2D v3.1.1, 4 substeps', \
     data using 2:($4 * 0.5) skip 1 with lines dashtype 2 lw 1.5 lc rgb pgs \
          title 'bar for pgs: 0.5 × Box2D 2.4.1', \
     data using 2:($10 * 1.5) skip 1 with lines dashtype 2 lw 1.5 lc rgb islands \
          title 'bar for islands: 1.5 × Box2D v3'
