set datafile separator ','
set key below
set grid
set title 'DEM velocity profile (last window)'
set xlabel 'vx / v_wall'
set ylabel 'z / d50'
set xrange [-0.1:1.1]
set arrow from -0.1,8.55 to 1.1,8.55 nohead dt 2 lw 2 lc rgb '#cc0000'
set label 'wall band' at 0.02,8.55 offset 0,0.7 tc rgb '#cc0000'
set arrow from -0.1,12.550000000000004 to 1.1,12.550000000000004 nohead dt 3 lw 2 lc rgb '#0055cc'
set label 'plate band' at 0.75,12.550000000000004 offset 0,0.7 tc rgb '#0055cc'

set terminal svg size 900,560 font 'sans,12' noenhanced background '#ffffff'
set output 'velocity_profile.svg'
plot 'velocity_profile.csv' using 1:2 skip 1 with lines lw 3 title 'u_x = 4.41 mm'
set terminal pngcairo size 900,560 font 'sans,10' noenhanced
set output 'velocity_profile.png'
replot
unset output
