# awk -F, -f ratios.awk header_steps_run[1-4].csv lto_steps_run[1-4].csv > ratios.csv
# Chapter 11 NOTES' inlining table: within each run (one ch11 process, one file), the ratio of two steps'
# Mrays/s per scene and ray set, and across the files of a build their median and range; the LTO build's
# step 4 over the usual build's step 4 pairs run K of one with run K of the other (they ran alternately).
# Steps: 4 triangles (the test a call), 5 inlined, 6 soa. Portable awk (no gawk sort).
FNR == 1 { build = (FILENAME ~ /lto_/) ? "lto" : "usual"; run = FILENAME; sub(/.*_run/, "", run); sub(/\.csv$/, "", run); next }
{ for (k = 4; k <= 6; ++k) v[build, run, $1, $2, k] = $k; if (!($1 in seen)) { seen[$1] = 1; scene_list[++nscenes] = $1 }; runs[run] = 1 }
function add(name, b1, s1, b2, s2,    q, scene, k, r, n, x, i, j, t, m) {
    for (q = 1; q <= nscenes; ++q) for (k = 4; k <= 6; ++k) {
        scene = scene_list[q]
        n = 0
        for (r in runs) if ((b1, r, scene, s1, k) in v && (b2, r, scene, s2, k) in v) x[++n] = v[b1, r, scene, s1, k] / v[b2, r, scene, s2, k]
        for (i = 2; i <= n; ++i) { t = x[i]; for (j = i - 1; j >= 1 && x[j] > t; --j) x[j + 1] = x[j]; x[j + 1] = t }
        m = (n % 2) ? x[(n + 1) / 2] : (x[n / 2] + x[n / 2 + 1]) / 2
        line[name, scene, k] = sprintf("%s,%s,%s,%d,%.4f,%.4f,%.4f", name, scene, kind[k], n, m, x[1], x[n])
    }
    names[++count] = name
}
END {
    kind[4] = "primary"; kind[5] = "diffuse"; kind[6] = "shadow"
    add("usual step 5 / step 4", "usual", "inlined", "usual", "triangles")
    add("lto step 5 / step 4", "lto", "inlined", "lto", "triangles")
    add("lto step 4 / usual step 4", "lto", "triangles", "usual", "triangles")
    add("usual step 6 / step 5", "usual", "soa", "usual", "inlined")
    print "ratio,scene,rays,runs,median,min,max"
    for (c = 1; c <= count; ++c) for (q = 1; q <= nscenes; ++q) for (k = 4; k <= 6; ++k) print line[names[c], scene_list[q], k]
}
