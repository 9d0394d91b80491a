set datafile separator ','
set key below
set grid
set title 'Uncertainties per model (ranked)'
set xlabel 'model'
set ylabel 'uncertainty'
set style data histograms
set style histogram clustered
set style fill solid 0.8
set xtics ('hvwe-rd' 0, 'lashkari' 1, 'hvwe-pg' 2, 'hp1d' 3, 'hvwe-igs' 4, 'hvwe' 5, 'ahe' 6, 'ah' 7, 'ahe-igs' 8, 'mc' 9, 'hyperbolic' 10, 'mortara' 11) rotate by -30
set logscale y

set terminal svg size 900,560 font 'sans,12' noenhanced background '#ffffff'
set output 'league.svg'
plot 'league.csv' using 2 skip 1 title 'UA_model shear', '' using 3 skip 1 title 'UA_model normal', '' using 4 skip 1 title 'UA_par', '' using 5 skip 1 title 'global'
set terminal pngcairo size 900,560 font 'sans,10' noenhanced
set output 'league.png'
replot
unset output
