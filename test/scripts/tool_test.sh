#!/bin/sh
# SPDX-License-Identifier: MIT
# Tests of the subd host tool (port/host/subd_*.c): exit codes, FILE:LINE messages for
# every row of test/bad/EXPECT, info topology on test/data, convert round trips, render,
# --stats JSON, --arena budget, --tags files, loop --stream (.stl/.obj/.off against loop's output),
# the option table behind --help, usage and I/O errors.
# Needs only sh, coreutils, grep, sed, awk, od and a C compiler ($CC or cc, for test/tools/tri_dump.c). Prints one "ok - ..." / "not ok - ..." line per
# check (details of a failure follow, indented) and ends with "N passed, M failed".
# usage: test/scripts/tool_test.sh BIN_DIR      (BIN_DIR holds subd and subd-fixed)
if [ $# -ne 1 ]; then
    echo "usage: $0 BIN_DIR" >&2
    exit 2
fi
case $1 in /*) BIN=$1 ;; *) BIN=$(pwd)/$1 ;; esac
cd "$(dirname "$0")/../.." || exit 2 # repo root: messages name test/bad/FILE as given
FLOAT=$BIN/subd
FIXED=$BIN/subd-fixed
T=$(mktemp -d "${TMPDIR:-/tmp}/subd_tool_test.XXXXXX") || exit 2
trap 'rm -rf "$T"' EXIT
trap 'exit 2' HUP INT TERM
pass=0
fail=0

# run BIN ARGS...: runs with no stdin; sets rc, stdout in $T/out, stderr in $T/err.
run() {
    "$@" < /dev/null > "$T/out" 2> "$T/err"
    rc=$?
}
# check CONDITION_STATUS DESCRIPTION (CONDITION_STATUS is 0 for a pass)
check() {
    if [ "$1" -eq 0 ]; then
        pass=$((pass + 1))
        echo "ok - $2"
    else
        fail=$((fail + 1))
        echo "not ok - $2"
        echo "    exit status $rc; stdout:"
        head -n 5 "$T/out" | sed 's/^/      /'
        echo "    stderr:"
        head -n 5 "$T/err" | sed 's/^/      /'
    fi
}
is() { [ "$rc" -eq "$1" ]; }
err_starts() { # stderr's first line starts with $1 (a literal string)
    first=$(head -n 1 "$T/err")
    case $first in "$1"*) return 0 ;; *) return 1 ;; esac
}
out_has() { grep -q -e "$1" "$T/out"; }

# A minimal JSON checker (one value, nothing after it); exit 0 when valid.
json_ok() {
    awk '
    function ws() { while (pos <= n && index(" \t\r\n", substr(s, pos, 1))) pos++ }
    function str(   c, e) {
        pos++
        while (pos <= n) {
            c = substr(s, pos, 1)
            if (c == "\"") { pos++; return 1 }
            if (c == "\\") {
                e = substr(s, pos + 1, 1)
                if (index("\"\\/bfnrt", e)) { pos += 2; continue }
                if (e == "u" && substr(s, pos + 2, 4) ~ /^[0-9a-fA-F][0-9a-fA-F][0-9a-fA-F][0-9a-fA-F]$/) { pos += 6; continue }
                return 0
            }
            if (c == "\n" || c == "\t" || c == "\r") return 0
            pos++
        }
        return 0
    }
    function members(cl,   c, isobj) {
        isobj = (cl == "}")
        pos++; ws()
        if (substr(s, pos, 1) == cl) { pos++; return 1 }
        for (;;) {
            ws()
            if (isobj) {
                if (substr(s, pos, 1) != "\"" || !str()) return 0
                ws()
                if (substr(s, pos, 1) != ":") return 0
                pos++
            }
            if (!value()) return 0
            ws()
            c = substr(s, pos, 1); pos++
            if (c == cl) return 1
            if (c != ",") return 0
        }
    }
    function value(   c, rest) {
        ws(); c = substr(s, pos, 1)
        if (c == "{") return members("}")
        if (c == "[") return members("]")
        if (c == "\"") return str()
        rest = substr(s, pos)
        if (match(rest, /^-?(0|[1-9][0-9]*)(\.[0-9]+)?([eE][+-]?[0-9]+)?/)) { pos += RLENGTH; return 1 }
        if (substr(rest, 1, 4) == "true" || substr(rest, 1, 4) == "null") { pos += 4; return 1 }
        if (substr(rest, 1, 5) == "false") { pos += 5; return 1 }
        return 0
    }
    { s = s $0 "\n" }
    END {
        n = length(s); pos = 1; ws()
        if (substr(s, pos, 1) != "{") exit 1
        if (!value()) exit 1
        ws()
        exit (pos > n) ? 0 : 1
    }' "$1"
}
# json_num KEY: the number after "KEY": in $T/out (top-level keys are unique in our output).
json_num() { sed -n "s/.*\"$1\":\([0-9][0-9.]*\).*/\1/p" "$T/out"; }

for b in "$FLOAT" "$FIXED"; do
    if [ ! -x "$b" ]; then
        echo "not ok - $b is built"
        echo "0 passed, 1 failed"
        exit 1
    fi
done

# ---------------------------------------------------------------- test/bad/EXPECT
rows=0
while read -r file status line only; do
    case $file in '' | '#'*) continue ;; esac
    rows=$((rows + 1))
    case $only in
    fixed) bins=$FIXED ;;
    float) bins=$FLOAT ;;
    *) bins="$FLOAT $FIXED" ;;
    esac
    for b in $bins; do
        name=$(basename "$b")
        run "$b" info "test/bad/$file"
        is 2 && err_starts "test/bad/$file:$line: " && [ "$(wc -l < "$T/err")" -eq 1 ] && [ ! -s "$T/out" ]
        check $? "$name info test/bad/$file: exit 2, 'test/bad/$file:$line: ' ($status)"
    done
    # A value out of range in one arithmetic only is valid in the other.
    case $only in
    fixed) run "$FLOAT" info "test/bad/$file"; is 0; check $? "subd info test/bad/$file: valid in float32" ;;
    float) run "$FIXED" info "test/bad/$file"; is 0; check $? "subd-fixed info test/bad/$file: valid in q16.16" ;;
    esac
