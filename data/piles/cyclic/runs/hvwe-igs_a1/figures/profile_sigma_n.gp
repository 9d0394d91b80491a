set datafile separator ','
set key below
set grid
set title 'normal stress sigma_n (kPa) along the shaft (hvwe-igs)'
set xlabel 'normal stress sigma_n (kPa)'
set ylabel 'depth below the head (m, negative)'
set datafile missing 'nan'

set terminal svg size 900,560 font 'sans,12' noenhanced background '#ffffff'
set output 'profile_sigma_n.svg'
plot 'profile_sigma_n.csv' using 1:2 skip 1 with lines lw 2 title '2188.24 kN'
set terminal pngcairo size 900,560 font 'sans,10' noenhanced
set output 'profile_sigma_n.png'
replot
unset output
