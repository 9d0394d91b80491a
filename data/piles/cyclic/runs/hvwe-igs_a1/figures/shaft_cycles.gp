set datafile separator ','
set key below
set grid
set title 'The shaft over the cycles (hvwe-igs)'
set xlabel 'cycle N'
set ylabel 'ratio'
set datafile missing 'nan'

set terminal svg size 900,560 font 'sans,12' noenhanced background '#ffffff'
set output 'shaft_cycles.svg'
plot 'shaft_cycles.csv' using 1:2 skip 1 with linespoints lw 2 pt 7 title 'sigma_n / sigma_n0 at the cycle''s end', 'shaft_cycles.csv' using 3:4 skip 1 with linespoints lw 2 pt 5 title 'peak tau / sigma_n towards +A'
set terminal pngcairo size 900,560 font 'sans,10' noenhanced
set output 'shaft_cycles.png'
replot
unset output
