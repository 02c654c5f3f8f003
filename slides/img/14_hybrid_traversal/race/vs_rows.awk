# awk -f vs_rows.awk race.csv processes/[1-5]/race.csv > vs_rows.csv
# Chapter 14's hybrid rows (and the final tracer, `final`) against the fastest of chapters 12 and 13 (packets or
# single rays), against Embree's own hybrid (embree-medium-packet8: rtcIntersect8/rtcOccluded8, default flags) and against
# embree-medium, per scene and ray set (closest hit; any hit for shadow rays). The fastest rows are chosen
# by the medians of race.csv (the first file); the ratios are each process's own (the other files, in the
# order given: p1, p2, ...), with their median, smallest and largest.
BEGIN { FS = ","; OFS = "," }
FNR == 1 { f++; for (i = 1; i <= NF; i++) col[$i] = i; next }
{
    q = $6 == "shadow" ? "any" : "closest"; v = $(col[q "_mrays_s"]) + 0; k = $1 SUBSEP $6
    g = $3 ~ /^ch14-/ || $3 == "final" ? "h" : $3 ~ /^ch1[23]-/ ? "b" : $3 == "embree-medium-packet8" ? "e" : $3 == "embree-medium" ? "m" : ""
    if (f == 1) {
        if (!(k in seen)) { seen[k]; order[++n] = k }
        if (g == "h") { rows[k] = rows[k] SUBSEP $3; mrays[k, $3] = v }
        if (g != "" && v > best[k, g]) { best[k, g] = v; name[k, g] = $3 }
    } else speed[f - 1, k, $3] = v
}
# The processes' ratios a / b: "median,smallest,largest" into out[1], ",p1,p2,..." into out[2].
function ratios(k, a, b,   p, r, i, j, t) {
    out[2] = ""
    for (p = 1; p < f; p++) { r[p] = speed[p, k, a] / speed[p, k, b]; out[2] = out[2] sprintf(",%.4g", r[p]) }
    for (i = 2; i < f; i++) for (j = i; j > 1 && r[j - 1] > r[j]; j--) { t = r[j]; r[j] = r[j - 1]; r[j - 1] = t }
    out[1] = sprintf("%.4g,%.4g,%.4g", (f % 2 == 0) ? r[f / 2] : (r[(f - 1) / 2] + r[(f + 1) / 2]) / 2, r[1], r[f - 1])
}
END {
    head = "scene,rays,query,row,mrays_s,best_row,best_mrays_s,vs_best,vs_best_lo,vs_best_hi," \
           "embree_packet8_mrays_s,vs_embree_packet8,vs_embree_packet8_lo,vs_embree_packet8_hi," \
           "embree_mrays_s,vs_embree,vs_embree_lo,vs_embree_hi"
    for (c = 1; c <= 3; c++) for (p = 1; p < f; p++)
        head = head "," (c == 1 ? "vs_best" : c == 2 ? "vs_embree_packet8" : "vs_embree") "_p" p
    print head
    for (i = 1; i <= n; i++) {
        k = order[i]; split(k, s, SUBSEP); m = split(substr(rows[k], 2), list, SUBSEP)
        for (j = 1; j <= m; j++) {
            a = list[j]
            ratios(k, a, name[k, "b"]); c1 = out[1]; e1 = out[2]
            ratios(k, a, "embree-medium-packet8"); c2 = out[1]; e2 = out[2]
            ratios(k, a, "embree-medium"); c3 = out[1]; e3 = out[2]
            print s[1], s[2], s[2] == "shadow" ? "any" : "closest", a, mrays[k, a], name[k, "b"], best[k, "b"], c1,
                  best[k, "e"], c2, best[k, "m"], c3 e1 e2 e3
        }
    }
}
