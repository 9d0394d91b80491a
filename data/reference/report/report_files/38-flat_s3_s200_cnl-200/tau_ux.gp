set datafile separator ','
set key below
set grid
set title 'tau (kPa) against u_x'
set xlabel 'u_x (mm)'
set ylabel 'tau (kPa)'

set terminal svg size 900,560 font 'sans,12' noenhanced background '#ffffff'
set output 'tau_ux.svg'
plot 'tau_ux.csv' using 1:6:7 skip 1 with filledcurves fc rgb '#d8d8d8' fs solid 0.6 title 'DEM, mean ± SD over seeds', 'tau_ux.csv' using 1:3 skip 1 with lines lw 1.5 title 'predicted: kappa_r = 0.05 (flat wall: eq. 5.35''s floor), d_s = 5 d50', 'tau_ux.csv' using 1:4 skip 1 with lines lw 1.5 title 'fitted to tau alone: kappa_r = 0.738 +- 0.002, d_s = 4.33 +- 0.09 mm (2.2 d50)', 'tau_ux.csv' using 1:5 skip 1 with lines lw 1.5 title 'fitted to tau and u_n: kappa_r = 0.852 +- 0.006, d_s = 7.26 +- 0.34 mm (3.6 d50)', 'tau_ux.csv' using 1:2 skip 1 with lines lw 3 lc rgb '#000000' title 'DEM (this run)'
set terminal pngcairo size 900,560 font 'sans,10' noenhanced
set output 'tau_ux.png'
replot
unset output
