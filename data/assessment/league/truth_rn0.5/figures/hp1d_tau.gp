set datafile separator ','
set key below
set grid
set title 'hp1d: shear stress'
set xlabel 'u_x (mm)'
set ylabel 'tau (kPa)'
set datafile missing 'nan'

set terminal svg size 900,560 font 'sans,12' noenhanced background '#ffffff'
set output 'hp1d_tau.svg'
plot 'hp1d_tau.csv' using 1:2 skip 1 with lines lw 2 title 'DEM, seed mean', 'hp1d_tau.csv' using 3:4 skip 1 with lines lw 2 title 'hp1d, calibrated', 'hp1d_tau.csv' using 5:6 skip 1 with lines lw 2 title 'hp1d, 5 % of the parameter samples', 'hp1d_tau.csv' using 7:8 skip 1 with lines lw 2 title 'hp1d, 95 % of the parameter samples'
set terminal pngcairo size 900,560 font 'sans,10' noenhanced
set output 'hp1d_tau.png'
replot
unset output
