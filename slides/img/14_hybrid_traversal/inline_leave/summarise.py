#!/usr/bin/env python3
# Per process, each row's speed over embree-medium-packet8's in the same process (closest hit; any hit for
# shadow rays), for the code before (old/K/race.csv) and after (new/K/race.csv); the medians, their ranges
# and new over old. Usage: summarise.py > summary.csv (in this folder).
import csv, glob, statistics as st
ratios = {}
for w in ("old", "new"):
    for f in sorted(glob.glob(f"{w}/*/race.csv")):
        rows = list(csv.DictReader(open(f)))
        speed = {}
        for r in rows:
            q = "closest_mrays_s" if float(r["closest_mrays_s"] or 0) > 0 else "any_mrays_s"
            speed[(r["scene"], r["rays"], r["structure"])] = float(r[q])
        cpu = rows[0]["cpu"]
        for (scene, rays, s), v in speed.items():
            if s == "embree-medium-packet8": continue
            ratios.setdefault((scene, rays, s), {}).setdefault(w, []).append(v / speed[(scene, rays, "embree-medium-packet8")])
print("scene,rays,structure,old_median,old_min,old_max,new_median,new_min,new_max,new_over_old,cpu,threads")
for (scene, rays, s), d in sorted(ratios.items()):
    o, n = d["old"], d["new"]
    print(f"{scene},{rays},{s},{st.median(o):.3f},{min(o):.3f},{max(o):.3f},{st.median(n):.3f},{min(n):.3f},{max(n):.3f},"
          f"{st.median(n) / st.median(o):.3f},{cpu},1")