done < test/bad/EXPECT
[ "$rows" -gt 0 ]; check $? "test/bad/EXPECT has rows ($rows)"
missing=""
for f in test/bad/*; do
    n=$(basename "$f")
    [ "$n" = EXPECT ] && continue
    grep -q "^$n[ 	]" test/bad/EXPECT || missing="$missing $n"
done
[ -z "$missing" ]; check $? "every file in test/bad has an EXPECT row${missing:+ (missing:$missing)}"

# ---------------------------------------------------------------- info on test/data
for b in "$FLOAT" "$FIXED"; do
    name=$(basename "$b")
    run "$b" info test/data/torus_tri.obj
    is 0 && out_has '^euler characteristic: 0 ' && out_has '^genus: 1$' && out_has '^boundary loops: 0$' &&
        out_has '^components: 1 '
    check $? "$name info torus_tri.obj: chi 0, genus 1, closed, 1 component"
    run "$b" info test/data/icosahedron.obj
    is 0 && out_has '^euler characteristic: 2 ' && out_has '^genus: 0$' && out_has '^vertices: 12 ' &&
        out_has '^valence interior: 5:12$' && out_has '^faces: 20$' && out_has '^edges: 30$'
    check $? "$name info icosahedron.obj: chi 2, genus 0, 12 vertices of valence 5"
    run "$b" info test/data/hexfan.obj
    is 0 && out_has '^boundary loops: 1$' && out_has '^boundary edges: 6$' && out_has '^genus: 0$' &&
        out_has '^valence interior: 6:1$' && out_has '^valence boundary: 3:6$'
    check $? "$name info hexfan.obj: 1 boundary loop, centre valence 6"
    run "$b" info test/data/cube_quad.obj
    is 0 && out_has '^face sizes: 4:6$' && out_has '^euler characteristic: 2 '
    check $? "$name info cube_quad.obj: 6 quads, chi 2"
done
run "$FLOAT" info test/data/icosahedron.obj
out_has '^arithmetic: float32$'; check $? "subd reports arithmetic float32"
run "$FIXED" info test/data/icosahedron.obj
out_has '^arithmetic: q16.16$'; check $? "subd-fixed reports arithmetic q16.16"
# Isolated vertices are accepted and do not distort the genus.
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv 5 5 5\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 4 3\n' > "$T/iso.obj"
run "$FLOAT" info "$T/iso.obj"
is 0 && out_has '^isolated vertices: 1$' && out_has '^euler characteristic: 3 ' && out_has '^genus: 0$' &&
    out_has '^components: 2 '
check $? "info tetrahedron + isolated vertex: chi 3, genus 0, 2 components"

# ---------------------------------------------------------------- convert round trips
for b in "$FLOAT" "$FIXED"; do
    name=$(basename "$b")
    for f in test/data/*.obj; do
        m=$(basename "$f" .obj)
        "$b" convert "$f" -o "$T/$m.a.obj" < /dev/null > /dev/null 2>&1 &&
            "$b" convert "$f" -o "$T/$m.off" < /dev/null > /dev/null 2>&1 &&
            "$b" convert "$T/$m.off" -o "$T/$m.b.obj" < /dev/null > /dev/null 2>&1 &&
            "$b" info "$f" < /dev/null 2>&1 | sed 1d > "$T/info1" &&
            "$b" info "$T/$m.b.obj" < /dev/null 2>&1 | sed 1d > "$T/info2" &&
            cmp -s "$T/info1" "$T/info2" && cmp -s "$T/$m.a.obj" "$T/$m.b.obj"
        check $? "$name convert $m: obj -> off -> obj keeps info and text"
    done
done
run "$FLOAT" convert test/data/hexfan.obj -o "$T/UPPER.OFF"
is 0 && [ "$(head -n 1 "$T/UPPER.OFF")" = OFF ]; check $? "convert: extension is case-insensitive (.OFF)"

# ---------------------------------------------------------------- render
for b in "$FLOAT" "$FIXED"; do
    name=$(basename "$b")
    run "$b" render test/data/torus_tri.obj -o "$T/t.png" --size 160x120 --yaw 45 --pitch -10 --no-edges
    is 0 && [ "$(od -An -tx1 -N8 "$T/t.png" | tr -d ' \n')" = 89504e470d0a1a0a ]
    check $? "$name render torus_tri.obj: file starts with the PNG signature"
done
run "$FLOAT" convert test/data/icosahedron.obj -o "$T/i.png"
is 0 && [ "$(od -An -tx1 -N8 "$T/i.png" | tr -d ' \n')" = 89504e470d0a1a0a ]
check $? "convert to .png renders a PNG"

# --with-input: the input drawn over the result. The limit and pia pictures of the
# icosahedron were byte-identical plain icosahedra; with the input they must differ (the
# limit points lie inside the control net, pia's control net outside the points), and the
# overlay changes the picture. Errors: not a mesh file (1), unreadable (2), no .png (1).
run "$FLOAT" limit test/data/icosahedron.obj --with-input test/data/icosahedron.obj --size 160x120 -o "$T/lim.png"
is 0; check $? "limit --with-input writes a picture"
run "$FLOAT" pia --tol 1e-5 test/data/icosahedron.obj --with-input test/data/icosahedron.obj --size 160x120 -q -o "$T/pia.png"
is 0 && [ ! -s "$T/err" ]; check $? "pia --with-input -q writes a picture, nothing on stderr"
run "$FLOAT" limit test/data/icosahedron.obj --size 160x120 -o "$T/lim0.png"
run cmp -s "$T/lim.png" "$T/pia.png"
is 1; check $? "limit and pia pictures with their input differ"
run cmp -s "$T/lim.png" "$T/lim0.png"
is 1; check $? "--with-input changes the picture"
run "$FLOAT" limit test/data/icosahedron.obj --no-labels --size 160x120 -o "$T/lim1.png"
run cmp -s "$T/lim0.png" "$T/lim1.png"
is 1; check $? "--no-labels changes the picture (captions are drawn by default)"
run "$FLOAT" render test/data/hexfan.obj --with-input "$T/x.txt" -o "$T/x.png"
is 1 && grep -q '^usage: subd' "$T/err"; check $? "--with-input not .obj/.off: usage error, exit 1"
run "$FLOAT" loop test/data/icosahedron.obj --with-input test/data/icosahedron.obj -o "$T/x.obj"
is 1 && grep -q 'need a .png output' "$T/err"; check $? "--with-input without a .png output: usage error, exit 1"
run "$FLOAT" render test/data/hexfan.obj --with-input "$T/missing.obj" -o "$T/x.png"
is 2 && err_starts "subd: cannot read '$T/missing.obj'"; check $? "--with-input unreadable: exit 2"
run "$FLOAT" render test/data/hexfan.obj --with-input test/bad/nan.obj -o "$T/x.png"
is 2 && err_starts "test/bad/nan.obj:"; check $? "--with-input bad mesh: FILE:LINE, exit 2"

# ---------------------------------------------------------------- progress and --quiet
# Progress goes to stderr only when it is a terminal. Redirected to a file, a long-ish run
# (about a second or more; the delay before the first line set to 0) prints nothing at all.
: > "$T/empty"
SUBD_PROGRESS_DELAY_MS=0 "$FLOAT" loop -l 5 --stream --stats demo/spot_triangulated.obj < /dev/null > "$T/out" 2> "$T/err"
rc=$?
is 0 && cmp -s "$T/err" "$T/empty"; check $? "progress: stderr redirected to a file stays empty (loop -l 5 --stream)"
"$FLOAT" loop -l 5 --stream --stats demo/spot_triangulated.obj < /dev/null > "$T/out" 2> "$T/err"
rc=$?
is 0 && cmp -s "$T/err" "$T/empty"; check $? "progress: stderr redirected, default delay: empty"
# Under a pseudo-terminal (script from util-linux) the line appears: phase, percent, done.
if command -v script > /dev/null 2>&1 && script -qec true /dev/null > /dev/null 2>&1; then
    SUBD_PROGRESS_DELAY_MS=0 script -qec "'$FLOAT' loop -l 4 --stream --stats test/data/icosahedron.obj" /dev/null \
        < /dev/null > "$T/out" 2> "$T/err"
    rc=$?
    is 0 && grep -q 'subd loop: ' "$T/out" && grep -q '100%' "$T/out" && grep -q '"command":"loop"' "$T/out"
    check $? "progress: under a terminal the progress line appears, ending at 100%"
    SUBD_PROGRESS_DELAY_MS=0 script -qec "'$FLOAT' loop -l 4 test/data/icosahedron.obj -o '$T/p.obj'" /dev/null \
        < /dev/null > "$T/out" 2> "$T/err"
    rc=$?
    is 0 && grep -q 'subd loop: ' "$T/out" && grep -q 'done' "$T/out"; check $? "progress: loop to .obj under a terminal"
    SUBD_PROGRESS_DELAY_MS=0 script -qec "'$FLOAT' loop -l 4 --stream --stats --quiet test/data/icosahedron.obj" \
        /dev/null < /dev/null > "$T/out" 2> "$T/err"
    rc=$?
    is 0 && ! grep -q 'subd loop: ' "$T/out" && grep -q '"command":"loop"' "$T/out"
    check $? "progress: --quiet removes it under a terminal"
else
    echo "ok - progress under a terminal: skipped (no working 'script' from util-linux)"
fi
run "$FLOAT" --help
is 0 && grep -q '^  -q, --quiet ' "$T/out" && grep -q '^  --with-input FILE ' "$T/out" && grep -q '^  --edges ' "$T/out"
check $? "--help lists --quiet, --with-input and --edges"

# ---------------------------------------------------------------- --stats
for b in "$FLOAT" "$FIXED"; do
    name=$(basename "$b")
    run "$b" info --stats test/data/torus_tri.obj
    keys=0
    for k in command scheme levels arithmetic input output arena_budget arena_planned arena_used time_ms; do
        grep -q "\"$k\":" "$T/out" || keys=1
    done
    planned=$(json_num arena_planned)
    used=$(json_num arena_used)
    is 0 && [ "$(wc -l < "$T/out")" -eq 1 ] && json_ok "$T/out" && [ $keys -eq 0 ] &&
        grep -q '"command":"info"' "$T/out" && grep -q '"output":null' "$T/out" &&
        [ -n "$planned" ] && [ -n "$used" ] && [ "$used" -le "$planned" ] && grep -q '^genus: 1$' "$T/err"
    check $? "$name info --stats: one valid JSON object on stdout (report on stderr)"
    run "$b" convert --stats test/data/spot_control_mesh.obj -o "$T/s.off"
    is 0 && [ "$(wc -l < "$T/out")" -eq 1 ] && json_ok "$T/out" &&
        grep -q '"output":{"file":"[^"]*s.off","format":"off"' "$T/out" && [ ! -s "$T/err" ]
    check $? "$name convert --stats: one valid JSON object, output described"
done
printf '{"a":[1,2,{"b":null}],"c":"x\\"y"}\n' > "$T/good.json"
printf '{"a":1,}\n' > "$T/bad1.json"
printf '{"a":1}\n{"b":2}\n' > "$T/bad2.json"
json_ok "$T/good.json" && ! json_ok "$T/bad1.json" && ! json_ok "$T/bad2.json"
check $? "the JSON checker itself accepts valid and rejects invalid JSON"

# ---------------------------------------------------------------- --arena
run "$FLOAT" info --arena 100 test/data/torus_tri.obj
need=$(sed -n 's/^subd: arena too small: needs \([0-9][0-9]*\) bytes, have 100$/\1/p' "$T/err")
is 3 && [ -n "$need" ] && [ "$need" -gt 100 ] && [ ! -s "$T/out" ]
check $? "info --arena 100: exit 3, says how many bytes are needed"
if [ -n "$need" ]; then
    run "$FLOAT" info --arena "$need" test/data/torus_tri.obj
    is 0; check $? "info --arena $need (exactly the need): exit 0"
    run "$FIXED" info --arena $((need - 1)) test/data/torus_tri.obj
    is 3; check $? "subd-fixed info --arena $((need - 1)): exit 3 (same need in q16.16)"
fi
run "$FLOAT" info --arena 64k --stats test/data/icosahedron.obj
is 0 && grep -q '"arena_budget":65536' "$T/out"; check $? "--arena accepts a k suffix"

# ---------------------------------------------------------------- scheme commands
# Counts checked against closed forms (Loop: V' = V + E, F' = 4F; Doo-Sabin: V' = corners,
# F' = F + E + V on a closed mesh), geometry against known shapes.
run "$FLOAT" loop -l 2 test/data/icosahedron.obj -o "$T/ico2.obj" --stats
is 0 && json_ok "$T/out" && [ "$(json_num vertices)" = 162 ] && [ "$(json_num faces)" = 320 ] &&
    [ "$(json_num arena_planned)" = "$(json_num arena_used)" ]
check $? "loop -l 2 icosahedron: 162 vertices, 320 faces, arena used = planned"
run "$FIXED" loop -l 2 --boundary bspline test/data/hexfan.obj -o "$T/hex2.off"
is 0 && [ "$(sed -n 2p "$T/hex2.off" | cut -d' ' -f1-2)" = "61 96" ]
check $? "subd-fixed loop -l 2 --boundary bspline hexfan: 61 vertices, 96 faces"
run "$FLOAT" loop -l 1 --crease-angle 60 demo/cube_tri.obj -o "$T/cube1.obj"
is 0 && grep -q "^subd: 12 crease edge" "$T/err"; check $? "loop --crease-angle 60 on a triangulated cube tags its 12 cube edges, not the diagonals"
# --tags FILE: the cube's 12 edges, found here from the coordinates (vertex pairs that differ in
# exactly one coordinate), as a tag file give the same output as --crease-angle 60.
awk '/^v /{n++; x[n]=$2; y[n]=$3; z[n]=$4}
     END{print "# cube edges"; for(i=1;i<=n;i++) for(j=i+1;j<=n;j++)
         if ((x[i]!=x[j])+(y[i]!=y[j])+(z[i]!=z[j]) == 1) print "crease", i, j}' demo/cube_tri.obj > "$T/cube.tags"
run "$FLOAT" loop -l 2 --crease-angle 60 demo/cube_tri.obj -o "$T/cube_angle.obj"
run "$FLOAT" loop -l 2 --tags "$T/cube.tags" demo/cube_tri.obj -o "$T/cube_tags.obj"
is 0 && [ "$(grep -c '^crease' "$T/cube.tags")" = 12 ] && grep -q "12 crease edge(s), 0 vertex tag(s)" "$T/err" &&
    cmp -s "$T/cube_angle.obj" "$T/cube_tags.obj"; check $? "loop --tags with the cube's 12 edges = --crease-angle 60"
# corner and fixed vertices do not move (vertex i of the input is vertex i of the output)
printf 'corner 1\n' > "$T/c1.tags"
run "$FLOAT" loop -l 2 --tags "$T/c1.tags" test/data/icosahedron.obj -o "$T/ico_c.obj"
v_in=$(grep -m1 '^v ' test/data/icosahedron.obj | awk '{print $2+0, $3+0, $4+0}')
v_out=$(grep -m1 '^v ' "$T/ico_c.obj" | awk '{print $2+0, $3+0, $4+0}')
v_free=$(run "$FLOAT" loop -l 2 test/data/icosahedron.obj -o "$T/ico_f.obj"; grep -m1 '^v ' "$T/ico_f.obj" | awk '{print $2+0, $3+0, $4+0}')
is 0 && [ "$v_in" = "$v_out" ] && [ "$v_in" != "$v_free" ]; check $? "loop --tags 'corner 1': vertex 1 stays ($v_in), untagged it moves"
printf 'fixed 1\n' > "$T/f1.tags"
run "$FIXED" convert test/data/icosahedron.obj -o "$T/ico_q0.obj" # the input as Q16.16 reads it
v_in=$(grep -m1 '^v ' "$T/ico_q0.obj")
run "$FIXED" quasi48 -l 2 --tags "$T/f1.tags" test/data/icosahedron.obj -o "$T/ico_q.obj"
v_out=$(grep -m1 '^v ' "$T/ico_q.obj")
is 0 && [ -n "$v_in" ] && [ "$v_in" = "$v_out" ]; check $? "subd-fixed quasi48 --tags 'fixed 1': vertex 1 stays ($v_in)"
# tag file errors: FILE:LINE, exit 2, no output written, nothing applied
printf 'corner 1\ncrease 1 2 3\n' > "$T/bad1.tags"
rm -f "$T/x.obj"; run "$FLOAT" loop --tags "$T/bad1.tags" test/data/icosahedron.obj -o "$T/x.obj"
is 2 && err_starts "$T/bad1.tags:2: expected" && [ ! -e "$T/x.obj" ]; check $? "--tags with a malformed line: exit 2, FILE:LINE, no output"
printf 'fixed 13\n' > "$T/bad2.tags"
run "$FLOAT" loop --tags "$T/bad2.tags" test/data/icosahedron.obj -o "$T/x.obj"
is 2 && err_starts "$T/bad2.tags:1: expected" && grep -q "1..12" "$T/err"; check $? "--tags with a vertex number out of range: exit 2"
a1=$(awk '/^f /{for(i=2;i<=4;i++){split($i,p,"/"); if(p[1]==1) s=1} if(s){for(i=2;i<=4;i++){split($i,p,"/"); e[p[1]]=1}} s=0} END{for(v=2;v<=12;v++) if(!(v in e)){print v; exit}}' test/data/icosahedron.obj)
printf 'crease 1 %s\n' "$a1" > "$T/bad3.tags"
run "$FLOAT" loop --tags "$T/bad3.tags" test/data/icosahedron.obj -o "$T/x.obj"
is 2 && err_starts "$T/bad3.tags:1: vertices 1 and $a1 share no edge"; check $? "--tags naming two vertices without an edge (1, $a1): exit 2"
run "$FLOAT" loop --tags "$T/missing.tags" test/data/icosahedron.obj -o "$T/x.obj"
is 2 && err_starts "subd: cannot read tag file"; check $? "--tags with a missing file: exit 2"
run "$FLOAT" semireg48 --tags "$T/c1.tags" test/data/icosahedron.obj -o "$T/x.obj"
is 1; check $? "--tags on a command that does not use tags (semireg48): exit 1"
run "$FLOAT" loop test/data/cube_quad.obj -o "$T/x.obj"
is 2 && err_starts "test/data/cube_quad.obj:11: not a triangle mesh (face 0)"; check $? "loop on quads: exit 2, FILE:LINE of the first quad"
# every triangle scheme (and the stream) names the first polygon, face 4 on line 13 (OFF: 14)
printf '# four triangles and a quad\nv 0 0 0\nv 1 0 0\nv 0.5 0.875 0\nv -0.5 0.875 0\nv -1 0 0\nv -0.5 -0.875 0\nv 0.5 -0.875 0\nf 1 2 3\nf 1 3 4\nf 1 4 5\nf 1 5 6\nf 1 6 7 2\n' > "$T/tri4q.obj"
printf 'OFF\n7 5 0\n0 0 0\n1 0 0\n0.5 0.875 0\n-0.5 0.875 0\n-1 0 0\n-0.5 -0.875 0\n0.5 -0.875 0\n3 0 1 2\n3 0 2 3\n3 0 3 4\n3 0 4 5\n4 0 5 6 1\n' > "$T/tri4q.off"
for args in "loop" "loop --stream" "limit" "pia --tol 0.01" "quasi48" "semireg48 -l 2"; do
    for b in "$FLOAT" "$FIXED"; do
        # shellcheck disable=SC2086
        run "$b" $args "$T/tri4q.obj" -o "$T/x.obj"
        is 2 && err_starts "$T/tri4q.obj:13: not a triangle mesh (face 4)"; check $? "$(basename "$b") $args on 4 triangles + a quad: exit 2, FILE:13 (face 4)"
    done
done
run "$FLOAT" loop "$T/tri4q.off" -o "$T/x.off"
is 2 && err_starts "$T/tri4q.off:14: not a triangle mesh (face 4)"; check $? "loop on an OFF with a quad: exit 2, FILE:14 (face 4)"
run "$FLOAT" quasi48 -l 2 demo/torus_12x6.obj -o "$T/q.obj" --stats
is 0 && json_ok "$T/out" && [ "$(json_num faces)" = 576 ]; check $? "quasi48 -l 2 on the 12x6 torus: every face split twice (576)"
usage_case_pre() { run "$FLOAT" "$@"; is 1; }
# semi-regular 4-8: level 0 of a triangle mesh with C two-face clusters and T = F - 2C isolated
# triangles has V + C + T + (E - C) = V + T + E vertices (a face point per cluster and per
# isolated triangle, an edge point per edge that is not a cluster diagonal) and 8C + 6T faces
# (section 5); each binary step doubles
# the faces; adaptive meshes are valid meshes with fewer faces than the uniform level.
run "$FLOAT" semireg48 -l 0 test/data/icosahedron.obj -o "$T/sr0.obj" --stats
c=$(json_num clusters) ti=$(json_num isolated_triangles)
is 0 && json_ok "$T/out" && [ $((2 * c + ti)) = 20 ] && [ "$(json_num faces)" = $((8 * c + 6 * ti)) ] &&
    [ "$(sed -n 's/.*"output":{[^}]*"vertices":\([0-9]*\).*/\1/p' "$T/out")" = $((12 + ti + 30)) ] &&
    [ "$(json_num arena_planned)" = "$(json_num arena_used)" ]
