# The same soil cells of the default grains in LIGGGHTS and YADE (README.md beside).
# Redraw from this folder: gnuplot engines.gp
set datafile separator ","
set key bottom right
L = "../"
Y = "./"
do for [fmt in "svg png"] {
  if (fmt eq "svg") { set terminal svg size 1100,420 dynamic font "sans,12"; set output "engines.svg" }
  if (fmt eq "png") { set terminal pngcairo size 1100,420 font "sans,10"; set output "engines.png" }
  set multiplot layout 1,3
  set title "oedometer, dense: e against sigma_v"
  set logscale x
  set xrange [5:300]
  set xlabel "sigma_v (kPa)"
  set ylabel "e"
  plot L."oedometer-dense/timeseries.csv" skip 1 using 1:3 with linespoints pt 7 title "LIGGGHTS", \
       Y."oedometer-dense/timeseries.csv" skip 1 using 1:3 with linespoints pt 5 title "YADE"
  unset logscale x
  set autoscale x
  set title "simple shear CNL 50 kPa, loose: tau/sigma_n"
  set xlabel "gamma"
  set ylabel "tau / sigma_n"
  plot L."simpleshear-CNL-loose/timeseries.csv" skip 1 using 1:($2/$3) with lines lw 2 title "LIGGGHTS", \
       Y."simpleshear-CNL-loose/timeseries.csv" skip 1 using 1:($2/$3) with lines lw 2 title "YADE"
  set title "simple shear CNL 50 kPa, loose: e"
  set ylabel "e"
  plot L."simpleshear-CNL-loose/timeseries.csv" skip 1 using 1:4 with lines lw 2 title "LIGGGHTS", \
       Y."simpleshear-CNL-loose/timeseries.csv" skip 1 using 1:4 with lines lw 2 title "YADE"
  unset multiplot
  unset output
}
