#!/bin/sh
# SPDX-License-Identifier: MIT
# tinysubd vs OpenSubdiv, CGAL and OpenMesh (make bench-peers). See bench/peers/README.md.
#
#   bench/peers/run.sh [MESH_DIR]        (run from anywhere; MESH_DIR defaults to
#                                          $SHARED/data/meshes/bench, SHARED=../shared)
# Environment: TIME=cpu|wall (which time the tables use, default cpu: the process CPU time of
# the timed call, robust on a shared machine; both are in the raw lines), REPS (runs per case, default 3), LONG (s; a first run longer than this is not
# repeated, default 5), CASE_LIMIT (s; skip a mesh/level whose predicted total over all
# implementations exceeds it, default 60), MEM_LIMIT_MB (skip an implementation whose
# predicted max RSS exceeds it, default 8192), PEERS_NO_INSTALL=1 (never call apt-get),
# LOOP_LEVELS (the Loop levels to run, default "1 2 3 4 5"; e.g. "3 4 5" for the targets only),
# PEERS_OUT (build directory of the drivers and results, default build/peers),
# E2E_MESHES / E2E_LEVEL (the end-to-end OBJ row: default spot_triangulated, level 5),
# E2E_ONLY=1 (run only the end-to-end row).
# Loop runs five implementations: tinysubd (subd_loop), stream (tinysubd's subd_loop_stream into
# a checksum sink, reported as tinysubd-stream), osd, cgal, openmesh.
#
# Installs libosd-dev libcgal-dev libopenmesh-dev with apt-get when missing, builds the four
# drivers into build/peers/, runs every case in its own process (so max RSS is per case),
# REPS times, and prints the medians, the ratios and whether the issue's target is met.
# Needs no stdin. Raw result lines: build/peers/results.txt.
set -eu

ROOT=$(cd "$(dirname "$0")/../.." && pwd)
if [ $# -ge 1 ]; then MESH_DIR=$(cd "$1" && pwd); fi
cd "$ROOT"
SHARED=${SHARED:-../shared}
MESH_DIR=${MESH_DIR:-$SHARED/data/meshes/bench}
TIME=${TIME:-cpu}
case $TIME in cpu|wall) ;; *) echo "TIME must be cpu or wall" >&2; exit 2 ;; esac
OUT=${PEERS_OUT:-build/peers}  # PEERS_OUT: where the drivers and results go
REPS=${REPS:-3}
LONG=${LONG:-5}
CASE_LIMIT=${CASE_LIMIT:-60}
MEM_LIMIT_MB=${MEM_LIMIT_MB:-8192}
MESHES="spot_triangulated nefertiti stanford-bunny-open"
IMPLS="tinysubd stream osd cgal openmesh"  # stream = tinysubd's subd_loop_stream (Loop only)

# ------------------------------------------------------------------ packages
PKGS="libosd-dev libcgal-dev libopenmesh-dev time"  # time: /usr/bin/time for the end-to-end row
missing=
for p in $PKGS; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
if [ -n "$missing" ]; then
    if [ "${PEERS_NO_INSTALL:-0}" = 1 ]; then echo "missing packages:$missing" >&2; exit 1; fi
    echo "installing$missing"
    SUDO=; [ "$(id -u)" -eq 0 ] || SUDO=sudo
    $SUDO apt-get update -q </dev/null >/dev/null &&
        DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -q $missing </dev/null >/dev/null ||
        { echo "could not install$missing" >&2; exit 1; }
fi
for m in $MESHES; do
    [ -f "$MESH_DIR/$m.obj" ] || { echo "missing mesh $MESH_DIR/$m.obj" >&2; exit 1; }
done

