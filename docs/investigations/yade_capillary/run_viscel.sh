#!/bin/sh
# the ViscElCap packing series, one after another
cd /work/yade_wet
for a in "dry 0" "wet 2000" "wet 10000"; do
  set -- $a
  NSPH=300 nice -n 10 yade -n -x -j1 30_packing_shear.py viscel $1 $2 1 500 > results/viscel_$1_$2.log 2>&1
done
