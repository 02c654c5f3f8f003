# awk -f embree_own.awk processes/[1-5]/race.csv > embree_own.csv
# Embree's own hybrid (embree-medium-packet8, default flags) over Embree's fastest other row on the same
# rays (its single rays, embree-medium, or its packet and stream rows flagged coherent), and chapter 14's
# hybrid (ch14-hybrid16-auto) over the course's fastest packet or single-ray row (chapters 12 and 13), per
# process and their median: what each hybrid gives up against its own specialised walks (closest hit; any
# hit for shadow rays).
BEGIN { FS = ","; OFS = "," }
FNR == 1 { f++; for (i = 1; i <= NF; i++) col[$i] = i; next }
{
    q = $6 == "shadow" ? "any" : "closest"; v = $(col[q "_mrays_s"]) + 0; k = $1 OFS $6
    if (!(k in seen)) { seen[k]; order[++n] = k }
    if (($3 ~ /^embree-.*coherent$/ || $3 == "embree-medium") && v > ec[f, k]) ec[f, k] = v
    if ($3 ~ /^ch1[23]-/ && v > cb[f, k]) cb[f, k] = v
    if ($3 == "embree-medium-packet8") e8[f, k] = v
    if ($3 == "ch14-hybrid16-auto") h[f, k] = v
    cpu = $(col["cpu"])
}
# The median of the processes' values of ratio r (1: Embree's, 2: the course's) on ray set k.
function median(k, r,   p, v, i, j, t) {
    for (p = 1; p <= f; p++) v[p] = r == 1 ? e8[p, k] / ec[p, k] : h[p, k] / cb[p, k]
    for (i = 2; i <= f; i++) for (j = i; j > 1 && v[j - 1] > v[j]; j--) { t = v[j]; v[j] = v[j - 1]; v[j - 1] = t }
    return f % 2 ? v[(f + 1) / 2] : (v[f / 2] + v[f / 2 + 1]) / 2
}
END {
    print "scene,rays,process,embree_hybrid_vs_embree_best,course_hybrid_vs_course_best,cpu,threads"
    for (i = 1; i <= n; i++) {
        for (p = 1; p <= f; p++)
            printf "%s,%d,%.3f,%.3f,%s,1\n", order[i], p, e8[p, order[i]] / ec[p, order[i]], h[p, order[i]] / cb[p, order[i]], cpu
        printf "%s,median,%.3f,%.3f,%s,1\n", order[i], median(order[i], 1), median(order[i], 2), cpu
    }
}
