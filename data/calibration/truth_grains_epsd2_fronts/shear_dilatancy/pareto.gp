set datafile separator ','
set key below
set grid
set title 'calibration front: dilatancy against shear'
set xlabel 'shear RMS (scatter units)'
set ylabel 'dilatancy RMS (scatter units)'
set label '0.004' at 8.953176483789878,3.865892145873937 offset 0.8,0.5 font ',9'
set label '0.04' at 6.61081114664697,3.95800136473336 offset 0.8,0.5 font ',9'
set label '0.4' at 2.1345635360709903,4.375477866484397 offset 0.8,0.5 font ',9'
set label '4' at 1.710518983432333,4.711839190915199 offset 0.8,0.5 font ',9'
set label '40' at 1.6913677600074686,4.756023146720081 offset 0.8,0.5 font ',9'
set label '4e+02' at 1.685858881715121,4.827499594225035 offset 0.8,0.5 font ',9'
set label '4e+03' at 1.685856324833609,4.82749760933836 offset 0.8,0.5 font ',9'

set terminal svg size 900,560 font 'sans,12' noenhanced background '#ffffff'
set output 'pareto.svg'
plot 'pareto.csv' using 5:6 skip 1 with linespoints pt 7 lw 2 title 'optimum at the weight ratio shear:dilatancy (labels)', 'pareto.csv' using 5:($8 > 0 ? $6 : 1/0) skip 1 with points pt 6 ps 2.5 lw 2 title 'the given weights'
set terminal pngcairo size 900,560 font 'sans,10' noenhanced
set output 'pareto.png'
replot
unset output
