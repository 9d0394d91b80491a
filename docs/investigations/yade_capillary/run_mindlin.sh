#!/bin/sh
# the Hertz-Mindlin (+ Law2_ScGeom_CapillaryPhys_Capillarity) packing series, one after another
cd /work/yade_wet
for a in "dry 0" "wet 2000" "wet 10000"; do
  set -- $a
  NSPH=300 GDOT=1.0 STRAIN=0.2 nice -n 10 yade -n -x -j1 30_packing_shear.py mindlin $1 $2 1 500 > results/mindlin_$1_$2.log 2>&1
done