check $? "semireg48 -l 0 icosahedron: V + T + E vertices, 8C + 6T faces, arena used = planned"
run "$FIXED" semireg48 -l 3 test/data/icosahedron.obj -o "$T/sr3.obj" --stats
is 0 && [ "$(json_num faces)" = $((8 * (8 * c + 6 * ti))) ] && [ "$(json_num arena_planned)" = "$(json_num arena_used)" ]
check $? "subd-fixed semireg48 -l 3 icosahedron: 2^3 x the level-0 faces, arena used = planned"
# semireg48 --stream: the same triangles as semireg48 (faces expanded to their corner
# coordinates, which both write with the library's formatter), in a stream arena of its own
off_faces() { awk 'NR==2{nv=$1} NR>2 && NR<=2+nv{v[NR-3]=$1" "$2" "$3} NR>2+nv{print v[$2]" | "v[$3]" | "v[$4]}' "$1" | sort; }
for bin in "$FLOAT" "$FIXED"; do
    for l in 0 3; do
        run "$bin" semireg48 -l $l test/data/icosahedron.obj -o "$T/srm.off"
        run "$bin" semireg48 --stream --stats -l $l test/data/icosahedron.obj -o "$T/srs.off"
        is 0 && [ "$(json_num stream_arena)" -gt 0 ] && [ "$(json_num arena_planned)" = "$(json_num arena_used)" ] &&
            [ "$(off_faces "$T/srm.off")" = "$(off_faces "$T/srs.off")" ]
        check $? "$(basename "$bin") semireg48 --stream -l $l: semireg48's triangles, arena used = planned"
    done
done
# a base whose extraordinary vertices are close (three valence-9 vertices in a triangle): the
# stream's windows are sized by the base's census (stream_valence above the valence rule's 9 x 2)
for bin in "$FLOAT" "$FIXED"; do
    run "$bin" sr48 -l 2 test/data/dense_ico.obj -o "$T/srdm.off"
    run "$bin" sr48 --stream --stats -l 2 test/data/dense_ico.obj -o "$T/srds.off"
    is 0 && [ "$(json_num stream_valence)" -gt 8 ] && [ "$(off_faces "$T/srdm.off")" = "$(off_faces "$T/srds.off")" ]
    check $? "$(basename "$bin") sr48 --stream -l 2 dense_ico: sr48's triangles, stream_valence in --stats"
done
run "$FLOAT" semireg48 --stream -l 2 test/data/icosahedron.obj -o "$T/srs.stl"
is 0 && [ "$(wc -c < "$T/srs.stl")" = $((84 + 50 * 8 * (8 * c + 6 * ti) / 2)) ]
check $? "semireg48 --stream -o .stl: 84 + 50 bytes per triangle"
usage_case_pre semireg48 --stream --limit -l 2 test/data/icosahedron.obj -o "$T/x.stl"; check $? "semireg48 --stream --limit: exit 1"
run "$FLOAT" adapt -l 6 --chord 0.01 demo/torus_12x6.obj -o "$T/ad.obj" --stats
is 0 && json_ok "$T/out" && [ "$(json_num uniform_faces)" = 36864 ] &&
    [ "$(json_num faces)" -lt 36864 ] && [ "$(json_num saved_faces)" = $((36864 - $(json_num faces))) ] &&
    [ "$(sed -n 's/.*"output":{[^}]*"boundary_edges":\([0-9]*\).*/\1/p' "$T/out")" = 0 ]
check $? "adapt --chord on the torus: closed output, fewer faces than uniform level 6, saved = uniform - faces"
run "$FLOAT" info "$T/ad.obj"
is 0 && grep -q '^genus: 1$' "$T/out"; check $? "adapt output reads back as a valid genus-1 mesh"
for mode in "--point 1.4,0,0" "--ramp z" "--plane 0,0,0,1,0,0"; do
    run "$FIXED" adapt -l 4 $mode demo/torus_12x6.obj -o "$T/am.off" --stats
    is 0 && [ "$(json_num faces)" -lt "$(json_num uniform_faces)" ]; check $? "subd-fixed adapt -l 4 $mode: fewer faces than uniform"
done
# adapt --stream: subd_sr48_stream's cut = subd_sr48_extract's (same face set, corner
# coordinates as the library formats them), in a stream arena of its own; .stl by its size
obj_faces() { awk '$1=="v"{v[++n]=$2" "$3" "$4} $1=="f"{split($2,a,"/");split($3,b,"/");split($4,c,"/");print v[a[1]]" | "v[b[1]]" | "v[c[1]]}' "$1" | sort; }
for bin in "$FLOAT" "$FIXED"; do
    for mode in "--point 1.4,0,0" "--point 1.4,0,0 --radius 0.3" "--ramp z" "--plane 0,0,0,1,0,0"; do
        run "$bin" adapt -l 4 $mode demo/torus_12x6.obj -o "$T/am.off" --stats
        nf=$(json_num faces) nu=$(json_num uniform_faces)
        run "$bin" adapt --stream -l 4 $mode demo/torus_12x6.obj -o "$T/as.off" --stats
        is 0 && [ "$(json_num stream_arena)" -gt 0 ] && [ "$(json_num faces)" = "$nf" ] && [ "$nf" -lt "$nu" ] &&
            [ "$(json_num uniform_faces)" = "$nu" ] && [ "$(json_num saved_faces)" = $((nu - nf)) ] &&
            [ "$(off_faces "$T/am.off")" = "$(off_faces "$T/as.off")" ]
        check $? "$(basename "$bin") adapt --stream -l 4 $mode -o .off: adapt's face set, --stats faces and stream_arena"
        run "$bin" adapt --stream -l 4 $mode demo/torus_12x6.obj -o "$T/as.obj"
        is 0 && [ "$(off_faces "$T/am.off")" = "$(obj_faces "$T/as.obj")" ]
        check $? "$(basename "$bin") adapt --stream -l 4 $mode -o .obj: adapt's face set"
        run "$bin" adapt --stream -l 4 $mode demo/torus_12x6.obj -o "$T/as.stl"
        is 0 && [ "$(wc -c < "$T/as.stl")" = $((84 + 50 * nf)) ]
        check $? "$(basename "$bin") adapt --stream -l 4 $mode -o .stl: 84 + 50 bytes per face of adapt's cut"
    done
