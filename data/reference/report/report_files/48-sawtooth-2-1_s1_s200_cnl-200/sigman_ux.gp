set datafile separator ','
set key below
set grid
set title 'sigma_n (kPa) against u_x'
set xlabel 'u_x (mm)'
set ylabel 'sigma_n (kPa)'

set terminal svg size 900,560 font 'sans,12' noenhanced background '#ffffff'
set output 'sigman_ux.svg'
plot 'sigman_ux.csv' using 1:6:7 skip 1 with filledcurves fc rgb '#d8d8d8' fs solid 0.6 title 'DEM, mean ± SD over seeds', 'sigman_ux.csv' using 1:3 skip 1 with lines lw 1.5 title 'predicted: kappa_r = 1.000 (eq. 5.35, R_n = 1), d_s = 5 d50', 'sigman_ux.csv' using 1:4 skip 1 with lines lw 1.5 title 'fitted to tau alone: kappa_r = 0.997 +- 0.002, d_s = 18.95 +- 0.30 mm (9.5 d50)', 'sigman_ux.csv' using 1:5 skip 1 with lines lw 1.5 title 'fitted to tau and u_n: kappa_r = 1.000 +- 0.005, d_s = 16.45 +- 0.58 mm (8.2 d50)', 'sigman_ux.csv' using 1:2 skip 1 with lines lw 3 lc rgb '#000000' title 'DEM (this run)'
set terminal pngcairo size 900,560 font 'sans,10' noenhanced
set output 'sigman_ux.png'
replot
unset output
