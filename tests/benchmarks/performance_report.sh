#!/bin/sh
# Runs the benchmarks and regenerates docs/performance.md's tables and plot from the run.
#   tests/benchmarks/performance_report.sh [build folder, default build]
# Writes images/performance/*.md, *.csv and time_per_step.png, and the tables in
# docs/performance.md between their "generated" markers. Run from the source folder.
set -eu
build=${1:-build}
out=images/performance
"$build/tests/benchmarks/lamina_benchmarks" --report="$out" --doc=docs/performance.md
gnuplot -e "data='$out/scaling.csv'; output='$out/time_per_step.png'" tests/benchmarks/time_per_step.gp
echo "performance_report: tables in $out and docs/performance.md, plot $out/time_per_step.png"
