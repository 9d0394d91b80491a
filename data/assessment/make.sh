#!/usr/bin/env bash
# The sensitivity tables of data/assessment/ (README.md here): total Sobol indices of the reference
# interface models at the seed's two coefficients of variation, under CNL and CV. Run from the
# repository root after building; a few seconds in all.
set -euo pipefail
IWB=${IWB:-build/iwb}
DEST=data/assessment
N=4000
for cov in 0.05 0.1; do
  for bc in CNL CV; do
    "$IWB" assess mc data/params/table_4_3_mohr_coulomb.toml --cov "$cov" --bc "$bc" --gamma 0.1 --samples $N \
      -o "$DEST/sobol/mc_${bc}_cov$cov" > /dev/null
    "$IWB" assess hyperbolic data/params/table_4_4_hyperbolic.toml --cov "$cov" --bc "$bc" --gamma 2 --samples $N \
      -o "$DEST/sobol/hyperbolic_${bc}_cov$cov" > /dev/null
  done
done
# Parameter uncertainty (Table 4.8, Tables A.1-A.2): CV_Y from 10 000 Latin hypercube samples, CNL
"$IWB" assess mc data/params/table_4_3_mohr_coulomb.toml --uncertainty "$DEST/distributions/mc.toml" --gamma 0.1 \
  --samples 10000 -o "$DEST/uncertainty/mc_CNL" > /dev/null
"$IWB" assess hyperbolic data/params/table_4_4_hyperbolic.toml --uncertainty "$DEST/distributions/hyperbolic.toml" \
  --gamma 2 --samples 10000 -o "$DEST/uncertainty/hyperbolic_CNL" > /dev/null
