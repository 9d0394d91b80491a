set datafile separator ','
set key below
set grid
set title 'hvwe-rd: free normal quantity (u_n in mm, or sigma_n in kPa under CV)'
set xlabel 'u_x (mm)'
set ylabel 'change from the start'
set datafile missing 'nan'

set terminal svg size 900,560 font 'sans,12' noenhanced background '#ffffff'
set output 'hvwe-rd_normal.svg'
plot 'hvwe-rd_normal.csv' using 1:2 skip 1 with lines lw 2 title 'DEM, seed mean', 'hvwe-rd_normal.csv' using 3:4 skip 1 with lines lw 2 title 'hvwe-rd, calibrated'
set terminal pngcairo size 900,560 font 'sans,10' noenhanced
set output 'hvwe-rd_normal.png'
replot
unset output
