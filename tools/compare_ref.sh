#!/bin/bash
# SPDX-License-Identifier: MIT
# Same output as a reference commit: builds the host tool (float32 and Q16.16) of REF in a
# temporary git worktree, runs both tools on a list of streamed and materialised cuts and
# compares the output files byte for byte (and the --stats face counts and checksums).
# Why: the test suite compares each stream with its materialised call on small shapes; a
# refactor that changes a cut only on larger meshes (an odd max_level, a deep CHORD decision)
# passes it. This catches such changes before a release (make compare-ref REF=<commit>).
# Exit 0 when every output is the same, 1 otherwise; the bench meshes (SHARED/data/meshes/
# bench) are used when present, the project's own meshes always.
# Usage: tools/compare_ref.sh REF [SHARED]   (run from the repository's top directory)
set -u
ref=${1:?usage: tools/compare_ref.sh REF [SHARED]}
shared=${2:-../shared}
top=$(pwd)
work=$(mktemp -d)
trap 'git -C "$top" worktree remove --force "$work/ref" >/dev/null 2>&1; rm -rf "$work"' EXIT
git -C "$top" worktree add --detach "$work/ref" "$ref" >/dev/null 2>&1 || { echo "compare-ref: no commit $ref"; exit 1; }
echo "== building the tool of $ref and of the working tree"
make -C "$work/ref" -j2 tool >"$work/ref_build.log" 2>&1 || { echo "compare-ref: $ref does not build (log: $work/ref_build.log)"; tail -5 "$work/ref_build.log"; exit 1; }
make -j2 tool >"$work/new_build.log" 2>&1 || { echo "compare-ref: the working tree does not build"; tail -5 "$work/new_build.log"; exit 1; }
b=$shared/data/meshes/bench
configs=(
    "sr48 --stream -l 9 --chord 0.01 test/data/icosahedron.obj"
    "sr48 --stream -l 8 --chord 0.01 test/data/dense_ico.obj"
    "sr48 --stream -l 5 --chord 0.05 test/data/dense_ico.obj"
    "sr48 --stream -l 6 --chord 0.002 --no-smooth demo/torus_12x6.obj"
    "sr48 --stream -l 7 --chord 0.002 demo/spot_control_tri.obj"
    "sr48 --stream -l 8 test/data/icosahedron.obj"
    "sr48 --stream -l 7 test/data/dense_ico.obj"
    "sr48 --stream -l 5 --no-smooth demo/torus_12x6.obj"
    "sr48 --stream -l 6 --no-smooth test/data/hexfan.obj"
    "sr48 -l 6 --chord 0.002 demo/spot_control_tri.obj"
    "loop -l 6 --stream test/data/icosahedron.obj"
    "loop -l 5 --stream --limit test/data/torus_tri.obj"
    "loop -l 4 --stream test/data/nefertiti_patch.obj"
)
if [ -d "$b" ]; then
    configs+=(
        "sr48 --stream -l 5 --chord 0.002 $b/spot_triangulated.obj"
        "sr48 --stream -l 6 --chord 0.01 $b/spot_triangulated.obj"
        "sr48 --stream -l 3 --chord 0.0005 $b/stanford-bunny-open.obj"
        "sr48 --stream -l 6 $b/spot_triangulated.obj"
        "sr48 --stream -l 3 $b/stanford-bunny-open.obj"
        "sr48 --stream -l 2 $b/nefertiti.obj"
        "sr48 --stream -l 6 --plane 0,0,0,0,0,1 $b/spot_triangulated.obj"
        "loop -l 3 --stream $b/nefertiti.obj"
        "loop -l 5 --stream $b/spot_triangulated.obj"
        "loop -l 4 --stream --limit $b/spot_triangulated.obj"
    )
else
    echo "(no $b: the bench meshes are skipped)"
fi
fail=0
for tool in subd subd-fixed; do
    for c in "${configs[@]}"; do
        rm -f "$work/a.obj" "$work/n.obj" # an error writes nothing: never compare stale files
        # shellcheck disable=SC2086 # the configuration is a word list
        a=$("$work/ref/build/bin/$tool" $c --stats -o "$work/a.obj" 2>&1 | grep -o '"faces":[0-9]*\|"checksum":"[0-9a-f]*"\|rror.*' | tr '\n' ' ')
        # shellcheck disable=SC2086
        n=$("build/bin/$tool" $c --stats -o "$work/n.obj" 2>&1 | grep -o '"faces":[0-9]*\|"checksum":"[0-9a-f]*"\|rror.*' | tr '\n' ' ')
        if [ "$a" = "$n" ] && cmp -s "$work/a.obj" "$work/n.obj"; then
            echo "same  $tool $c"
        else
            echo "DIFF  $tool $c :: $ref: $a :: now: $n"
            fail=1
        fi
    done
done
[ $fail = 0 ] && echo "== compare-ref: every output equals $ref's" || echo "== compare-ref: outputs differ from $ref's"
exit $fail