done
# adapt --stream --chord: subd_sr48_stream's chordal cut (not subd_sr48_extract's exact one,
# but containing it: at least its faces, fewer than uniform). Every output format gets the same
# triangles (.obj = .off face sets, .stl by its size, one checksum with and without -o); the
# .obj (vertices by id) reads back as a closed genus-1 mesh: welded by id, crack-free. On the
# icosahedron: every vertex of the uniform level-4 cut (all hierarchy vertices) lies within
# eps of the streamed triangles (brute force in awk, double; slack 1e-6, Q16.16 4 / 65536).
tri_dist_check() { # EPS SLACK UNIFORM.off STREAM.obj: exit 0 when every vertex is within EPS + SLACK
    awk -v eps="$1" -v slack="$2" '
        FNR == 1 { file++ }
        file == 1 && FNR == 2 { nv = $1 }
        file == 1 && FNR > 2 && FNR <= 2 + nv { px[++np] = $1; py[np] = $2; pz[np] = $3 }
        file == 2 && $1 == "v" { vx[++n] = $2; vy[n] = $3; vz[n] = $4 }
        file == 2 && $1 == "f" { split($2, a, "/"); split($3, b, "/"); split($4, c, "/"); ta[++nt] = a[1]; tb[nt] = b[1]; tc[nt] = c[1] }
        function closest(x, y, z, A, B, C,   abx, aby, abz, acx, acy, acz, apx, apy, apz, bpx, bpy, bpz, cpx, cpy, cpz, d1, d2_, d3, d4, d5, d6, va, vb, vc, v, w, den, qx, qy, qz) {
            abx = vx[B] - vx[A]; aby = vy[B] - vy[A]; abz = vz[B] - vz[A]
            acx = vx[C] - vx[A]; acy = vy[C] - vy[A]; acz = vz[C] - vz[A]
            apx = x - vx[A]; apy = y - vy[A]; apz = z - vz[A]
            bpx = x - vx[B]; bpy = y - vy[B]; bpz = z - vz[B]
            cpx = x - vx[C]; cpy = y - vy[C]; cpz = z - vz[C]
            d1 = abx * apx + aby * apy + abz * apz; d2_ = acx * apx + acy * apy + acz * apz
            d3 = abx * bpx + aby * bpy + abz * bpz; d4 = acx * bpx + acy * bpy + acz * bpz
            d5 = abx * cpx + aby * cpy + abz * cpz; d6 = acx * cpx + acy * cpy + acz * cpz
            if (d1 <= 0 && d2_ <= 0) { qx = vx[A]; qy = vy[A]; qz = vz[A] }
            else if (d3 >= 0 && d4 <= d3) { qx = vx[B]; qy = vy[B]; qz = vz[B] }
            else if (d6 >= 0 && d5 <= d6) { qx = vx[C]; qy = vy[C]; qz = vz[C] }
            else if ((vc = d1 * d4 - d3 * d2_) <= 0 && d1 >= 0 && d3 <= 0) { v = d1 / (d1 - d3); qx = vx[A] + v * abx; qy = vy[A] + v * aby; qz = vz[A] + v * abz }
            else if ((vb = d5 * d2_ - d1 * d6) <= 0 && d2_ >= 0 && d6 <= 0) { w = d2_ / (d2_ - d6); qx = vx[A] + w * acx; qy = vy[A] + w * acy; qz = vz[A] + w * acz }
            else if ((va = d3 * d6 - d5 * d4) <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) { w = (d4 - d3) / ((d4 - d3) + (d5 - d6)); qx = vx[B] + w * (vx[C] - vx[B]); qy = vy[B] + w * (vy[C] - vy[B]); qz = vz[B] + w * (vz[C] - vz[B]) }
            else { den = 1 / (va + vb + vc); v = vb * den; w = vc * den; qx = vx[A] + abx * v + acx * w; qy = vy[A] + aby * v + acy * w; qz = vz[A] + abz * v + acz * w }
            return (x - qx) * (x - qx) + (y - qy) * (y - qy) + (z - qz) * (z - qz)
        }
        END {
            if (np == 0 || nt == 0) exit 1
            lim = (eps + slack) * (eps + slack)
            for (i = 1; i <= np; i++) {
                best = 1e300
                for (t = 1; t <= nt && best > lim; t++) { dd = closest(px[i], py[i], pz[i], ta[t], tb[t], tc[t]); if (dd < best) best = dd }
                if (best > lim) { printf "vertex %d at %g from the cut\n", i, sqrt(best) > "/dev/stderr"; exit 1 }
            }
            exit 0
        }' "$3" "$4"
}
for bin in "$FLOAT" "$FIXED"; do
    name=$(basename "$bin")
    run "$bin" adapt -l 4 --chord 0.02 demo/torus_12x6.obj -o "$T/cm.off" --stats
    nx=$(json_num faces) nu=$(json_num uniform_faces)
    run "$bin" adapt --stream -l 4 --chord 0.02 demo/torus_12x6.obj -o "$T/cs.off" --stats
    nf=$(json_num faces) sum=$(sed -n 's/.*"checksum":"\([0-9a-f]*\)".*/\1/p' "$T/out")
    is 0 && [ "$(json_num stream_arena)" -gt 0 ] && [ -n "$nx" ] && [ "$nf" -ge "$nx" ] && [ "$nf" -lt "$nu" ] &&
        [ "$(json_num uniform_faces)" = "$nu" ] && [ "$(json_num saved_faces)" = $((nu - nf)) ] && grep -q '"adapt":"chord"' "$T/out"
    check $? "$name adapt --stream --chord 0.02 -l 4 torus -o .off: $nf faces, at least adapt --chord's $nx, fewer than uniform $nu"
    run "$bin" adapt --stream -l 4 --chord 0.02 demo/torus_12x6.obj -o "$T/cs.obj" --stats
    is 0 && [ "$(json_num faces)" = "$nf" ] && grep -q "\"checksum\":\"$sum\"" "$T/out" &&
        [ "$(off_faces "$T/cs.off")" = "$(obj_faces "$T/cs.obj")" ]
    check $? "$name adapt --stream --chord -o .obj: the .off's face set and checksum"
    run "$bin" adapt --stream -l 4 --chord 0.02 demo/torus_12x6.obj -o "$T/cs.stl" --stats
    is 0 && [ "$(wc -c < "$T/cs.stl")" = $((84 + 50 * nf)) ] && grep -q "\"checksum\":\"$sum\"" "$T/out"
    check $? "$name adapt --stream --chord -o .stl: its count first (a counting pass), 84 + 50 x $nf bytes, same checksum"
    run "$bin" adapt --stream -l 4 --chord 0.02 demo/torus_12x6.obj --stats
    is 0 && [ "$(json_num faces)" = "$nf" ] && grep -q "\"checksum\":\"$sum\"" "$T/out"
    check $? "$name adapt --stream --chord --stats without -o: the same faces and checksum"
    run "$bin" info "$T/cs.obj"
    is 0 && grep -q '^genus: 1$' "$T/out" && grep -q '^boundary edges: 0$' "$T/out" && grep -q "^faces: $nf$" "$T/out"
    check $? "$name adapt --stream --chord .obj welded by id: a closed genus-1 mesh (crack-free)"
    slack=0.000001
    [ "$bin" = "$FIXED" ] && slack=0.00006104
    run "$bin" semireg48 -l 4 test/data/icosahedron.obj -o "$T/cu.off"
    run "$bin" adapt --stream -l 4 --chord 0.05 test/data/icosahedron.obj -o "$T/ci.obj" --stats
    ni=$(json_num faces)
    is 0 && [ "$ni" -lt "$(json_num uniform_faces)" ] && tri_dist_check 0.05 $slack "$T/cu.off" "$T/ci.obj" 2> "$T/err"
    check $? "$name adapt --stream --chord 0.05 -l 4 icosahedron: every level-4 vertex within eps of the $ni streamed faces"
    # semireg48 --stream in every output format: semireg48's triangles, one checksum, --stats counts
    run "$bin" semireg48 -l 3 test/data/icosahedron.obj -o "$T/sm.off" --stats
    nm=$(json_num faces)
    ok=0 sum=
    for fmt in off obj stl none; do
        if [ $fmt = none ]; then run "$bin" semireg48 --stream -l 3 test/data/icosahedron.obj --stats
        else run "$bin" semireg48 --stream -l 3 test/data/icosahedron.obj -o "$T/ss.$fmt" --stats; fi
        s1=$(sed -n 's/.*"checksum":"\([0-9a-f]*\)".*/\1/p' "$T/out")
        { is 0 && [ "$(json_num triangles)" = "$nm" ] && [ "$(json_num uniform_faces)" = "$nm" ] &&
            [ "$(json_num saved_faces)" = 0 ] && [ "$(json_num stream_arena)" -gt 0 ] && [ -n "$s1" ] &&
            { [ -z "$sum" ] || [ "$s1" = "$sum" ]; }; } || ok=1
        sum=$s1
    done
    [ $ok = 0 ] && [ "$(off_faces "$T/sm.off")" = "$(off_faces "$T/ss.off")" ] &&
        [ "$(off_faces "$T/sm.off")" = "$(obj_faces "$T/ss.obj")" ] && [ "$(wc -c < "$T/ss.stl")" = $((84 + 50 * nm)) ]
    check $? "$name semireg48 --stream -l 3 -o .off/.obj/.stl/none: semireg48's $nm triangles, one checksum, --stats counts"
done
usage_case_pre adapt -l 4 demo/torus_12x6.obj -o "$T/x.obj"; check $? "adapt without a mode: exit 1"
usage_case_pre adapt -l 4 --ramp w demo/torus_12x6.obj -o "$T/x.obj"; check $? "adapt --ramp w: exit 1"
usage_case_pre adapt -l 4 --ramp x --chord 1 demo/torus_12x6.obj -o "$T/x.obj"; check $? "adapt with two modes: exit 1"
usage_case_pre adapt -l 4 --chord 0 demo/torus_12x6.obj -o "$T/x.obj"; check $? "adapt --chord 0: exit 1"
usage_case_pre adapt -l 4 --plane 0,0,0,0,0,0 demo/torus_12x6.obj -o "$T/x.obj"; check $? "adapt --plane with a zero normal: exit 1"
usage_case_pre adapt -l 4 --ramp x --radius 1 demo/torus_12x6.obj -o "$T/x.obj"; check $? "adapt --radius without --point: exit 1"
usage_case_pre semireg48 -l 17 test/data/icosahedron.obj -o "$T/x.obj"; check $? "semireg48 -l 17 (above 2 x SUBD_MAX_LEVELS): exit 1"
usage_case_pre semireg48 --chord 1 test/data/icosahedron.obj -o "$T/x.obj"; check $? "semireg48 --chord (an adapt option): exit 1"
run "$FLOAT" semireg48 -l 2 test/data/cube_quad.obj -o "$T/x.obj"
is 2 && err_starts "test/data/cube_quad.obj"; check $? "semireg48 on quads: exit 2 naming the input"
run "$FLOAT" semireg48 -l 2 --arena 20k test/data/icosahedron.obj -o "$T/x.obj"
is 3 && grep -q "needs" "$T/err"; check $? "semireg48 --arena 20k: exit 3, says how many bytes it needs"
run "$FLOAT" alpha --kernel cos --alpha 1/4 -l 5 demo/square.obj -o "$T/circle.xyz"
is 0 && awk 'BEGIN { n = 0 } NF == 3 { x[n] = $1; y[n] = $2; n++ }
    END { if (n != 129 || x[0] != x[128] || y[0] != y[128]) exit 1
          for (i = 0; i + 1 < n; i++) { j = i + 1; mx = (x[i] + x[j]) / 2; my = (y[i] + y[j]) / 2
              r = sqrt(mx * mx + my * my); if (r < 1 - 1e-6 || r > 1 + 1e-6) exit 1 }
          exit 0 }' "$T/circle.xyz"
check $? "alpha cos kernel on the square: 128 points (closed), every edge midpoint on the unit circle"
run "$FLOAT" alpha -l 1 test/data/cube_quad.obj -o "$T/ds.obj" --stats
is 0 && [ "$(json_num vertices)" = 24 ] && [ "$(json_num faces)" = 26 ]; check $? "alpha (Doo-Sabin type) on the cube: 24 vertices, 26 faces"
run "$FLOAT" alpha --order 3 -l 1 test/data/cube_quad.obj -o "$T/cc.obj" --stats
is 0 && [ "$(json_num vertices)" = 26 ] && [ "$(json_num faces)" = 24 ]; check $? "alpha --order 3 on the cube: Catmull-Clark counts, 26 vertices, 24 faces"
run "$FLOAT" limit --normals test/data/icosahedron.obj -o "$T/lim.obj"
is 0 && [ "$(grep -c '^vn ' "$T/lim.obj")" = 12 ]; check $? "limit --normals: one vn per vertex"
run "$FLOAT" pia --tol 1e-4 test/data/icosahedron.obj -o "$T/pia.obj" --stats
is 0 && json_ok "$T/out" && grep -q '"converged":true' "$T/out"; check $? "pia --tol 1e-4 on the icosahedron converges"
usage_case_pre loop --boundary sideways test/data/icosahedron.obj -o "$T/x.obj"; check $? "loop --boundary sideways: exit 1"
usage_case_pre quasi48 --boundary paper test/data/icosahedron.obj -o "$T/x.obj"; check $? "quasi48 --boundary paper: exit 1"
usage_case_pre alpha --stiffness -1 demo/square.obj -o "$T/x.obj"; check $? "alpha --stiffness -1 (diverges): exit 1"
usage_case_pre alpha --stiffness -0.5 demo/square.obj -o "$T/x.obj"; check $? "alpha --stiffness -0.5 (diverges): exit 1"
run "$FLOAT" --help
is 0 && grep -q 's <= -1/2 diverges' "$T/out" && ! grep -q 's <= -1 diverges' "$T/out"
check $? "--help: --stiffness says s <= -1/2 diverges, as the code refuses"
# one grammar for --alpha and a tag file's alpha lines (subd_tags_parse_alpha): no exponent
usage_case_pre alpha --alpha 4.5e1deg demo/square.obj -o "$T/x.obj"; check $? "alpha --alpha 4.5e1deg (an exponent): exit 1"
usage_case_pre alpha --alpha 45.00001deg demo/square.obj -o "$T/x.obj"; check $? "alpha --alpha 45.00001deg (5 decimals): exit 1"
printf 'alpha 1 4.5e1deg\n' > "$T/exp.tags"
run "$FLOAT" alpha --tags "$T/exp.tags" demo/square.obj -o "$T/x.obj"
is 2 && grep -q "exp.tags:1: expected" "$T/err"; check $? "a tag file's alpha 4.5e1deg (an exponent): exit 2, FILE:LINE, as --alpha"
run "$FLOAT" alpha --kernel cos --alpha 1/8 -l 3 demo/square.obj -o "$T/a8.xyz"
run "$FLOAT" alpha --kernel cos --alpha 45deg -l 3 demo/square.obj -o "$T/a45.xyz"
is 0 && cmp -s "$T/a8.xyz" "$T/a45.xyz"; check $? "alpha --alpha 45deg = --alpha 1/8, byte for byte (one reduced value)"
usage_case_pre pia test/data/icosahedron.obj -o "$T/x.obj"; check $? "pia without --tol: exit 1"
run "$FIXED" pia --tol 1e-6 test/data/icosahedron.obj -o "$T/x.obj"
is 1 && grep -q "below what Q16.16 can resolve" "$T/err"; check $? "subd-fixed pia --tol 1e-6: exit 1, says Q16.16 cannot resolve it"
usage_case_pre loop --tol 1 test/data/icosahedron.obj -o "$T/x.obj"; check $? "loop --tol (not its option): exit 1"

