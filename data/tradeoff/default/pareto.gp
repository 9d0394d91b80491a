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
set label 'base' at 168158933.33333334,0.025692550664871902 offset 0.6,0.6 font ',9'
set label 'boxx0.5' at 66824800,0.083158211514288 offset 0.6,0.6 font ',9'
set label 'kappax0.5' at 98705600,0.05180324939823586 offset 0.6,0.6 font ',9'
set label 'Ix2' at 148612800,0.0009897825778633872 offset 0.6,0.6 font ',9'
set label 'Ix0.5' at 181649600,0.07575379140484968 offset 0.6,0.6 font ',9'
set label 'kappax2' at 268412800,0.06355194811870875 offset 0.6,0.6 font ',9'
set label 'dtx0.5' at 332049600,0.006068324610068455 offset 0.6,0.6 font ',9'
set label 'boxx2' at 978451200,0.10219594415183075 offset 0.6,0.6 font ',9'
set xrange [3.34124e+07:2.93535e+09]

set terminal svg size 900,560 font 'sans,12' noenhanced background '#ffffff'
set output 'pareto.svg'
plot 'pareto.csv' using 1:2 skip 1 with points pt 5 ps 1.3 title 'peak_friction', 'pareto.csv' using 1:3 skip 1 with points pt 7 ps 1.3 title 'residual_friction', 'pareto.csv' using 1:4 skip 1 with points pt 9 ps 1.3 title 'dilation_rate', 'pareto.csv' using 1:5 skip 1 with points pt 11 ps 1.3 title 'band_thickness'
set terminal pngcairo size 900,560 font 'sans,10' noenhanced
set output 'pareto.png'
replot
unset output
