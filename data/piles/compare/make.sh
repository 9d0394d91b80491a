#!/usr/bin/env bash
# Models compared on one pile (issue 22 item 4; README.md here): every file of this folder through
# `iwb pile` into runs/<name>/ (committed: the whole run directory, ~0.4 MB each), then the
# comparison figures into figures/. Run from the repository root after building:
#   data/piles/compare/make.sh
set -euo pipefail
IWB=${IWB:-build/iwb}
here=data/piles/compare
for f in "$here"/*.toml; do
  name=$(basename "$f" .toml)
  "$IWB" pile "$f" -o "$here/runs/$name" --force
done
mkdir -p "$here/figures"
/usr/bin/python3 "$here/ratcheting.py" "$here/runs" > "$here/figures/ratcheting.csv"
gnuplot <<GP
set datafile separator ','
set terminal pngcairo size 900,560 font ',11'
set key bottom right; set grid
set output '$here/figures/load_settlement.png'
set title 'One pile, three interface models (10 m, D 0.6 m, K = 4G/D)'
set xlabel 'head settlement (mm)'; set ylabel 'head load (kN)'
plot '$here/runs/hvwe_eq535/load_settlement.csv' every ::1 u 2:3 w l lw 2 t 'hvwe, kappa_r 0.899 (eq. 5.35), d_s 10 mm', \
     '$here/runs/hvwe_dem_fit/load_settlement.csv' every ::1 u 2:3 w l lw 2 t 'hvwe, kappa_r 1.0, d_s 18.1 mm (DEM fit)', \
     '$here/runs/mc/load_settlement.csv' every ::1 u 2:3 w l lw 2 t 'Mohr-Coulomb (Table 4.3)'
set output '$here/figures/ratcheting.png'
set title 'Cyclic head load 250 +- 150 kN: settlement at the mean load after each cycle'
set xlabel 'cycle'; set ylabel 'head settlement (mm)'; set key top left
plot '$here/figures/ratcheting.csv' every ::1 u 1:2 w lp lw 2 t 'hvwe', '' every ::1 u 1:3 w lp lw 2 t 'hvwe-igs'
GP
echo "make.sh: runs in $here/runs, figures in $here/figures"