# ------------------------------------------------------------------ build
mkdir -p "$OUT"
CXX=${CXX:-g++}
CC=${CC:-gcc}
CXXFLAGS="-O2 -DNDEBUG -std=c++17 -Ibench/peers"
echo "== building drivers into $OUT/"
$CC -std=c99 -O2 -Iinclude -DSUBD_FIXED=0 bench/peers/tinysubd_driver.c src/*.c -lm \
    -o "$OUT/tinysubd_driver" 2>"$OUT/build-tinysubd.log" & p1=$!
$CXX $CXXFLAGS bench/peers/osd_driver.cpp -o "$OUT/osd_driver" -losdCPU \
    2>"$OUT/build-osd.log" & p2=$!
$CXX $CXXFLAGS bench/peers/openmesh_driver.cpp -o "$OUT/openmesh_driver" -lOpenMeshCore \
    2>"$OUT/build-openmesh.log" & p3=$!
$CXX $CXXFLAGS bench/peers/cgal_driver.cpp -o "$OUT/cgal_driver" -lgmp -lmpfr \
    2>"$OUT/build-cgal.log" & p4=$!
${MAKE:-make} --no-print-directory build/bin/subd >"$OUT/build-subd.log" 2>&1 & p5=$!  # the tool, for end to end
fail=0
for p in $p1 $p2 $p3 $p4 $p5; do wait $p || fail=1; done
if [ $fail -ne 0 ]; then cat "$OUT"/build-*.log >&2; echo "driver build failed" >&2; exit 1; fi

ver() { dpkg-query -W -f='${Version}' "$1" 2>/dev/null || echo "?"; }
echo "versions: tinysubd $(sed -n 's/^#define SUBD_VERSION "\(.*\)"/\1/p' include/subd.h)" \
     "(gcc -O2, float32) | OpenSubdiv $(ver libosd-dev) | CGAL $(ver libcgal-dev)" \
     "| OpenMesh $(ver libopenmesh-dev) | $($CXX --version | head -n 1)"
echo "machine: $(nproc) CPUs, $(awk '/MemTotal/ {printf "%.1f GB", $2/1048576}' /proc/meminfo)," \
     "load average at start: $(cut -d' ' -f1-3 /proc/loadavg)"

if [ "${E2E_ONLY:-0}" != 1 ]; then
# ------------------------------------------------------------------ run
RES="$OUT/results.txt"
: >"$RES"
SKIPS="$OUT/skips.txt"
: >"$SKIPS"
start=$(date +%s)

# run IMPL SCHEME MESH LEVEL -> appends result lines; prints the first run's "seconds maxrss_kb"
run_case() {
    drv="$OUT/$1_driver"
    arg=$2
    if [ "$1" = stream ]; then drv="$OUT/tinysubd_driver"; arg=stream; fi
    n=0
    first=
    while [ $n -lt "$REPS" ]; do
        if ! line=$(timeout 300 "$drv" "$arg" "$MESH_DIR/$3.obj" "$4" 2>"$OUT/last-stderr.txt"); then
            echo "$3 L$4 $2 $1: failed: $(tail -n 1 "$OUT/last-stderr.txt")" >>"$SKIPS"
            echo "fail"
            return 0
        fi
        echo "$line" >>"$RES"
        n=$((n + 1))
        if [ -z "$first" ]; then
            first=$(echo "$line" | sed "s/.* ${TIME}_seconds=\\([^ ]*\\).*maxrss_kb=\\([^ ]*\\).*/\\1 \\2/")
            # a long case is not repeated (time budget); the table shows the run count
            if awk -v t="${first% *}" -v l="$LONG" 'BEGIN { exit !(t > l) }'; then break; fi
        fi
    done
    echo "$first"
}

