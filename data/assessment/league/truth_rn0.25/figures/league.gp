set datafile separator ','
set key below
set grid
set title 'Uncertainties per model (ranked)'
set xlabel 'model'
set ylabel 'uncertainty'
set style data histograms
set style histogram clustered
set style fill solid 0.8
set xtics ('lashkari' 0, 'hvwe-pg' 1, 'hvwe-rd' 2, 'hp1d' 3, 'hvwe-igs' 4, 'hvwe' 5, 'mc' 6, 'ahe' 7, 'ah' 8, 'ahe-igs' 9, 'hyperbolic' 10, 'mortara' 11) rotate by -30
set logscale y

set terminal svg size 900,560 font 'sans,12' noenhanced background '#ffffff'
set output 'league.svg'
plot 'league.csv' using 2 skip 1 title 'UA_model shear', '' using 3 skip 1 title 'UA_model normal', '' using 4 skip 1 title 'UA_par', '' using 5 skip 1 title 'global'
set terminal pngcairo size 900,560 font 'sans,10' noenhanced
set output 'league.png'
replot
unset output
