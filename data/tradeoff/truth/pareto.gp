set datafile separator ','
set key below
set grid
set title 'error against cost: data/scenes/truth.toml'
set xlabel 'cost, particle-steps'
set ylabel 'relative error against the reference'
set logscale xy
set format y '%g'
set arrow from graph 0, first 0.05 to graph 1, first 0.05 nohead dt 2
set arrow from graph 0, first 0.01 to graph 1, first 0.01 nohead dt 3
set label 'coarsened' at 72014080,0.049246194059264246 offset 0.6,0.6 font ',9'
set label 'boxx0.5' at 434819840,0.025775019094296105 offset 0.6,0.6 font ',9'
set label 'dtx2' at 554032640,0.09425318523045965 offset 0.6,0.6 font ',9'
set label 'kappax0.5' at 672000000,0.01678920394608771 offset 0.6,0.6 font ',9'
set label 'Ix2' at 727490560,0.031459371435947 offset 0.6,0.6 font ',9'
set xrange [3.6007e+07:2.18247e+09]

set terminal svg size 900,560 font 'sans,12' noenhanced background '#ffffff'
set output 'pareto.svg'
plot 'pareto.csv' using 1:2 skip 1 with points pt 5 ps 1.3 title 'peak_friction', 'pareto.csv' using 1:3 skip 1 with points pt 7 ps 1.3 title 'residual_friction', 'pareto.csv' using 1:4 skip 1 with points pt 9 ps 1.3 title 'dilation_rate', 'pareto.csv' using 1:5 skip 1 with points pt 11 ps 1.3 title 'total_dilation', 'pareto.csv' using 1:6 skip 1 with points pt 13 ps 1.3 title 'band_thickness'
set terminal pngcairo size 900,560 font 'sans,10' noenhanced
set output 'pareto.png'
replot
unset output
