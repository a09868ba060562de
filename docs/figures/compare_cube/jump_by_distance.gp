set terminal pngcairo size 720,480 font 'sans,10'
set output '.jump_by_distance.png.tmp'
set logscale xy
set format y '10^{%L}'
set yrange [1e-13:*]
set grid
set key bottom right
set xlabel 'distance from the extraordinary point along the boundary (parameter t)'
set ylabel 'largest normal jump (degrees)'
set title 'Normal jump across patch boundaries near extraordinary points'
plot 'jump_by_distance.dat' index 0 using 1:2 with linespoints title 'asc', 'jump_by_distance.dat' index 1 using 1:2 with linespoints title 'mdc', 'jump_by_distance.dat' index 2 using 1:2 with linespoints title 'cc'