echo "== running (time = $TIME; each case in its own process; REPS=$REPS, runs over ${LONG}s not repeated)"
for scheme in loop doosabin; do
    if [ $scheme = loop ]; then levels=${LOOP_LEVELS:-1 2 3 4 5}; impls=$IMPLS; else levels=3; impls="tinysubd cgal"; fi
    for m in $MESHES; do
        # per implementation: last level's seconds and max RSS, for the skip prediction
        for i in $impls; do eval "t_$i=0; r_$i=0"; done
        for l in $levels; do
            # predict this level from the previous one: 4x the faces -> ~4.5x time, 4x memory
            pred=0
            for i in $impls; do
                eval "t=\$t_$i"
                pred=$(awk -v p="$pred" -v t="$t" 'BEGIN { printf "%.3f", p + 4.5 * t }')
            done
            if awk -v p="$pred" -v c="$CASE_LIMIT" 'BEGIN { exit !(p > c) }'; then
                if awk -v p="$pred" 'BEGIN { exit !(p > 1e8) }'; then
                    why="the previous level was skipped"
                else
                    why="predicted ${pred} s for all implementations together (4.5x the previous level) > ${CASE_LIMIT} s"
                fi
                echo "$m L$l $scheme: skipped, $why" >>"$SKIPS"
                printf '  %-20s %-8s L%s skipped\n' "$m" "$scheme" "$l"
                for i in $impls; do eval "t_$i=1e9"; done
                continue
            fi
            printf '  %-20s %-8s L%s' "$m" "$scheme" "$l"
            for i in $impls; do
                eval "r=\$r_$i"
                mem=$(awk -v r="$r" 'BEGIN { printf "%.0f", 4 * r / 1024 }')
                if [ "$mem" -gt "$MEM_LIMIT_MB" ]; then
                    echo "$m L$l $scheme $i: skipped, predicted max RSS ${mem} MB > ${MEM_LIMIT_MB} MB" >>"$SKIPS"
                    eval "t_$i=0; r_$i=1e12"
                    printf ' %s:skip' "$i"
                    continue
                fi
                res=$(run_case "$i" "$scheme" "$m" "$l")
                if [ "$res" = fail ]; then eval "t_$i=1e9; r_$i=1e12"; printf ' %s:FAIL' "$i"; continue; fi
                eval "t_$i=${res% *}; r_$i=${res#* }"
                printf ' %s:%ss' "$i" "${res% *}"
            done
            echo
        done
    done
done
echo "total run time: $(( $(date +%s) - start )) s"

