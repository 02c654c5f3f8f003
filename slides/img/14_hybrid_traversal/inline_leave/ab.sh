cd /work/main
OLD=/work/scratch/s12/old/build/release/bin/ch16; NEW=/work/main/build/release/bin/race
A="--scenes builtin:teapot_stadium,/work/shared/scenes/bunny.ply --accels final,ch14-hybrid16-auto,ch12-frustum16-4x4,embree-medium-packet8 --cache /work/scratch/s11/cache"
for i in 1 2 3 4 5 6 7 8; do
  if [ $((i % 2)) = 1 ]; then order="old new"; else order="new old"; fi
  for w in $order; do
    if [ $w = old ]; then $OLD $A --out /work/scratch/s12/ab/$w/$i > /dev/null 2>&1; else $NEW $A --cpu none --out /work/scratch/s12/ab/$w/$i > /dev/null 2>&1; fi
  done
done