# ---------------------------------------------------------------- loop --stream
# The stream (subd_loop_stream) against subd_loop through the tool: test/tools/tri_dump.c prints
# every corner of a .stl/.obj/.off in face order as float32 bits, so the stream's triangles must
# be subd_loop's, in the same order, with bit-identical coordinates, whatever the format.
TRI_DUMP=$T/tri_dump
CC_TEST=${CC:-cc}
command -v "$CC_TEST" > /dev/null 2>&1 || CC_TEST=gcc
"$CC_TEST" -std=c99 -O1 -o "$TRI_DUMP" test/tools/tri_dump.c -lm > "$T/cc.log" 2>&1
rc=$?; : > "$T/out"; cp "$T/cc.log" "$T/err"
is 0; check $? "test/tools/tri_dump.c compiles with $CC_TEST"
dump() { "$TRI_DUMP" "$@" 2>> "$T/err"; }
for b in "$FLOAT" "$FIXED"; do
    name=$(basename "$b")
    # mesh, options, faces: closed, open (both boundary rules), creases
    for case in "test/data/icosahedron.obj||20" "test/data/hexfan.obj|--boundary bspline|6" \
        "test/data/grid_tri_8x8.obj||128" "demo/cube_tri.obj|--crease-angle 60|12"; do
        m=${case%%|*} rest=${case#*|}
        opts=${rest%|*} f=${rest##*|}
        mb=$(basename "$m" .obj)
        "$b" loop -l 2 $opts "$m" -o "$T/ref.obj" < /dev/null > /dev/null 2>&1
        "$b" loop -l 2 $opts "$m" -o "$T/ref.off" < /dev/null > /dev/null 2>&1
        run "$b" loop -l 2 $opts --stream "$m" -o "$T/s.stl"
        is 0 && [ "$(wc -c < "$T/s.stl")" -eq $((84 + 50 * 16 * f)) ]
        check $? "$name loop -l 2 --stream $mb -o .stl: 84 + 50 x 4^2 x $f bytes"
        dump "$T/s.stl" > "$T/s.tri" && dump "$T/ref.obj" > "$T/ref.tri" && cmp -s "$T/s.tri" "$T/ref.tri" &&
            sort -u "$T/s.tri" > "$T/s.set" && dump -v "$T/ref.obj" | sort -u > "$T/ref.set" && cmp -s "$T/s.set" "$T/ref.set"
        check $? "$name --stream $mb .stl: subd_loop's triangles in order, float32 bit for bit; vertex set = ref v lines"
        run "$b" loop -l 2 $opts --stream "$m" -o "$T/s.obj"
        is 0 && [ "$(grep -c '^v ' "$T/s.obj")" = "$(grep -c '^v ' "$T/ref.obj")" ] &&
            [ "$(grep -c '^f ' "$T/s.obj")" = "$(grep -c '^f ' "$T/ref.obj")" ] &&
            dump "$T/s.obj" > "$T/so.tri" && cmp -s "$T/so.tri" "$T/ref.tri"
        check $? "$name --stream $mb .obj: as many v and f lines as loop's .obj, same triangles and bits"
        run "$b" loop -l 2 $opts --stream "$m" -o "$T/s.off"
        is 0 && [ "$(sed -n 2p "$T/s.off")" = "$(sed -n 2p "$T/ref.off")" ] && dump "$T/s.off" > "$T/sf.tri" &&
            cmp -s "$T/sf.tri" "$T/ref.tri"
        check $? "$name --stream $mb .off: loop's counts line, same triangles and bits"
    done
    m=test/data/hexfan.obj
    # --limit: limit positions and normals = 'limit --normals' of loop's level-2 output
    "$b" loop -l 2 "$m" -o "$T/ref.obj" < /dev/null > /dev/null 2>&1
    "$b" limit --normals "$T/ref.obj" -o "$T/lim.obj" < /dev/null > /dev/null 2>&1
    run "$b" loop -l 2 --stream --limit "$m" -o "$T/sl.obj"
    is 0 && [ "$(grep -c '^vn ' "$T/sl.obj")" = "$(grep -c '^v ' "$T/sl.obj")" ] && [ "$(grep -c '^vn ' "$T/sl.obj")" -gt 0 ] &&
        grep -q '^f [0-9]*//[0-9]* ' "$T/sl.obj" && dump "$T/sl.obj" > "$T/sl.tri" && dump "$T/lim.obj" > "$T/lim.tri" &&
        cmp -s "$T/sl.tri" "$T/lim.tri"
    check $? "$name loop --stream --limit -o .obj: a vn per v, f a//a, = limit --normals of loop's output bit for bit"
    run "$b" loop -l 2 --stream --limit "$m" -o "$T/sl.stl"
    is 0 && [ "$(wc -c < "$T/sl.stl")" -eq $((84 + 50 * 16 * 6)) ] && dump "$T/sl.stl" > "$T/sls.tri" &&
        sed 's/ [0-9a-f]* [0-9a-f]* [0-9a-f]*$//' "$T/lim.tri" | cmp -s - "$T/sls.tri"
    check $? "$name loop --stream --limit -o .stl: limit positions, facet normals of the triangles"
    # --stats: with no -o a counting sink; the same stream gives the same checksum with -o
    run "$b" loop -l 3 --stream --stats test/data/icosahedron.obj -o "$T/s3.stl"
    sum=$(sed -n 's/.*"checksum":"\([0-9a-f]*\)".*/\1/p' "$T/out")
    planned=$(json_num arena_planned)
    is 0 && json_ok "$T/out" && grep -q '"output":{"file":"[^"]*s3.stl","format":"stl","bytes":64084,' "$T/out" &&
        [ "$(json_num triangles)" = 1280 ] && [ "$(json_num arena_used)" -le "$planned" ]
    check $? "$name loop --stream --stats -o .stl: output described (64084 bytes), 1280 triangles, used <= planned"
    run "$b" loop -l 3 --stream --stats test/data/icosahedron.obj
    keys=0
    for k in command scheme levels arithmetic input output arena_budget arena_planned arena_used time_ms; do
        grep -q "\"$k\":" "$T/out" || keys=1
    done
    is 0 && [ "$(wc -l < "$T/out")" -eq 1 ] && json_ok "$T/out" && [ $keys -eq 0 ] && grep -q '"output":null' "$T/out" &&
        grep -q '"stream":true' "$T/out" && grep -q '"limit":false' "$T/out" && [ "$(json_num triangles)" = $((64 * 20)) ] &&
        [ -n "$sum" ] && grep -q "\"checksum\":\"$sum\"" "$T/out" && [ "$(json_num arena_planned)" = "$planned" ]
    check $? "$name loop -l 3 --stream --stats, no -o: JSON with every key, triangles 4^3 x 20, same checksum and plan"
    sa=$(json_num stream_arena)
    [ -n "$sa" ] && [ "$sa" -gt 0 ] && [ "$sa" -lt "$planned" ] && { [ -z "$stream_arena_prev" ] || [ "$sa" = "$stream_arena_prev" ]; }
    check $? "$name loop --stream --stats: stream_arena (the stream's plan) > 0, below arena_planned, same in both arithmetics"
    stream_arena_prev=$sa
    run "$b" loop -l 2 --stream --limit --stats test/data/hexfan.obj
    is 0 && json_ok "$T/out" && grep -q '"limit":true' "$T/out" && [ "$(json_num triangles)" = 96 ]
    check $? "$name loop --stream --limit --stats: \"limit\":true, 96 triangles"
    # --arena: the input mesh plus the stream's plan, exactly
    rm -f "$T/a.stl"
    run "$b" loop -l 3 --stream --arena $((planned - 1)) test/data/icosahedron.obj -o "$T/a.stl"
    is 3 && err_starts "subd: arena too small: needs $planned bytes, have $((planned - 1))" && [ ! -e "$T/a.stl" ]
    check $? "$name loop --stream --arena $((planned - 1)): exit 3, needs $planned bytes, no output"
    run "$b" loop -l 3 --stream --arena "$planned" --stats test/data/icosahedron.obj -o "$T/a.stl"
    is 0 && cmp -s "$T/a.stl" "$T/s3.stl" && [ "$(json_num arena_used)" -le "$planned" ]
    check $? "$name loop --stream --arena $planned (the plan): exit 0, the same file"
done
# The stream's plan grows with the level only a little: level 6 (524288 triangles) in less than
# 16 KiB more than level 3 (8192 triangles).
run "$FLOAT" loop -l 3 --stream --stats test/data/grid_tri_8x8.obj
p1=$(json_num arena_planned)
run "$FLOAT" loop -l 6 --stream --stats test/data/grid_tri_8x8.obj
p2=$(json_num arena_planned)
is 0 && [ "$(json_num triangles)" = $((4096 * 128)) ] && [ "$p2" -gt "$p1" ] && [ "$p2" -lt $((p1 + 16384)) ]
check $? "loop -l 6 --stream --stats grid: 4^6 x 128 triangles, plan $p1 -> $p2 bytes (levels 3 -> 6)"
# .stl needs no seek: it can be a pipe
if mkfifo "$T/fifo.stl" 2> /dev/null; then
    cat "$T/fifo.stl" > "$T/from_fifo" &
    reader=$!
    run "$FLOAT" loop -l 3 --stream test/data/icosahedron.obj -o "$T/fifo.stl"
    is 0 || kill "$reader" 2> /dev/null # a run that never opened the FIFO leaves cat waiting
    wait "$reader"
    is 0 && "$FLOAT" loop -l 3 --stream test/data/icosahedron.obj -o "$T/p.stl" && cmp -s "$T/from_fifo" "$T/p.stl"
    check $? "loop --stream -o a FIFO named .stl: the same bytes as the file"
fi
# output errors: exit 4
run "$FLOAT" loop --stream test/data/icosahedron.obj -o "$T/no/such/dir/x.stl"
is 4 && err_starts "subd: cannot write"; check $? "loop --stream to an unwritable .stl: exit 4"
if [ -w /dev/full ]; then
    for e in stl obj off; do
        ln -s /dev/full "$T/full.$e"
        run "$FIXED" loop -l 4 --stream test/data/icosahedron.obj -o "$T/full.$e"
        is 4 && err_starts "subd: cannot write '$T/full.$e'" && [ -c /dev/full ]
        check $? "subd-fixed loop --stream -o .$e on a full disk (/dev/full): exit 4"
    done
fi
usage_case_pre loop --limit test/data/icosahedron.obj -o "$T/x.obj"
grep -q -- '--limit needs --stream' "$T/err"; check $? "loop --limit without --stream: exit 1, says so"
usage_case_pre convert --stream test/data/icosahedron.obj -o "$T/x.obj"
grep -q -- "--stream applies to 'loop', 'alpha' and 'sr48' only" "$T/err"; check $? "convert --stream: exit 1, says --stream is loop's, alpha's and sr48's"
usage_case_pre limit --stream --limit test/data/icosahedron.obj -o "$T/x.obj"; check $? "limit --stream: exit 1"
for e in png xyz; do
    usage_case_pre loop --stream test/data/icosahedron.obj -o "$T/x.$e"
    grep -q -- '--stream writes .stl, .obj or .off' "$T/err"; check $? "loop --stream -o .$e: exit 1, names the formats"
done
usage_case_pre loop test/data/icosahedron.obj -o "$T/x.stl"
grep -q "written by --stream only" "$T/err"; check $? "loop -o .stl without --stream: exit 1"
usage_case_pre loop --stream test/data/icosahedron.obj
grep -q "needs an output file" "$T/err"; check $? "loop --stream without -o and without --stats: exit 1"
run "$FLOAT" --help
is 0 && grep -q '^  --stream  ' "$T/out" && grep -q '^  --limit  ' "$T/out" && grep -q 'gathered on the host' "$T/out"
check $? "--help lists --stream and --limit"

# ---------------------------------------------------------------- usage errors (exit 1)
usage_case() { # DESCRIPTION ARGS...
    d=$1
    shift
    run "$FLOAT" "$@"
    is 1 && grep -q '^usage: subd' "$T/err" && [ ! -s "$T/out" ]
    check $? "usage error exits 1: $d"
}
usage_case "no arguments"
usage_case "unknown command" frobnicate test/data/hexfan.obj
usage_case "unknown option" info --bogus test/data/hexfan.obj
usage_case "missing input" info
usage_case "two inputs" info test/data/hexfan.obj test/data/cube_quad.obj
usage_case "convert without -o" convert test/data/hexfan.obj
usage_case "-o without value" convert test/data/hexfan.obj -o
usage_case "unknown output extension" convert test/data/hexfan.obj -o "$T/x.ply"
usage_case ".stl without loop --stream" convert test/data/hexfan.obj -o "$T/x.stl"
usage_case "unknown input extension" info test/data/hexfan.step
usage_case "render to .obj" render test/data/hexfan.obj -o "$T/x.obj"
usage_case "bad --size" render test/data/hexfan.obj -o "$T/x.png" --size 12by3
usage_case "bad --pitch" render test/data/hexfan.obj -o "$T/x.png" --pitch 100
usage_case "bad --arena" info --arena lots test/data/hexfan.obj
usage_case "-l on info" info -l 2 test/data/hexfan.obj
usage_case "picture option without png" convert test/data/hexfan.obj -o "$T/x.off" --no-edges
run "$FLOAT" --help
is 0 && grep -q '^usage: subd' "$T/out"; check $? "--help prints usage on stdout, exit 0"
run "$FLOAT" help
is 0 && grep -q '^usage: subd' "$T/out"; check $? "help prints usage on stdout, exit 0"
run "$FIXED" --version
is 0 && grep -q '^subd [0-9].*q16\.16' "$T/out"; check $? "subd-fixed --version names q16.16"
# The help's option list is generated from the parser's option table: every option it lists
# is known to the parser (a misspelt row would say "unknown option").
"$FLOAT" --help 2> /dev/null | awk '/^options:/ { o = 1; next } /^Long options/ { o = 0 }
    o && /^  -/ { col = substr($0, 3, 17); sub(/ +$/, "", col); print col }' > "$T/opts"
unknown=""
while read -r name meta; do
    case $name in -h, | --version) continue ;; *,) name=$meta meta="" ;; esac
    if [ -n "$meta" ]; then run "$FLOAT" info "$name" 1 test/data/hexfan.obj; else run "$FLOAT" info "$name" test/data/hexfan.obj; fi
    grep -q "unknown option" "$T/err" && unknown="$unknown $name"
