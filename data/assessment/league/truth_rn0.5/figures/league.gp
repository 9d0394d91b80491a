set datafile separator ','
set key below
set grid
set title 'Uncertainties per model (ranked)'
set xlabel 'model'
set ylabel 'uncertainty'
set style data histograms
set style histogram clustered
set style fill solid 0.8
set xtics ('lashkari' 0, 'hp1d' 1, 'hvwe-igs' 2, 'hvwe' 3, 'ahe' 4, 'ah' 5, 'ahe-igs' 6, 'mc' 7, 'hyperbolic' 8, 'mortara' 9) rotate by -30
set logscale y

set terminal svg size 900,560 font 'sans,12' noenhanced background '#ffffff'
set output 'league.svg'
plot 'league.csv' using 2 skip 1 title 'UA_model shear', '' using 3 skip 1 title 'UA_model normal', '' using 4 skip 1 title 'UA_par', '' using 5 skip 1 title 'global'
set terminal pngcairo size 900,560 font 'sans,10' noenhanced
set output 'league.png'
replot
unset output
