set datafile separator ','
set key below
set grid
set title 'u_n (mm), dilation positive against u_x'
set xlabel 'u_x (mm)'
set ylabel 'u_n (mm), dilation positive'

set terminal svg size 900,560 font 'sans,12' noenhanced background '#ffffff'
set output 'un_ux.svg'
plot 'un_ux.csv' using 1:2 skip 1 with lines lw 3 title 'DEM', 'un_ux.csv' using 1:3 skip 1 with lines lw 1.5 title 'kappa_r = 1.000 (eq. 5.35, R_n = 1), d_s = 5 d50', 'un_ux.csv' using 1:4 skip 1 with lines lw 1.5 title 'kappa_r = 1.000 (eq. 5.35, R_n = 1), d_s = 10 d50', 'un_ux.csv' using 1:5 skip 1 with lines lw 1.5 title 'fitted: kappa_r = 1.000 +- 0.004, d_s = 18.57 +- 0.50 mm (9.3 d50)'
set terminal pngcairo size 900,560 font 'sans,10' noenhanced
set output 'un_ux.png'
replot
unset output
