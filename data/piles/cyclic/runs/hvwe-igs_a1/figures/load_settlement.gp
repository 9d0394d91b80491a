set datafile separator ','
set key below
set grid
set title 'Load-settlement (hvwe-igs)'
set xlabel 'head settlement (mm)'
set ylabel 'load (kN)'
set datafile missing 'nan'

set terminal svg size 900,560 font 'sans,12' noenhanced background '#ffffff'
set output 'load_settlement.svg'
plot 'load_settlement.csv' using 1:2 skip 1 with lines lw 2 title 'head', 'load_settlement.csv' using 3:4 skip 1 with lines lw 2 title 'shaft', 'load_settlement.csv' using 5:6 skip 1 with lines lw 2 title 'base'
set terminal pngcairo size 900,560 font 'sans,10' noenhanced
set output 'load_settlement.png'
replot
unset output