done < "$T/opts"
[ "$(wc -l < "$T/opts")" -ge 28 ] && [ -z "$unknown" ]
check $? "every option --help lists is parsed ($(wc -l < "$T/opts") options${unknown:+; unknown:$unknown})"
run "$FLOAT" info --help test/data/hexfan.obj
is 0 && grep -q '^usage: subd' "$T/out" && grep -q '^  --tags FILE ' "$T/out"; check $? "--help after a command prints the help, exit 0"
usage_case "--version after a command" info --version test/data/hexfan.obj
usage_case "a flag given a value (--stats=1)" info --stats=1 test/data/hexfan.obj
usage_case "two tag files" loop --tags "$T/c1.tags" --tags "$T/c1.tags" test/data/icosahedron.obj -o "$T/x.obj"
# --tags through the library parser: CRLF and comments give the same tags as LF, --name=VALUE works,
# an empty tag file is valid
printf '# cube edges, CRLF\r\n' > "$T/cube_crlf.tags"
sed 's/$/\r/' "$T/cube.tags" >> "$T/cube_crlf.tags"
run "$FLOAT" loop -l 2 --tags="$T/cube_crlf.tags" demo/cube_tri.obj -o "$T/cube_crlf.obj"
is 0 && cmp -s "$T/cube_tags.obj" "$T/cube_crlf.obj"; check $? "--tags=FILE with CRLF lines and comments = the LF file"
: > "$T/empty.tags"
run "$FIXED" loop --tags "$T/empty.tags" test/data/icosahedron.obj -o "$T/x.obj"
is 0 && grep -q "0 crease edge(s), 0 vertex tag(s)" "$T/err"; check $? "an empty tag file is valid (no tags)"
printf 'corner 1\nfixed 2 # ok\ncorner 0\n' > "$T/bad4.tags"
run "$FIXED" quasi48 --tags "$T/bad4.tags" test/data/icosahedron.obj -o "$T/x.obj"
is 2 && err_starts "$T/bad4.tags:3: expected"; check $? "subd-fixed --tags with vertex 0 on line 3: exit 2, FILE:3"

# ---------------------------------------------------------------- I/O errors
run "$FLOAT" info "$T/does-not-exist.obj"
is 2 && grep -q "cannot read .*does-not-exist.obj" "$T/err"; check $? "missing input file: exit 2"
mkdir "$T/dir.obj"
run "$FLOAT" info "$T/dir.obj"
is 2 && grep -q "cannot read" "$T/err"; check $? "input is a directory: exit 2"
run "$FLOAT" convert test/data/hexfan.obj -o "$T/no/such/dir/x.obj"
is 4 && grep -q "cannot write" "$T/err"; check $? "unwritable output: exit 4"

# ---------------------------------------------------------------- robustness (issue 13, item 8)
# non-regular inputs are refused unread (a FIFO with no writer would block, a device never ends)
if mkfifo "$T/in_fifo.obj" 2> /dev/null; then
    # (a reader that opened it would block: bounded by timeout(1) when there is one)
    if command -v timeout > /dev/null 2>&1; then run timeout 20 "$FLOAT" info "$T/in_fifo.obj"
    else run "$FLOAT" info "$T/in_fifo.obj"; fi
    is 2 && grep -q "not a regular file" "$T/err"; check $? "FIFO input: exit 2, 'not a regular file', nothing read"
fi
ln -s /dev/urandom "$T/urandom.obj"
run "$FLOAT" info "$T/urandom.obj"
is 2 && grep -q "not a regular file" "$T/err"; check $? "/dev/urandom as input: exit 2, 'not a regular file'"
ln -s /dev/zero "$T/zero.tags"
run "$FLOAT" loop --tags "$T/zero.tags" test/data/icosahedron.obj -o "$T/x.obj"
is 2 && grep -q "tag file .*not a regular file" "$T/err"; check $? "a device as --tags file: exit 2, 'not a regular file'"
# over the 2 GiB input cap (a sparse file: no disk used)
if dd if=/dev/null of="$T/huge.obj" bs=1 seek=2147483649 2> /dev/null && [ -s "$T/huge.obj" ]; then
    run "$FLOAT" info "$T/huge.obj"
    is 2 && grep -q "larger than the input cap of 2147483648 bytes" "$T/err"; check $? "input over 2 GiB: exit 2, names the cap"
fi
# a failed write to a non-regular output leaves the path alone
if [ -w /dev/full ]; then
    ln -s /dev/full "$T/full.obj"
    run "$FLOAT" convert test/data/hexfan.obj -o "$T/full.obj"
    is 4 && [ -L "$T/full.obj" ] && [ -c /dev/full ]; check $? "write to /dev/full fails with exit 4, the path and device are kept"
fi
# --stats on failure: one JSON object with the exit status and the message
run "$FLOAT" info --stats test/bad/absurd_counts.off
is 2 && json_ok "$T/out" && grep -q '"status":"error"' "$T/out" && grep -q '"exit":2' "$T/out" &&
    grep -q '"message":"test/bad/absurd_counts.off:3: syntax error"' "$T/out"
check $? "info --stats on a bad file: exit 2, JSON with status, exit and the FILE:LINE message"
run "$FLOAT" loop --stats --tol 1 test/data/icosahedron.obj -o "$T/x.obj"
is 1 && json_ok "$T/out" && grep -q '"exit":1' "$T/out" && grep -q "not accepted by 'loop'" "$T/out"
check $? "loop --stats with a usage error: exit 1, JSON with the message"
run "$FLOAT" loop -l 2 --stats --arena 1k test/data/icosahedron.obj -o "$T/x.obj"
is 3 && json_ok "$T/out" && grep -q '"message":"arena too small: needs [0-9]* bytes, have 1024"' "$T/out"
check $? "--stats with a too small --arena: exit 3, JSON says how much is needed"
run "$FLOAT" convert --stats test/data/hexfan.obj -o "$T/no/such/dir/x.obj"
is 4 && json_ok "$T/out" && grep -q '"exit":4' "$T/out" && grep -q '"message":"cannot write ' "$T/out"
check $? "convert --stats to an unwritable output: exit 4, JSON with the message"
# pia that does not reach --tol: exit 5, the error reached on stderr, output written
run "$FLOAT" pia --tol 1e-12 --max-iter 2 test/data/icosahedron.obj -o "$T/pia5.obj"
is 5 && grep -q "tolerance 1e-12 not reached: max error [0-9.e+-]* after --max-iter 2" "$T/err" && [ -s "$T/pia5.obj" ]
check $? "pia not reaching --tol: exit 5, says the error reached, output written"
run "$FLOAT" pia --tol 1e-12 --max-iter 2 --stats test/data/icosahedron.obj -o "$T/pia5.obj"
is 5 && json_ok "$T/out" && grep -q '"converged":false' "$T/out"; check $? "pia --stats not converged: exit 5, one JSON object"
# "not accepted" names the option and the command
run "$FLOAT" alpha --method fast test/data/cube_quad.obj -o "$T/x.obj"
is 1 && grep -q "option '--method' is not accepted by 'alpha'" "$T/err"; check $? "an option the command does not take: named with the command"
# OFF faces spread over several lines are read
printf 'OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1\n2\n3\n0 2 3\n' > "$T/multi.off"
run "$FLOAT" info "$T/multi.off"
is 0 && grep -q "^faces: 2$" "$T/out"; check $? "OFF with faces over several lines: read (2 faces)"

# --- quasi48 --boundary normal and pia per-phase --stats (issue 15, items 2 and 3) ---
# phase member N of the pia JSON: phase_num boundary_phase iterations
phase_num() { sed -n "s/.*\"$1\":{\([^}]*\)}.*/\1/p" "$T/out" | sed -n "s/.*\"$2\":\([0-9][0-9.e+-]*\).*/\1/p"; }
top_iter() { sed -n 's/.*,"iterations":\([0-9]*\),"max_err".*/\1/p' "$T/out"; }
for b in "$FLOAT" "$FIXED"; do
    for m in paper fast; do
        run "$b" pia --tol 0.001 --method $m --stats test/data/grid_tri_8x8.obj -o "$T/pia_ph.obj"
        bi=$(phase_num boundary_phase iterations); ii=$(phase_num interior_phase iterations); ti=$(top_iter)
        bv=$(phase_num boundary_phase vertices); iv=$(phase_num interior_phase vertices)
        is 0 && json_ok "$T/out" && [ -n "$bi" ] && [ -n "$ii" ] && [ -n "$ti" ] && [ $((bi + ii)) -eq "$ti" ] &&
            [ "$bi" -ge 1 ] && [ "$bv" = 32 ] && [ "$iv" = 49 ]
        check $? "$(basename "$b") pia --method $m --stats on the open 8x8 grid: boundary $bi + interior $ii = $ti iterations, 32 + 49 vertices"
    done
    run "$b" pia --tol 0.001 --method paper --stats test/data/icosahedron.obj -o "$T/pia_ph.obj"
    is 0 && json_ok "$T/out" && [ "$(phase_num boundary_phase iterations)" = 0 ] &&
        [ "$(phase_num boundary_phase vertices)" = 0 ] && [ "$(phase_num interior_phase vertices)" = 12 ]
    check $? "$(basename "$b") pia --stats on the closed icosahedron: empty boundary phase"
    # a planar open mesh (z = 0): the normal mode leaves the boundary in place, as fixed does
    run "$b" quasi48 -l 3 --boundary fixed test/data/grid_tri_8x8.obj -o "$T/q_fixed.obj"
    run "$b" quasi48 -l 3 --boundary normal --stats test/data/grid_tri_8x8.obj -o "$T/q_normal.obj"
    is 0 && json_ok "$T/out" && grep -q '"boundary":"normal"' "$T/out" && cmp -s "$T/q_fixed.obj" "$T/q_normal.obj"
    check $? "$(basename "$b") quasi48 --boundary normal on the planar 8x8 grid: the same file as --boundary fixed"
done
run "$FLOAT" pia --tol 0.001 test/data/grid_tri_8x8.obj -o "$T/pia_ph.obj"
is 0 && grep -q "^pia: [0-9]* iterations (boundary [0-9]*, interior [0-9]*)" "$T/err"
check $? "pia without --stats: stderr names the boundary and interior iterations"
usage_case_pre quasi48 --boundary sideways test/data/icosahedron.obj -o "$T/x.obj" &&
    grep -q "expected fixed, smooth or normal" "$T/err"
check $? "quasi48 --boundary sideways: exit 1, lists fixed, smooth and normal"

# ---- alpha tags (--tags: 'alpha V A', 'falpha F A'; semi-stationary paper, section 3) ----
# uniform tags give the untagged output byte for byte, both arithmetics, odd and even orders
for b in "$FLOAT" "$FIXED"; do
    for k in 2 3 4; do
        if [ $((k % 2)) -eq 1 ]; then kw=alpha; n=8; else kw=falpha; n=6; fi
        i=1; : > "$T/uni.tags"
        while [ $i -le $n ]; do echo "$kw $i 45deg" >> "$T/uni.tags"; i=$((i + 1)); done
        run "$b" alpha --order $k --kernel cos --alpha 1/8 -l 2 test/data/cube_quad.obj -o "$T/u0.obj"
        run "$b" alpha --order $k --kernel cos --alpha 1/8 -l 2 --tags "$T/uni.tags" test/data/cube_quad.obj -o "$T/u1.obj"
        is 0 && cmp -s "$T/u0.obj" "$T/u1.obj"
        check $? "alpha --order $k: uniform $kw tags (45deg) = --alpha 1/8 untagged, byte for byte ($(basename "$b"))"
    done
