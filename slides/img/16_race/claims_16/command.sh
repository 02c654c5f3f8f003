# The race behind the verdicts that chapter 16's first figures quote (the built-in scenes: every chapter's row against Embree).
# Run from the repository root. RACE: the race program (default build/release/bin/race); OUT: where the run goes
# (default this folder); further arguments go to the race (./course figures --measure adds --against this
# folder's compare.csv and a --cache). Five processes, one thread's timings on one CPU.
"${RACE:-build/release/bin/race}" --scenes builtin:cornell,builtin:teapot,builtin:teapot_stadium,builtin:soup --processes 5 \
 --accels ch01-virtual,brute,ch02-grid,ch03-kd,ch04-median,ch05-sweep,ch05-binned16,ch05-binned16-fast,ch06-binned16-reinserted-fast,embree-medium,embree-medium-packet8 \
 --compare ch01-virtual:brute,brute:ch04-median,ch04-median:embree-medium,ch02-grid:embree-medium,ch03-kd:embree-medium,ch05-binned16-fast:embree-medium,ch06-binned16-reinserted-fast:embree-medium,ch05-sweep:ch04-median,ch05-binned16:ch04-median,ch05-binned16-fast:ch05-binned16,embree-medium-packet8:embree-medium \
 --out "${OUT:-slides/img/16_race/claims_16}" "$@"
