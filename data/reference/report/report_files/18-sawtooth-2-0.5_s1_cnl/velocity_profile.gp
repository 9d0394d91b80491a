set datafile separator ','
set key below
set grid
set title 'DEM velocity profile (last window)'
set xlabel 'vx / v_wall'
set ylabel 'z / d50'
set xrange [-0.1:1.1]

set terminal svg size 900,560 font 'sans,12' noenhanced background '#ffffff'
set output 'velocity_profile.svg'
plot 'velocity_profile.csv' using 1:2 skip 1 with lines lw 3 title 'u_x = 3.99 mm'
set terminal pngcairo size 900,560 font 'sans,10' noenhanced
set output 'velocity_profile.png'
replot
unset output