done
# one tag changes the output; --stats says tagged, and the plan is the peak
printf 'alpha 1 515.662deg # 9 radians\n' > "$T/one.tags"
run "$FLOAT" alpha --order 3 --kernel cos -l 2 --tags "$T/one.tags" test/data/cube_quad.obj -o "$T/t0.obj"
is 0 && grep -q "one.tags: 0 crease edge(s), 0 vertex tag(s), 1 alpha(s)" "$T/err"
check $? "alpha --tags: the tag file's summary counts the alpha line"
run "$FLOAT" alpha --order 3 --kernel cos -l 2 test/data/cube_quad.obj -o "$T/u0.obj"
run "$FLOAT" alpha --order 3 --kernel cos -l 2 --tags "$T/one.tags" --stats test/data/cube_quad.obj -o "$T/t1.obj"
is 0 && json_ok "$T/out" && grep -q '"tagged":true' "$T/out" &&
    [ "$(json_num arena_planned)" = "$(json_num arena_used)" ] && ! cmp -s "$T/t1.obj" "$T/u0.obj"
check $? "alpha --tags one vertex: output changes, --stats tagged, planned = used"
# the wrong kind for the order: FILE:LINE, exit 2
printf '# c\nfalpha 1 1/8\n' > "$T/f.tags"
run "$FLOAT" alpha --order 3 --tags "$T/f.tags" test/data/cube_quad.obj -o "$T/x.obj"
is 2 && grep -q "f.tags:2: 'falpha' (per-face alpha) needs an even --order" "$T/err"
check $? "alpha --order 3 with a falpha line: exit 2, FILE:LINE"
run "$FLOAT" alpha --order 2 --tags "$T/one.tags" test/data/cube_quad.obj -o "$T/x.obj"
is 2 && grep -q "one.tags:1: 'alpha' (per-vertex alpha) needs an odd --order" "$T/err"
check $? "alpha --order 2 with an alpha line: exit 2, FILE:LINE"
run "$FLOAT" alpha --tags "$T/f.tags" demo/square.obj -o "$T/x.obj"
is 2 && grep -q "f.tags:2: .*falpha.* needs a surface\|f.tags:2: .*face numbers 1..0" "$T/err"
check $? "alpha on a curve with a falpha line: exit 2, FILE:LINE"
# parse and index errors name the tag file's line
printf 'alpha 1 1/8\nalpha 2 x\n' > "$T/bad1.tags"
run "$FLOAT" alpha --order 3 --tags "$T/bad1.tags" test/data/cube_quad.obj -o "$T/x.obj"
is 2 && grep -q "bad1.tags:2: expected" "$T/err"; check $? "alpha --tags with a bad value: exit 2, FILE:LINE"
printf 'falpha 7 1/8\n' > "$T/bad2.tags"
run "$FLOAT" alpha --order 2 --tags "$T/bad2.tags" test/data/cube_quad.obj -o "$T/x.obj"
is 2 && grep -q "bad2.tags:1: expected.*face numbers 1..6" "$T/err"; check $? "alpha --tags with face 7 of 6: exit 2, FILE:LINE"
# a common denominator too fine for the levels: exit 2, says so
printf 'alpha 1 1/999999937\nalpha 2 1/999999929\n' > "$T/fine.tags"
run "$FLOAT" alpha --order 3 --tags "$T/fine.tags" test/data/cube_quad.obj -o "$T/x.obj"
is 2 && grep -q "common denominator" "$T/err"; check $? "alpha --tags needing a too fine denominator: exit 2"
# curves: per-vertex alpha; uniform = untagged, one tag changes only its neighbourhood
printf 'alpha 1 1/4\nalpha 2 1/4\nalpha 3 1/4\nalpha 4 1/4\n' > "$T/sq.tags"
run "$FLOAT" alpha --kernel cos --alpha 1/4 -l 3 demo/square.obj -o "$T/c0.obj"
run "$FLOAT" alpha --kernel cos -l 3 --tags "$T/sq.tags" demo/square.obj -o "$T/c1.obj"
is 0 && cmp -s "$T/c0.obj" "$T/c1.obj"; check $? "alpha curve: uniform alpha tags = --alpha, byte for byte"
printf 'alpha 1 1/4\nalpha 2 1/4\nalpha 3 -1/3\nalpha 4 1/4\n' > "$T/sq2.tags"
run "$FLOAT" alpha --kernel cos -l 3 --tags "$T/sq2.tags" demo/square.obj -o "$T/c2.obj"
is 0 && ! cmp -s "$T/c0.obj" "$T/c2.obj" &&
    [ "$(grep -c '^v ' "$T/c2.obj")" = 32 ]
check $? "alpha curve: one vertex tag changes the curve, same point count"

# ---------------------------------------------------------------- STL and PLY input
# .stl (binary or ASCII) and .ply (ASCII or binary little-endian) are read by extension; the
# stream's STL reads back with the same triangles in the same order, float32 bit for bit (every
# coordinate here is below 256, exact in Q16.16 too); STL and PLY copies of an OBJ give loop the
# same triangles; errors name FILE:LINE or, for binary STL, FILE: facet N.
for b in "$FLOAT" "$FIXED"; do
    name=$(basename "$b")
    run "$b" loop -l 2 --stream test/data/icosahedron.obj -o "$T/s.stl"
    run "$b" convert "$T/s.stl" -o "$T/back.obj"
    is 0 && dump "$T/s.stl" > "$T/s.tri" && dump "$T/back.obj" > "$T/back.tri" && cmp -s "$T/s.tri" "$T/back.tri"
    check $? "$name loop --stream -o .stl read back (convert to .obj): the same triangles in order, bit for bit"
    run "$b" info "$T/s.stl"
    is 0 && out_has "^vertices: 162 " && out_has "^faces: 320" && out_has "validation: ok"
    check $? "$name info of the stream's .stl: corners welded into the 162 vertices of level 2"
    "$b" loop -l 1 test/data/icosahedron.obj -o "$T/o.obj" < /dev/null > /dev/null 2>&1
    run "$b" loop -l 1 test/data/icosahedron.stl -o "$T/a.obj"
    is 0 && dump "$T/a.obj" > "$T/a.tri" && dump "$T/o.obj" > "$T/o.tri" && cmp -s "$T/a.tri" "$T/o.tri"
    check $? "$name loop of the ASCII .stl copy of an .obj: the same triangles, bit for bit"
    for p in icosahedron.ply icosahedron_le.ply; do
        run "$b" loop -l 1 "test/data/$p" -o "$T/p.obj"
        is 0 && cmp -s "$T/p.obj" "$T/o.obj"
        check $? "$name loop of test/data/$p = loop of the .obj, byte for byte"
    done
done
head -c 500 "$T/s.stl" > "$T/trunc.stl"
run "$FLOAT" info "$T/trunc.stl"
is 2 && err_starts "$T/trunc.stl: facet 8: syntax error"; check $? "truncated binary STL: exit 2, FILE: facet N"
printf 'solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 nan\n' > "$T/nan.stl"
run "$FLOAT" info "$T/nan.stl"
is 2 && err_starts "$T/nan.stl:4: coordinate is NaN"; check $? "ASCII STL with nan: exit 2, FILE:LINE"
f3='facet normal 0 0 1\nouter loop\nvertex %s\nvertex %s\nvertex %s\nendloop\nendfacet\n'
printf "solid x\n$f3$f3${f3}endsolid\n" "0 0 0" "1 0 0" "0 1 0" "1 0 0" "0 0 0" "0 -1 0" "0 0 0" "1 0 0" "0 0 1" > "$T/nm.stl"
run "$FLOAT" info "$T/nm.stl"
is 2 && err_starts "$T/nm.stl:16: non-manifold edge"; check $? "ASCII STL whose facets weld into a non-manifold edge: exit 2, FILE:LINE"
printf 'ply\nformat binary_big_endian 1.0\nelement vertex 1\nend_header\n' > "$T/be.ply"
run "$FLOAT" info "$T/be.ply"
is 2 && err_starts "$T/be.ply:2: big-endian PLY is not supported"; check $? "big-endian PLY refused at its format line: exit 2, says why"
sed 's/^0 3 0 11 5$/0 3 0 11 50/' test/data/icosahedron.ply > "$T/idx.ply"
n=$(grep -n '^0 3 0 11 50$' "$T/idx.ply" | cut -d: -f1)
run "$FIXED" info "$T/idx.ply"
is 2 && err_starts "$T/idx.ply:$n: vertex index out of range"; check $? "PLY index out of range: exit 2, FILE:LINE"
run "$FLOAT" convert test/data/icosahedron.obj -o "$T/x.ply"
is 1; check $? "writing .ply is refused: exit 1"
# ---- alpha --stream: curves point by point (.xyz, G-code), --chord, --feed ----
printf 'v 0 0 0\nv 4 0 0\nv 4 4 0\nv 0 4 0\nl 1 2 3 4 1\nv 10 0 0\nv 14 0 0\nv 14 0 3\nv 17 2 3\nl 5 6 7 8\n' > "$T/two.obj"
for b in "$FLOAT" "$FIXED"; do
    for k in 2 3 4; do
        run "$b" alpha --order $k --kernel cos --alpha 1/4 -l 6 "$T/two.obj" -o "$T/m.xyz"
        run "$b" alpha --order $k --kernel cos --alpha 1/4 -l 6 --stream "$T/two.obj" -o "$T/s.xyz"
        is 0 && cmp -s "$T/m.xyz" "$T/s.xyz"
        check $? "alpha --stream --order $k: the .xyz of the materialised curves, byte for byte ($(basename "$b"))"
    done
done
# G-code read back: header, one G0 per polyline, G1 per point, F once per polyline, the same
# numbers as the .xyz (a closed polyline returns to its start)
run "$FLOAT" alpha --order 3 --kernel cos --alpha 1/4 -l 5 --stream --feed 1200 "$T/two.obj" -o "$T/s.gcode"
run "$FLOAT" alpha --order 3 --kernel cos --alpha 1/4 -l 5 --stream "$T/two.obj" -o "$T/s5.xyz"
is 0 && awk '
    FNR == NR { if (NF == 3) { n++; x[n] = $1; y[n] = $2; z[n] = $3 } next }
    /^G21$/ || /^G90$/ { next }
    /^G[01] / { m++; if ($1 == "G0") g0++; if ($2 != "X" x[m] || $3 != "Y" y[m] || $4 != "Z" z[m]) exit 1
                if (NF == 5) { if ($5 != "F1200") exit 1; f++ } else if (NF != 4) exit 1; next }
    { exit 1 }
    END { if (m != n || g0 != 2 || f != 2) exit 1 }' "$T/s5.xyz" "$T/s.gcode"
check $? "alpha --stream -o .gcode: G21, G90, G0 per polyline, G1 X Y Z per point (the .xyz numbers), F once"
run "$FIXED" alpha --order 2 -l 4 --stream "$T/two.obj" -o "$T/s.nc"
is 0 && [ "$(head -2 "$T/s.nc" | tr '\n' ' ')" = "G21 G90 " ] && grep -q '^G0 X' "$T/s.nc"
check $? "subd-fixed alpha --stream -o .nc: G-code"
# --chord: fewer points, every one a point of the uniform output, the rest within EPS
run "$FLOAT" alpha --order 3 --kernel cos --alpha 1/4 -l 8 --stream demo/square.obj -o "$T/u.xyz"
run "$FLOAT" alpha --order 3 --kernel cos --alpha 1/4 -l 8 --stream --chord 0.001 demo/square.obj -o "$T/c.xyz" --stats
is 0 && json_ok "$T/out" && grep -q '"stream":true' "$T/out" && awk '
    FNR == NR { if (NF == 3) { n++; ux[n] = $1; uy[n] = $2; if (!(($1 " " $2) in key)) key[$1 " " $2] = n } next }
    NF == 3 { m++; if (!(($1 " " $2) in key)) exit 1; id[m] = key[$1 " " $2] }
    END { if (m < 3 || m * 4 > n) exit 1
          for (i = 1; i < m; i++) { a = id[i]; b = id[i + 1]; if (b == 1 && i + 1 == m) b = n; if (b <= a) exit 1
              for (j = a + 1; j < b; j++) { dx = ux[b] - ux[a]; dy = uy[b] - uy[a]; px = ux[j] - ux[a]; py = uy[j] - uy[a]
                  t = (dx * dx + dy * dy) > 0 ? (px * dx + py * dy) / (dx * dx + dy * dy) : 0; if (t < 0) t = 0; if (t > 1) t = 1
                  ex = px - t * dx; ey = py - t * dy; if (sqrt(ex * ex + ey * ey) > 0.001 * 1.0001) exit 1 } }
          exit 0 }' "$T/u.xyz" "$T/c.xyz"