# ------------------------------------------------------------------ report
awk -v meshes="$MESHES" -v tfield="${TIME}_seconds" '
function median(key,    n, i, j, a, t) {
    n = cnt[key]
    for (i = 1; i <= n; i++) a[i] = sec[key, i]
    for (i = 2; i <= n; i++) { t = a[i]; for (j = i - 1; j >= 1 && a[j] > t; j--) a[j + 1] = a[j]; a[j + 1] = t }
    return (n % 2) ? a[(n + 1) / 2] : (a[n / 2] + a[n / 2 + 1]) / 2
}
function maxrss(key,    n, i, a, t) {  # median of the runs max RSS
    n = cnt[key]
    for (i = 1; i <= n; i++) a[i] = rss[key, i]
    for (i = 2; i <= n; i++) { t = a[i]; for (j = i - 1; j >= 1 && a[j] > t; j--) a[j + 1] = a[j]; a[j + 1] = t }
    return (n % 2) ? a[(n + 1) / 2] : (a[n / 2] + a[n / 2 + 1]) / 2
}
{
    delete kv
    for (i = 1; i <= NF; i++) { split($i, p, "="); kv[p[1]] = p[2] }
    peer = kv["peer"]; if (peer == "opensubdiv") peer = "osd"; if (peer == "tinysubd-stream") peer = "stream"
    key = kv["scheme"] SUBSEP kv["mesh"] SUBSEP kv["level"] SUBSEP peer
    n = ++cnt[key]
    sec[key, n] = kv[tfield]; rss[key, n] = kv["maxrss_kb"]
    faces[key] = kv["faces"]
    if ("arena_bytes" in kv) arena[key] = kv["arena_bytes"]
    if ("plan_bytes" in kv) plan[key] = kv["plan_bytes"]
    row = kv["scheme"] SUBSEP kv["mesh"] SUBSEP kv["level"]
    if (!(row in seen)) { seen[row] = 1; rows[++nrows] = row }
}
END {
    np = split("tinysubd osd cgal openmesh", P, " ")
    nm = split(meshes, M, " ")
    # rows in a fixed order
    nr = 0
    split("loop doosabin", S, " ")
    for (s = 1; s <= 2; s++) for (m = 1; m <= nm; m++) for (l = 1; l <= 8; l++) {
        row = S[s] SUBSEP M[m] SUBSEP l
        if (row in seen) order[++nr] = row
    }
    print ""
    print "Times: median " (tfield == "cpu_seconds" ? "process CPU" : "wall-clock") " seconds of the timed call (n runs); Mf/s = output faces / s / 1e6; MB = max RSS of the case process (MiB)."
    printf "%-8s %-20s %2s %10s | %-27s | %-21s | %-21s | %-21s\n", "", "", "", "",
           "tinysubd", "opensubdiv", "cgal", "openmesh"
    printf "%-8s %-20s %2s %10s | %-27s | %-21s | %-21s | %-21s\n", "scheme", "mesh", "L", "out faces",
           "     s  Mf/s    MB arenaMB", "     s  Mf/s    MB(n)", "     s  Mf/s    MB(n)", "     s  Mf/s    MB(n)"
    for (r = 1; r <= nr; r++) {
        split(order[r], k, SUBSEP)
        f = faces[order[r] SUBSEP "tinysubd"]
        if (f == "") for (i = 2; i <= np; i++) if (faces[order[r] SUBSEP P[i]] != "") { f = faces[order[r] SUBSEP P[i]]; break }
        printf "%-8s %-20s %2s %10s", k[1], k[2], k[3], f
        for (i = 1; i <= np; i++) {
            key = order[r] SUBSEP P[i]
            if (!(key in cnt)) { printf " | %-" (i == 1 ? 27 : 21) "s", "-"; continue }
            T[P[i]] = median(key); R[P[i]] = maxrss(key) / 1024; F[P[i]] = faces[key]
            printf " | %6.3f %5.2f %5.0f", T[P[i]], F[P[i]] / T[P[i]] / 1e6, R[P[i]]
            if (i == 1) printf " %5.0f(%d)", arena[key] / 1048576, cnt[key]
            else printf "(%d)", cnt[key]
            if (faces[key] != f) printf "*"
        }
        printf "\n"
    }
    print ""
    print "Ratios: speed = tinysubd output faces/s / peer output faces/s (>1: tinysubd faster);"
    print "        mem = tinysubd max RSS / peer max RSS (<1: tinysubd smaller)."
    print "Target (issue): Loop L3-5, speed vs OpenSubdiv >= 6 and mem vs OpenSubdiv <= 1/3."
    printf "%-8s %-20s %2s | %-23s | %-23s | %s\n", "scheme", "mesh", "L", "speed: osd  cgal  om", "mem: osd  cgal   om", "target"
    tested = 0; met = 0
    for (r = 1; r <= nr; r++) {
        split(order[r], k, SUBSEP)
        tk = order[r] SUBSEP "tinysubd"
        if (!(tk in cnt)) continue
        tt = median(tk); tr = maxrss(tk); tf = faces[tk]
        printf "%-8s %-20s %2s | ", k[1], k[2], k[3]
        for (i = 2; i <= np; i++) {
            key = order[r] SUBSEP P[i]
            if (key in cnt) printf "%6.2f ", (tf / tt) / (faces[key] / median(key)); else printf "%6s ", "-"
        }
        printf " | "
        for (i = 2; i <= np; i++) {
            key = order[r] SUBSEP P[i]
            if (key in cnt) printf "%6.2f ", tr / maxrss(key); else printf "%6s ", "-"
        }
        ok = "";
        ok_key = order[r] SUBSEP "osd"
        if (k[1] == "loop" && k[3] >= 3 && (ok_key in cnt)) {
            sp = (tf / tt) / (faces[ok_key] / median(ok_key)); mr = tr / maxrss(ok_key)
            tested++
            if (sp >= 6 && mr <= 1 / 3) { ok = "met"; met++ }
            else ok = "NOT met (" (sp >= 6 ? "" : "speed") (sp < 6 && mr > 1 / 3 ? ", " : "") (mr <= 1 / 3 ? "" : "memory") ")"
        }
        printf " | %s\n", ok
    }
    print ""
    if (tested == 0) print "TARGET: not evaluated (no Loop L3-5 case with both tinysubd and OpenSubdiv)"
    else if (met == tested) printf "TARGET MET in all %d Loop L3-5 cases (>= 6x OpenSubdiv output faces/s, <= 1/3 its max RSS)\n", tested
    else printf "TARGET NOT MET: %d of %d Loop L3-5 cases meet >= 6x OpenSubdiv output faces/s with <= 1/3 its max RSS\n", met, tested
    print "(n) = runs behind the median; * = this implementation output a different face count."

    # streaming (issue 12, item 9): subd_loop_stream into a checksum sink vs OpenSubdiv
    print ""
    print "Streaming Loop: tinysubd-stream = subd_loop_stream (boundary PAPER) into a checksum sink (FNV-1a of every"
    print "emitted position), triangles/s; OpenSubdiv = its uniform refinement above, output faces/s; same run."
    print "speed = stream triangles/s / OpenSubdiv output faces/s; plan = stream arena bytes (subd_loop_stream_plan);"
    print "plan/osd = plan / OpenSubdiv max RSS; in+plan/osd = (input mesh arena + plan) / OpenSubdiv max RSS;"
    print "stream MB = the stream process max RSS (program, libc, file buffer freed, input mesh)."
    print "Target (issue 12, item 9): Loop L3-5, speed >= 6 and plan < 1/1000 of OpenSubdiv peak (max RSS)."
    printf "%-20s %2s %10s | %7s %6s %8s %8s | %7s %6s %7s | %6s %9s %11s | %s\n", "mesh", "L", "triangles",
           "s", "Mtri/s", "plan B", "MB(n)", "osd s", "Mf/s", "MB(n)", "speed", "plan/osd", "in+plan/osd", "target"
    stested = 0; smet = 0
    for (r = 1; r <= nr; r++) {
        split(order[r], k, SUBSEP)
        sk = order[r] SUBSEP "stream"; ok_key = order[r] SUBSEP "osd"
        if (k[1] != "loop" || !(sk in cnt)) continue
        st = median(sk); sf = faces[sk]
        printf "%-20s %2s %10s | %7.3f %6.2f %8d %5.0f(%d)", k[2], k[3], sf, st, sf / st / 1e6, plan[sk], maxrss(sk) / 1024, cnt[sk]
        if (!(ok_key in cnt)) { printf " | %-22s | %-28s |\n", "-", "-"; continue }
        ot = median(ok_key); of = faces[ok_key]; orss = maxrss(ok_key) * 1024
        sp = (sf / st) / (of / ot); mr = plan[sk] / orss; ar = arena[sk] / orss
        printf " | %7.3f %6.2f %4.0f(%d)%s | %6.2f %9.2e %11.2e", ot, of / ot / 1e6, orss / 1048576, cnt[ok_key],
               (of != sf ? "*" : " "), sp, mr, ar
        ok = ""
        if (k[3] >= 3) {
            stested++
            if (sp >= 6 && mr < 1 / 1000) { ok = "met"; smet++ }
            else ok = "NOT met (" (sp >= 6 ? "" : "speed " sprintf("%.2f", sp) "x < 6x") (sp < 6 && mr >= 1 / 1000 ? ", " : "") (mr < 1 / 1000 ? "" : "memory") ")"
        }
        printf " | %s\n", ok
    }
    print ""
    if (stested == 0) print "STREAM TARGET: not evaluated (no Loop L3-5 case with both tinysubd-stream and OpenSubdiv)"
    else if (smet == stested) printf "STREAM TARGET MET in all %d Loop L3-5 cases (>= 6x OpenSubdiv output faces/s, plan < 1/1000 of its max RSS)\n", stested
    else {
        nmem = 0
        for (r = 1; r <= nr; r++) {
            split(order[r], k, SUBSEP); sk = order[r] SUBSEP "stream"; ok_key = order[r] SUBSEP "osd"
            if (k[1] == "loop" && k[3] >= 3 && (sk in cnt) && (ok_key in cnt) && plan[sk] / (maxrss(ok_key) * 1024) < 1 / 1000) nmem++
        }
        printf "STREAM TARGET NOT MET: %d of %d Loop L3-5 cases meet both (memory part: %d of %d; speed part: see the speed column)\n", smet, stested, nmem, stested
    }
}' "$RES"
if [ -s "$SKIPS" ]; then echo "skipped / failed:"; sed 's/^/  /' "$SKIPS"; fi
echo "raw lines: $RES"
fi

