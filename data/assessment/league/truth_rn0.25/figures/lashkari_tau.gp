set datafile separator ','
set key below
set grid
set title 'lashkari: shear stress'
set xlabel 'u_x (mm)'
set ylabel 'tau (kPa)'
set datafile missing 'nan'

set terminal svg size 900,560 font 'sans,12' noenhanced background '#ffffff'
set output 'lashkari_tau.svg'
plot 'lashkari_tau.csv' using 1:2 skip 1 with lines lw 2 title 'DEM, seed mean', 'lashkari_tau.csv' using 3:4 skip 1 with lines lw 2 title 'lashkari, calibrated', 'lashkari_tau.csv' using 5:6 skip 1 with lines lw 2 title 'lashkari, 5 % of the parameter samples', 'lashkari_tau.csv' using 7:8 skip 1 with lines lw 2 title 'lashkari, 95 % of the parameter samples'
set terminal pngcairo size 900,560 font 'sans,10' noenhanced
set output 'lashkari_tau.png'
replot
unset output
