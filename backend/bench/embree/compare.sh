#!/bin/sh
# Our ray kernel against Embree's, alternated: ROUNDS rounds (default 3), each the Java side on every
# scene (studio-bench.jar kernel, which also writes the scenes' geometry) and then embree_rays on each.
# Every line goes to WORK/runs-THREADS.txt; at the end a summary per scene: the median over the rounds
# of each round's best frame, by CPU time and by wall clock, in millions of rays a second.
#
# Each side's figure is its best frame of FRAMES timed ones (default 15): this machine's speed changes for
# seconds at a time (one JVM's frames of the same code: 32-34 ms, then 46-49, then back), so a longer run
# of frames finds each side's fast spell.
#
# Run from anywhere, after building the bench jar and ./build.sh (see docs/speed.md):
#   backend/bench/embree/compare.sh [ROUNDS] [THREADS]     (JAVA=..., WORK=..., FRAMES=... to change them)
set -eu
rounds=${1:-3}
threads=${2:-1}
frames=${FRAMES:-15}
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../../.." && pwd)
work=${WORK:-${TMPDIR:-/tmp}/studio-kernel}
java=${JAVA:-java}
log=$work/runs-$threads.txt
mkdir -p "$work"
: > "$log"
for round in $(seq "$rounds"); do
    echo "# round $round:$(uptime)" | tee -a "$log"
    "$java" -jar "$root/backend/bench/target/studio-bench.jar" kernel --threads "$threads" --frames "$frames" --work "$work" \
        --scenes-dir "$root/scenes" | tee -a "$log"
    for scene in still-life spheres-10k mesh-100k; do
        "$here/embree_rays" "$work/$scene.kernel" --threads "$threads" --frames "$frames" | tee -a "$log"
        # cmp -l lists each differing byte: its two values in octal, 0 where a camera ray missed
        cmp -l "$work/$scene.ours.pgm" "$work/$scene.embree.pgm" | awk -v s="$scene" '
            $2 == 0 || $3 == 0 { hit++; next } { shadow++ }
            END { printf "# %s: pixels that differ: %d in hit or miss, %d in light or shadow\n", s, hit, shadow }' \
            | tee -a "$log"
    done
done
echo "# $(uptime)" | tee -a "$log"

awk '
    function median(list, n,    a, i, j, t) {
        n = split(list, a, " ")
        for (i = 2; i <= n; i++) for (j = i; j > 1 && a[j - 1] + 0 > a[j] + 0; j--) { t = a[j]; a[j] = a[j - 1]; a[j - 1] = t }
        return n % 2 ? a[(n + 1) / 2] : (a[n / 2] + a[n / 2 + 1]) / 2
    }
    /^kernel=/ {
        delete f
        for (i = 1; i <= NF; i++) { split($i, kv, "="); f[kv[1]] = kv[2] }
        k = f["scene"] SUBSEP f["kernel"]
        cpu[k] = cpu[k] " " f["mrays_cpu_best"]; wall[k] = wall[k] " " f["mrays_best"]; hits[k] = f["hits"]
        if (!(f["scene"] in seen)) { seen[f["scene"]] = 1; order[++scenes] = f["scene"] }
    }
    END {
        print ""
        printf "%-12s %9s %9s  %-26s %-26s %s\n", "scene", "hits ours", "embree", "ours M rays/s cpu (wall)", "embree M rays/s cpu (wall)", "ours/embree (cpu)"
        for (i = 1; i <= scenes; i++) {
            s = order[i]; o = s SUBSEP "ours"; e = s SUBSEP "embree"
            printf "%-12s %9d %9d  %6.2f (%6.2f)            %6.2f (%6.2f)             %.2f\n", s, hits[o], hits[e],
                median(cpu[o]), median(wall[o]), median(cpu[e]), median(wall[e]), median(cpu[o]) / median(cpu[e])
        }
    }' "$log" | tee "$work/summary-$threads.txt"