# ------------------------------------------------------------------ end to end: OBJ file
# The whole process, file to file: `subd loop -l L MESH -o out.obj` (read, build, Loop, write
# the OBJ text) against `osd_driver loop-obj MESH L out.obj` (read, Far refine, interpolate,
# write with printf "%.9g"), each REPS times in a fresh process under /usr/bin/time; the
# median of the process CPU time (user + system; TIME=wall: elapsed) and of the max RSS.
E2E_MESHES=${E2E_MESHES:-spot_triangulated}
E2E_LEVEL=${E2E_LEVEL:-5}
E2E="$OUT/e2e.txt"
: >"$E2E"
echo
echo "== end to end (time = $TIME; REPS=$REPS): subd loop -l $E2E_LEVEL MESH -o out.obj vs osd_driver loop-obj MESH $E2E_LEVEL out.obj"
for m in $E2E_MESHES; do
    n=0
    while [ $n -lt "$REPS" ]; do
        for i in tinysubd osd; do
            if [ $i = tinysubd ]; then
                set -- build/bin/subd loop -l "$E2E_LEVEL" "$MESH_DIR/$m.obj" -o "$OUT/e2e-$i.obj"
            else
                set -- "$OUT/osd_driver" loop-obj "$MESH_DIR/$m.obj" "$E2E_LEVEL" "$OUT/e2e-$i.obj"
            fi
            if ! /usr/bin/time -f "%e %U %S %M" -o "$OUT/e2e-time.txt" "$@" >/dev/null 2>"$OUT/last-stderr.txt"; then
                echo "  $m L$E2E_LEVEL $i: failed: $(tail -n 1 "$OUT/last-stderr.txt")"
                continue
            fi
            echo "$i $m $(tail -n 1 "$OUT/e2e-time.txt") $(wc -c <"$OUT/e2e-$i.obj")" >>"$E2E"
        done
        n=$((n + 1))
    done
