# The race behind the verdicts that chapters 02 to 04 quote (the grid, the k-d tree, the median BVHs).
# Run from the repository root. RACE: the race program (default build/release/bin/race); OUT: where the run goes
# (default this folder); further arguments go to the race (./course figures --measure adds --against this
# folder's compare.csv and a --cache). Five processes, one thread's timings on one CPU.
"${RACE:-build/release/bin/race}" --scenes builtin:teapot,builtin:teapot_stadium,builtin:soup --processes 5 \
 --accels brute,ch02-grid,ch02-grid-virtual,ch03-kd,ch03-kd-virtual,ch04-median,ch04-median-virtual,ch04-spatial,ch05-sweep,ch05-binned16,embree-medium \
 --compare ch02-grid:brute,ch02-grid:embree-medium,ch02-grid-virtual:ch02-grid,ch03-kd:ch02-grid,ch03-kd:embree-medium,ch03-kd-virtual:ch03-kd,ch03-kd:ch04-median,ch03-kd:ch04-spatial,ch04-spatial:ch04-median,ch04-median-virtual:ch04-median,ch05-sweep:ch03-kd,ch05-binned16:ch03-kd,ch05-sweep:ch04-median \
 --out "${OUT:-slides/img/16_race/claims_02_04}" "$@"
