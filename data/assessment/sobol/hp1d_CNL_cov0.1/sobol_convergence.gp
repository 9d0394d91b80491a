set datafile separator ','
set key below
set grid
set title 'hp1d: total Sobol indices of peak_friction against N'
set xlabel 'N, the base sample size'
set ylabel 'S_T'
set datafile missing 'nan'
set logscale x

set terminal svg size 900,560 font 'sans,12' noenhanced background '#ffffff'
set output 'sobol_convergence.svg'
plot 'sobol_convergence.csv' using 1:2 skip 1 with lines lw 2 title 'phi_c_deg', 'sobol_convergence.csv' using 3:4 skip 1 with lines lw 2 title 'hs_kPa', 'sobol_convergence.csv' using 5:6 skip 1 with lines lw 2 title 'n', 'sobol_convergence.csv' using 7:8 skip 1 with lines lw 2 title 'ec0', 'sobol_convergence.csv' using 9:10 skip 1 with lines lw 2 title 'alpha', 'sobol_convergence.csv' using 11:12 skip 1 with lines lw 2 title 'beta'
set terminal pngcairo size 900,560 font 'sans,10' noenhanced
set output 'sobol_convergence.png'
replot
unset output