done
rm -f "$OUT/e2e-tinysubd.obj" "$OUT/e2e-osd.obj"
awk -v tmode="$TIME" -v level="$E2E_LEVEL" '
function median(k,    n, i, j, a, t) {
    n = cnt[k]; for (i = 1; i <= n; i++) a[i] = v[k, i]
    for (i = 2; i <= n; i++) { t = a[i]; for (j = i - 1; j >= 1 && a[j] > t; j--) a[j + 1] = a[j]; a[j + 1] = t }
    return (n % 2) ? a[(n + 1) / 2] : (a[n / 2] + a[n / 2 + 1]) / 2
}
{   # impl mesh elapsed user sys maxrss_kb bytes
    k = $1 SUBSEP $2; n = ++cnt[k]
    v[k, n] = (tmode == "wall") ? $3 : $4 + $5
    rk = "rss" SUBSEP k; cnt[rk] = n; v[rk, n] = $6
    bytes[k] = $7
    if (!($2 in seen)) { seen[$2] = 1; ms[++nm] = $2 }
}
END {
    printf "%-20s %2s | %8s %6s %9s | %8s %6s %9s | %6s | %s\n", "mesh", "L", "subd s", "MB", "OBJ MB",
           "osd s", "MB", "OBJ MB", "speed", "target (>= 2x)"
    tested = 0; met = 0
    for (i = 1; i <= nm; i++) {
        a = "tinysubd" SUBSEP ms[i]; b = "osd" SUBSEP ms[i]
        if (!(a in cnt) || !(b in cnt)) { printf "%-20s %2s | missing runs\n", ms[i], level; continue }
        ta = median(a); tb = median(b); sp = tb / ta; tested++
        ok = sp >= 2 ? "met" : "NOT met"; if (sp >= 2) met++
        printf "%-20s %2s | %8.3f %6.0f %9.1f | %8.3f %6.0f %9.1f | %6.2f | %s (n=%d)\n", ms[i], level, ta,
               median("rss" SUBSEP a) / 1024, bytes[a] / 1048576, tb, median("rss" SUBSEP b) / 1024,
               bytes[b] / 1048576, sp, ok, cnt[a]
    }
    print "speed = OpenSubdiv process " (tmode == "wall" ? "elapsed" : "CPU (user + system)") " seconds / subd process seconds (medians); MB = max RSS (MiB)."
    if (tested == 0) print "E2E TARGET: not evaluated"
    else if (met == tested) printf "E2E TARGET MET in all %d cases (subd loop to OBJ >= 2x faster than OpenSubdiv writing OBJ)\n", tested
    else printf "E2E TARGET NOT MET: %d of %d cases >= 2x\n", met, tested
}' "$E2E"
echo "raw lines (impl mesh elapsed user sys maxrss_kb obj_bytes): $E2E"
