set datafile separator ','
set key below
set grid
set title 'calibration front: dilatancy against oedometer'
set xlabel 'oedometer RMS (scatter units)'
set ylabel 'dilatancy RMS (scatter units)'
set label '0.0038' at 1.7251066475040293,6.308651758341525 offset 0.8,0.5 font ',9'
set label '0.059' at 1.723818389402432,6.31686932416559 offset 0.8,0.5 font ',9'
set label '0.94' at 1.7225584171965767,6.327980217780277 offset 0.8,0.5 font ',9'
set label '3.8' at 1.7032492731356519,6.432838668049138 offset 0.8,0.5 font ',9'
set label '15' at 1.7027853727004365,6.411670065271168 offset 0.8,0.5 font ',9'
set label '2.4e+02' at 1.6945411444304175,6.357884807268955 offset 0.8,0.5 font ',9'
set label '3.7e+03' at 1.6957920042089814,6.281776302818078 offset 0.8,0.5 font ',9'

set terminal svg size 900,560 font 'sans,12' noenhanced background '#ffffff'
set output 'pareto.svg'
plot 'pareto.csv' using 4:6 skip 1 with linespoints pt 7 lw 2 title 'optimum at the weight ratio oedometer:dilatancy (labels)', 'pareto.csv' using 4:($8 > 0 ? $6 : 1/0) skip 1 with points pt 6 ps 2.5 lw 2 title 'the given weights'
set terminal pngcairo size 900,560 font 'sans,10' noenhanced
set output 'pareto.png'
replot
unset output