check $? "alpha --stream --chord 0.001: a quarter of the points or fewer, uniform points, the rest within EPS"
usage_case_pre alpha --stream demo/square.obj -o "$T/x.obj"; check $? "alpha --stream -o .obj: exit 1 (writes .xyz or G-code)"
usage_case_pre alpha --chord 0.1 demo/square.obj -o "$T/x.xyz"; check $? "alpha --chord without --stream: exit 1"
usage_case_pre alpha --stream --feed 100 demo/square.obj -o "$T/x.xyz"; check $? "alpha --feed with .xyz output: exit 1"
usage_case_pre alpha --stream --feed -5 demo/square.obj -o "$T/x.gcode"; check $? "alpha --feed -5: exit 1"
usage_case_pre alpha --stream --limit demo/square.obj -o "$T/x.xyz"; check $? "alpha --stream --limit: exit 1"
usage_case_pre loop --stream test/data/icosahedron.obj -o "$T/x.gcode"; check $? "loop --stream -o .gcode: exit 1"
run "$FLOAT" alpha --stream test/data/cube_quad.obj -o "$T/x.xyz"
is 1 && grep -q "streams curves" "$T/err"; check $? "alpha --stream on a surface: exit 1, says it streams curves"

# ---------------------------------------------------------------- loop --stream --limit --chord
# The adaptive limit stream (subd_loop_adapt_stream): welded by the tool's id gathering, a closed
# input gives a closed 2-manifold (subd info: validation ok, no boundary edge, Euler 2 or 0);
# fewer triangles than the uniform limit stream; a tolerance below every deviation gives the
# uniform limit stream's file byte for byte; the options it needs.
for b in "$FLOAT" "$FIXED"; do
    name=$(basename "$b")
    for m in test/data/icosahedron.obj test/data/torus_tri.obj; do
        lv=3; [ "$m" = test/data/torus_tri.obj ] && lv=2
        run "$b" loop -l $lv --stream --limit --chord 0.01 --stats "$m" -o "$T/ad.obj"
        n=$(json_num triangles)
        is 0 && json_ok "$T/out" && [ "$(json_num arena_used)" -le "$(json_num arena_planned)" ] &&
            "$b" info "$T/ad.obj" < /dev/null > "$T/info" 2>&1 && grep -q '^validation: ok' "$T/info" &&
            grep -q '^boundary edges: 0$' "$T/info" && grep -q "^faces: $n$" "$T/info"
        check $? "$name loop -l $lv --stream --limit --chord 0.01 $(basename "$m"): closed 2-manifold welded by id ($n triangles)"
        run "$b" loop -l $lv --stream --limit --chord 0.01 "$m" -o "$T/ad.stl"
        is 0 && [ "$(wc -c < "$T/ad.stl")" -eq $((84 + 50 * n)) ]
        check $? "$name --chord -o .stl: 84 + 50 x $n bytes"
    done
    run "$b" loop -l 3 --stream --limit --chord 0.05 --stats test/data/icosahedron.obj
    [ "$(json_num triangles)" -lt 1280 ]
    check $? "$name --chord 0.05 on the icosahedron: fewer than the uniform 1280 triangles"
    "$b" loop -l 2 --stream --limit test/data/hexfan.obj -o "$T/u.stl" < /dev/null > /dev/null 2>&1
    tiny=1e-30; [ "$b" = "$FIXED" ] && tiny=0.00002 # Q16.16: 1.3 LSB, below the 8 LSB margin
    run "$b" loop -l 2 --stream --limit --chord $tiny test/data/hexfan.obj -o "$T/a.stl"
    is 0 && cmp -s "$T/u.stl" "$T/a.stl"
    check $? "$name --chord $tiny: the uniform limit stream's .stl byte for byte"
done
usage_case_pre loop --stream --chord 0.01 test/data/icosahedron.obj -o "$T/x.stl"; check $? "loop --chord without --limit: exit 1"
usage_case_pre loop --chord 0.01 test/data/icosahedron.obj -o "$T/x.obj"; check $? "loop --chord without --stream: exit 1"
usage_case_pre loop --stream --limit --chord 0 test/data/icosahedron.obj -o "$T/x.stl"; check $? "loop --chord 0: exit 1"

# ---------------------------------------------------------------- sr48: one name per scheme
# 'sr48' is the semi-regular 4-8 command (include/subd_sr48.h: subd_sr48_*): uniform at -l N,
# or a MODE (--point, --ramp, --plane, --chord) for a variable-resolution cut up to level N.
# 'semireg48' and 'adapt' are its deprecated 0.5 spellings (until 1.0): the same bytes in every
# output format, uniform and each mode, materialised and streamed, in both arithmetics; their
# --stats differ from sr48's in "command" only.
stats_norm() { sed 's/"command":"[a-z0-9]*"//; s/"time_ms":[0-9.]*//; s/"file":"[^"]*"//g' "$1"; }
alias_case() { # BIN OLD_COMMAND INPUT EXT ARGS...: OLD_COMMAND ARGS vs sr48 ARGS
    ab=$1 old=$2 in=$3 ext=$4
    shift 4
    run "$ab" "$old" "$@" "$in" -o "$T/old.$ext" --stats
    orc=$rc
    stats_norm "$T/out" > "$T/old.stats"
    grep -q "\"command\":\"$old\"" "$T/out" || orc=99
    run "$ab" sr48 "$@" "$in" -o "$T/new.$ext" --stats
    stats_norm "$T/out" > "$T/new.stats"
    [ "$orc" -eq 0 ] && is 0 && grep -q '"command":"sr48"' "$T/out" && grep -q '"scheme":"sr48"' "$T/out" &&
        cmp -s "$T/old.$ext" "$T/new.$ext" && cmp -s "$T/old.stats" "$T/new.stats"
    check $? "$(basename "$ab") $old $* -o .$ext = sr48 $* byte for byte (file and --stats but \"command\")"
}
for b in "$FLOAT" "$FIXED"; do
    ico=test/data/icosahedron.obj tor=demo/torus_12x6.obj
    alias_case "$b" semireg48 $ico obj -l 3
    alias_case "$b" semireg48 $ico off -l 0 --no-smooth
    alias_case "$b" semireg48 $ico obj
    for e in stl obj off; do alias_case "$b" semireg48 $ico $e -l 3 --stream; done
    alias_case "$b" adapt $tor obj -l 4 --point 1.4,0,0 --radius 0.5
    alias_case "$b" adapt $tor off -l 4 --ramp x
    alias_case "$b" adapt $tor obj -l 4 --plane 0,0,0,1,0,0
    alias_case "$b" adapt $tor obj -l 4 --chord 0.02 --no-smooth
    alias_case "$b" adapt $tor off --ramp y
    for e in stl obj; do alias_case "$b" adapt $tor $e -l 4 --stream --ramp x; done
    for e in stl off; do alias_case "$b" adapt $tor $e -l 4 --stream --chord 0.02; done
done
alias_case "$FLOAT" semireg48 test/data/icosahedron.obj png -l 2
alias_case "$FLOAT" adapt demo/torus_12x6.obj png -l 4 --ramp x
# the picture and the STL header name the scheme by its one name, whatever the spelling
run "$FLOAT" adapt -l 3 --stream --ramp x demo/torus_12x6.obj -o "$T/h.stl"
is 0 && [ "$(head -c 13 "$T/h.stl")" = "tinysubd sr48" ]; check $? "adapt --stream -o .stl: the header says 'tinysubd sr48'"
# -l: 2 without a mode (semireg48's default), 6 with one (adapt's)
run "$FLOAT" sr48 test/data/icosahedron.obj -o "$T/x.obj" --stats
is 0 && [ "$(json_num levels)" = 2 ] && [ "$(json_num binary_steps)" = 2 ]; check $? "sr48 without -l: 2 binary steps"
run "$FLOAT" sr48 --ramp x demo/torus_12x6.obj -o "$T/x.obj" --stats
is 0 && [ "$(json_num levels)" = 6 ] && [ "$(json_num uniform_faces)" = 36864 ]; check $? "sr48 --ramp x without -l: up to level 6 (36864 uniform faces)"
usage_case_pre sr48 -l 4 --ramp x --chord 1 demo/torus_12x6.obj -o "$T/x.obj"
grep -q "give one adaptation mode" "$T/err"; check $? "sr48 with two modes: exit 1, says give one"
usage_case_pre sr48 -l 4 --ramp x --radius 1 demo/torus_12x6.obj -o "$T/x.obj"; check $? "sr48 --radius without --point: exit 1"
usage_case_pre sr48 -l 17 test/data/icosahedron.obj -o "$T/x.obj"; check $? "sr48 -l 17: exit 1"
usage_case_pre sr48 --stream --limit test/data/icosahedron.obj -o "$T/x.stl"
grep -q -- "--limit applies to 'loop --stream' only" "$T/err"; check $? "sr48 --stream --limit: exit 1, --limit is loop's"
usage_case_pre semireg48 --ramp x test/data/icosahedron.obj -o "$T/x.obj"
grep -q "not accepted by 'semireg48'" "$T/err"; check $? "semireg48 --ramp x: exit 1 (the old spelling keeps its 0.5 options)"
usage_case_pre sr48 --tags "$T/c1.tags" test/data/icosahedron.obj -o "$T/x.obj"; check $? "sr48 --tags: exit 1"
run "$FLOAT" --help
is 0 && grep -q '^  sr48 ' "$T/out" && grep -q '^  semireg48 (deprecated)' "$T/out" && grep -q '^  adapt .*(deprecated)' "$T/out" &&
    [ "$(grep -c '^  --point X,Y,Z' "$T/out")" = 1 ]
check $? "--help lists sr48, semireg48 and adapt as deprecated, each option once"

# ---------------------------------------------------------------- stream_arena
# --stats of every stream reports stream_arena, the stream's own plan (the mesh not counted):
# > 0, below arena_planned, the same in both arithmetics (plans do not depend on them), and
# arena_planned - stream_arena, the input's part, is one number for every stream of one input
# (the level, --limit, --chord, a mode change the stream's part only).
for fam in loop sr48 alpha; do
    case $fam in
    loop) in=test/data/icosahedron.obj
        set -- "loop -l 2 --stream" "loop -l 3 --stream" "loop -l 3 --stream --limit" "loop -l 3 --stream --limit --chord 0.01" ;;
    sr48) in=test/data/icosahedron.obj
        set -- "sr48 -l 3 --stream" "sr48 -l 4 --stream --ramp x" "sr48 -l 4 --stream --chord 0.02" "semireg48 -l 2 --stream" \
            "adapt -l 4 --stream --point 0,0,1" ;;
    alpha) in=demo/square.obj
        set -- "alpha -l 4 --stream" "alpha -l 5 --stream" "alpha -l 5 --stream --chord 0.01" "alpha --order 4 -l 3 --stream" ;;
    esac
    base=""
    for a in "$@"; do
        run "$FLOAT" $a "$in" --stats
        sa=$(json_num stream_arena) pl=$(json_num arena_planned)
        run "$FIXED" $a "$in" --stats
        ok=1
        is 0 && [ -n "$sa" ] && [ "$sa" -gt 0 ] && [ "$sa" -lt "$pl" ] && [ "$(json_num stream_arena)" = "$sa" ] &&
            [ "$(json_num arena_planned)" = "$pl" ] && { [ -z "$base" ] || [ $((pl - sa)) = "$base" ]; } && ok=0
        [ -z "$base" ] && base=$((pl - sa))
        check $ok "$a --stats: stream_arena $sa > 0, below arena_planned $pl, the same in both arithmetics, planned - stream = $base"
    done
done
# alpha: SUBD_ALPHA_CURVE_STREAM_BYTES(L, K) (subd_alpha.h) grows by 176 L K bytes, for every
# curve: one more level costs 176 K (K even: every term 8-aligned), the same on another curve
for k in 2 4; do
    run "$FLOAT" alpha --order $k -l 4 --stream demo/square.obj --stats
    s4=$(json_num stream_arena)
    run "$FLOAT" alpha --order $k -l 5 --stream demo/square.obj --stats
    s5=$(json_num stream_arena)
    run "$FLOAT" alpha --order $k -l 5 --stream --chord 0.01 demo/ellipse_control.obj --stats
    is 0 && [ -n "$s4" ] && [ $((s5 - s4)) = $((176 * k)) ] && [ "$(json_num stream_arena)" = "$s5" ]
    check $? "alpha --order $k --stream: stream_arena -l 4 -> -l 5 grows by 176 x $k, the same on another curve with --chord"
done

echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
