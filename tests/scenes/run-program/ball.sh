#!/bin/sh
# A RunProgram helper: for each request ("detail datablock") it writes a sphere
# of the radius the datablock gives, then the byte 0xFF that ends its answer.
while read detail radius; do
  echo "Sphere $radius -$radius $radius 360"
  printf '\377'
done
