set datafile separator ','
set key below
set grid
set title 'error against cost: data/scenes/default.toml'
set xlabel 'cost, particle-steps'
set ylabel 'relative error against the reference'
set logscale xy
set format y '%g'
set arrow from graph 0, first 0.05 to graph 1, first 0.05 nohead dt 2
set arrow from graph 0, first 0.01 to graph 1, first 0.01 nohead dt 3
set label 'base' at 170352533.33333334,0.02347746139713642 offset 0.6,0.6 font ',9'
set label 'boxx0.5' at 67373600,0.09276727403088758 offset 0.6,0.6 font ',9'
set label 'kappax0.5' at 100550400,0.05099139480036987 offset 0.6,0.6 font ',9'
set label 'Ix2' at 150806400,0.009041216036526254 offset 0.6,0.6 font ',9'
set label 'Ix0.5' at 183843200,0.07556950678760785 offset 0.6,0.6 font ',9'
set label 'kappax2' at 271022400,0.06934933964114168 offset 0.6,0.6 font ',9'
set label 'dtx0.5' at 336436800,0.008844498532634934 offset 0.6,0.6 font ',9'
set label 'boxx2' at 996000000,0.10373306670592065 offset 0.6,0.6 font ',9'
set xrange [3.36868e+07:2.988e+09]

set terminal svg size 900,560 font 'sans,12' noenhanced background '#ffffff'
set output 'pareto.svg'
plot 'pareto.csv' using 1:2 skip 1 with points pt 5 ps 1.3 title 'peak_friction', 'pareto.csv' using 1:3 skip 1 with points pt 7 ps 1.3 title 'residual_friction', 'pareto.csv' using 1:4 skip 1 with points pt 9 ps 1.3 title 'dilation_rate', 'pareto.csv' using 1:5 skip 1 with points pt 11 ps 1.3 title 'total_dilation', 'pareto.csv' using 1:6 skip 1 with points pt 13 ps 1.3 title 'band_thickness'
set terminal pngcairo size 900,560 font 'sans,10' noenhanced
set output 'pareto.png'
replot
unset output
