set datafile separator ','
set key below
set grid
set title 'lashkari: total Sobol indices of peak_friction against N'
set xlabel 'N, the base sample size'
set ylabel 'S_T'
set datafile missing 'nan'
set logscale x

set terminal svg size 900,560 font 'sans,12' noenhanced background '#ffffff'
set output 'sobol_convergence.svg'
plot 'sobol_convergence.csv' using 1:2 skip 1 with lines lw 2 title 'K_s0_kPa', 'sobol_convergence.csv' using 3:4 skip 1 with lines lw 2 title 'K_n0_kPa', 'sobol_convergence.csv' using 5:6 skip 1 with lines lw 2 title 'A0', 'sobol_convergence.csv' using 7:8 skip 1 with lines lw 2 title 'A1', 'sobol_convergence.csv' using 9:10 skip 1 with lines lw 2 title 'h0', 'sobol_convergence.csv' using 11:12 skip 1 with lines lw 2 title 'M', 'sobol_convergence.csv' using 13:14 skip 1 with lines lw 2 title 'e_c0', 'sobol_convergence.csv' using 15:16 skip 1 with lines lw 2 title 'lambda', 'sobol_convergence.csv' using 17:18 skip 1 with lines lw 2 title 'n_b', 'sobol_convergence.csv' using 19:20 skip 1 with lines lw 2 title 'n_d', 'sobol_convergence.csv' using 21:22 skip 1 with lines lw 2 title 'p_ref_kPa'
set terminal pngcairo size 900,560 font 'sans,10' noenhanced
set output 'sobol_convergence.png'
replot
unset output
