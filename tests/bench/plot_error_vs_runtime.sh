#!/bin/sh
# Log-log plot of error against wall time from the CSV that bench_error_vs_runtime writes.
# Needs gnuplot (Debian gnuplot-nox), a benchmark-only tool.
#   sh tests/bench/plot_error_vs_runtime.sh [in.csv] [out.png]
set -e
here=$(cd "$(dirname "$0")" && pwd)
csv=${1:-$here/results/error_vs_runtime.csv}
png=${2:-$here/results/error_vs_runtime.png}
gnuplot <<EOF
set datafile separator ","
set terminal pngcairo size 2100,650 font "sans,11"
set output "$png"
set logscale xy
set format y "10^{%L}"
set grid
set key below
set multiplot layout 1,3
# Columns: 1 problem, 2 contact, 3 model, 11 wall_s, 12 stable, 13 error (relative),
# 15 peak_force_err, 16 duration_err, 24 element (tet4, tet10, tet10c: composite).
sel(p, c, m) = strcol(1) eq p && (c eq "" || strcol(2) eq c) && (m eq "" || strcol(3) eq m) && \$12 == 1 && strcol(24) eq "tet4"
sel10(p, c, m) = strcol(1) eq p && (c eq "" || strcol(2) eq c) && (m eq "" || strcol(3) eq m) && \$12 == 1 && strcol(24) eq "tet10"
sel10c(p, c, m) = strcol(1) eq p && (c eq "" || strcol(2) eq c) && (m eq "" || strcol(3) eq m) && \$12 == 1 && strcol(24) eq "tet10c"
set title "Two-bar impact (nu = 0): impulse error against the 1-D solution"
set xlabel "wall time (s)"
set ylabel "|impulse error| (%)"
set arrow 1 from graph 0, first 0.5 to graph 1, first 0.5 nohead dt 2 lc rgb "black"
set arrow 2 from first 1, graph 0 to first 1, graph 1 nohead dt 2 lc rgb "black"
set label 1 "target: 0.5 % within 1 s" at graph 0.02, first 0.44 left
plot "$csv" skip 1 using (sel("two_bar", "multipliers", "paper") ? \$11 : NaN):(abs(\$13) * 100) with points pt 7 ps 1.2 title "multipliers, paper", \
     "" skip 1 using (sel("two_bar", "multipliers", "linear") ? \$11 : NaN):(abs(\$13) * 100) with points pt 5 ps 1.1 title "multipliers, linear", \
     "" skip 1 using (sel("two_bar", "multipliers", "corotational") ? \$11 : NaN):(abs(\$13) * 100) with points pt 9 ps 1.3 title "multipliers, corotational", \
     "" skip 1 using (sel("two_bar", "multipliers", "neo_hookean") ? \$11 : NaN):(abs(\$13) * 100) with points pt 13 ps 1.3 title "multipliers, neo-Hookean", \
     "" skip 1 using (sel("two_bar", "penalty_k1x", "") ? \$11 : NaN):(abs(\$13) * 100) with points pt 2 ps 1.5 lw 2 title "penalty baseline, k = 1x", \
     "" skip 1 using (sel("two_bar", "penalty_k10x", "") ? \$11 : NaN):(abs(\$13) * 100) with points pt 3 ps 1.5 lw 2 title "penalty baseline, k = 10x", \
     "" skip 1 using (sel("two_bar", "penalty_k100x", "") ? \$11 : NaN):(abs(\$13) * 100) with points pt 1 ps 1.5 lw 2 title "penalty baseline, k = 100x", \
     "" skip 1 using (sel10("two_bar", "multipliers", "") ? \$11 : NaN):(abs(\$13) * 100) with points pt 6 ps 1.8 lw 2 title "multipliers, paper, 10-node tets", \
     "" skip 1 using (sel10c("two_bar", "multipliers", "") ? \$11 : NaN):(abs(\$13) * 100) with points pt 12 ps 1.8 lw 2 title "multipliers, paper, 10-node composite tets"
unset arrow 1
unset arrow 2
unset label 1
set title "Spinning body, cantilever, incline: main error against the closed form"
set ylabel "|error| (%)"
plot "$csv" skip 1 using (sel("spin", "", "") ? \$11 : NaN):(abs(\$13) * 100) with points pt 7 ps 1.1 title "spin: largest of angular momentum, kinetic energy, volume", \
     "" skip 1 using (sel("cantilever", "", "") ? \$11 : NaN):(abs(\$13) * 100) with points pt 5 ps 1.1 title "cantilever: tip deflection", \
     "" skip 1 using (sel("incline", "", "") ? \$11 : NaN):(abs(\$13) * 100) with points pt 9 ps 1.3 title "incline: acceleration", \
     "" skip 1 using (sel10("cantilever", "", "corotational") ? \$11 : NaN):(abs(\$13) * 100) with linespoints pt 4 ps 1.6 lw 2 title "cantilever, 10-node tets (corotational)", \
     "" skip 1 using (sel10("spin", "", "") ? \$11 : NaN):(abs(\$13) * 100) with points pt 6 ps 1.4 title "spin, 10-node tets", \
     "" skip 1 using (sel10("incline", "", "") ? \$11 : NaN):(abs(\$13) * 100) with points pt 8 ps 1.4 title "incline, 10-node tets", \
     "" skip 1 using (sel10c("cantilever", "", "corotational") ? \$11 : NaN):(abs(\$13) * 100) with linespoints pt 12 ps 1.6 lw 2 title "cantilever, 10-node composite tets (corotational)"
set title "Hertz impact (Gmsh sphere, rigid plane): larger of peak force and contact time errors"
set arrow 3 from graph 0, first 5 to graph 1, first 5 nohead dt 2 lc rgb "black"
set arrow 4 from first 10, graph 0 to first 10, graph 1 nohead dt 2 lc rgb "black"
set label 3 "target: 5 % within 10 s" at graph 0.02, first 5.6 left
plot "$csv" skip 1 using (sel("hertz", "", "") ? \$11 : NaN):(abs(\$13) * 100) with linespoints pt 5 ps 1.3 title "1 m/s, 4-node tets", \
     "" skip 1 using (sel10("hertz", "", "") ? \$11 : NaN):(abs(\$13) * 100) with linespoints pt 4 ps 1.6 lw 2 title "1 m/s, 10-node tets", \
     "" skip 1 using (sel("hertz_10", "", "") ? \$11 : NaN):(abs(\$13) * 100) with linespoints pt 7 ps 1.3 title "10 m/s, 4-node tets", \
     "" skip 1 using (sel10("hertz_10", "", "") ? \$11 : NaN):(abs(\$13) * 100) with linespoints pt 6 ps 1.6 lw 2 title "10 m/s, 10-node tets", \
     "" skip 1 using (sel10c("hertz", "", "") ? \$11 : NaN):(abs(\$13) * 100) with linespoints pt 12 ps 1.6 lw 2 title "1 m/s, 10-node composite tets", \
     "" skip 1 using (sel10c("hertz_10", "", "") ? \$11 : NaN):(abs(\$13) * 100) with linespoints pt 13 ps 1.6 lw 2 title "10 m/s, 10-node composite tets"
unset multiplot
EOF
echo "wrote $png"
