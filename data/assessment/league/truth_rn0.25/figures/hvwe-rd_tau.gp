set datafile separator ','
set key below
set grid
set title 'hvwe-rd: shear stress'
set xlabel 'u_x (mm)'
set ylabel 'tau (kPa)'
set datafile missing 'nan'

set terminal svg size 900,560 font 'sans,12' noenhanced background '#ffffff'
set output 'hvwe-rd_tau.svg'
plot 'hvwe-rd_tau.csv' using 1:2 skip 1 with lines lw 2 title 'DEM, seed mean', 'hvwe-rd_tau.csv' using 3:4 skip 1 with lines lw 2 title 'hvwe-rd, calibrated', 'hvwe-rd_tau.csv' using 5:6 skip 1 with lines lw 2 title 'hvwe-rd, 5 % of the parameter samples', 'hvwe-rd_tau.csv' using 7:8 skip 1 with lines lw 2 title 'hvwe-rd, 95 % of the parameter samples'
set terminal pngcairo size 900,560 font 'sans,10' noenhanced
set output 'hvwe-rd_tau.png'
replot
unset output
