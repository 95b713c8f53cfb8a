#!/bin/sh
# SPDX-License-Identifier: MIT
# The single-file form (tools/amalgamate.sh, make amalgamate) beyond "its tests pass with the
# same hashes" (the amalgamation suites): the generator is deterministic and dist/ is what the
# sources give now; every source is in it once; no .c file's macro outlives its file (asked of
# the preprocessor, not of the generator); tinysubd.h stands alone as C99 and C++11; the M4F
# object built as an integrator might (gnu11 -O2, no -ffp-contract=off) has no fused
# multiply-add; and every refusal of the generator fails loudly with nothing written.
# usage: amalgamate_test.sh ARM_OBJDUMP M4F_GNU_OBJECT      (run from the repository root)
objdump_arm=$1 gnu_obj=$2
LC_ALL=C
export LC_ALL
CC=${CC:-gcc} CXX=${CXX:-g++}
pass=0 fail=0
ok() { pass=$((pass + 1)); echo "ok - $1"; }
bad() { fail=$((fail + 1)); echo "not ok - $1"; }
check() { if eval "$2"; then ok "$1"; else bad "$1"; fi; }
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT

# Determinism: two runs, byte for byte, and the same bytes as dist/ (built by make from these sources).
tools/amalgamate.sh "$t/a" > /dev/null && tools/amalgamate.sh "$t/b" > /dev/null
check "two runs give the same bytes" 'cmp -s "$t/a/tinysubd.c" "$t/b/tinysubd.c" && cmp -s "$t/a/tinysubd.h" "$t/b/tinysubd.h"'
check "dist/ is up to date with src/ and include/" 'cmp -s "$t/a/tinysubd.c" dist/tinysubd.c && cmp -s "$t/a/tinysubd.h" dist/tinysubd.h'
ls -A "$t/a" > "$t/list"
check "only tinysubd.c and tinysubd.h written" '[ "$(tr "\n" " " < "$t/list")" = "tinysubd.c tinysubd.h " ]'

# Contents: each file once, by the banner the generator writes at each file's start.
c=dist/tinysubd.c h=dist/tinysubd.h
banners() { sed -n 's|^/\* ---- \([^ (]*\) ---- \*/$|\1|p' "$1" | sort; }
check "tinysubd.c: every src/*.c once" '[ "$(banners $c | grep "\.c$")" = "$(ls src/*.c | sort)" ]'
check "tinysubd.c: each src/*.h at most once, no include/ header" \
    '[ -z "$(banners $c | grep "\.h$" | uniq -d)" ] && ! banners $c | grep -qv "^src/"'
check "tinysubd.h: every include/*.h once, nothing else" '[ "$(banners $h)" = "$(ls include/*.h | sort)" ]'
check "tinysubd.c: one quoted #include, of tinysubd.h" \
    '[ "$(grep "^[[:space:]]*#[[:space:]]*include[[:space:]]*\"" $c | cut -d\" -f2)" = tinysubd.h ]'
check "tinysubd.h: no quoted #include" '! grep -q "^[[:space:]]*#[[:space:]]*include[[:space:]]*\"" $h'
ver=$(awk '$1 == "#define" && $2 ~ /^SUBD_VERSION_(MAJOR|MINOR|PATCH)$/ { printf "%s%s", s, $3; s = "." }' include/subd.h)
for f in $c $h; do
    check "$f: SPDX line, then tinysubd $ver" \
        '[ "$(sed -n 1p $f)" = "/* SPDX-License-Identifier: MIT */" ] && sed -n 2p $f | grep -q "^/\* tinysubd $ver, "'
done

# Macros: the names #defined in src/*.c, none defined at the end of the unit (both arithmetics).
sed -n 's/^[[:space:]]*#[[:space:]]*define[[:space:]]\{1,\}\([A-Za-z_][A-Za-z0-9_]*\).*/\1/p' src/*.c | sort -u > "$t/own"
for fx in 0 1; do
    $CC -std=c99 -DSUBD_FIXED=$fx -E -dM $c | awk '{ sub(/\(.*/, "", $2); print $2 }' | sort -u > "$t/end$fx"
    left=$(comm -12 "$t/own" "$t/end$fx" | tr '\n' ' ')
    check "SUBD_FIXED=$fx: none of the $(wc -l < "$t/own") macros of src/*.c outlives its file${left:+ (left: $left)}" '[ -z "$left" ]'
done

# The header alone: C99 pedantic, C++11; each with only the file itself.
W="-Wall -Wextra -Werror -pedantic"
check "tinysubd.h alone compiles as C99 ($W)" '$CC -std=c99 $W -x c -fsyntax-only $h'
check "tinysubd.h alone compiles as C++11 ($W)" '$CXX -std=c++11 $W -x c++ -fsyntax-only $h'

# The M4F unit as an integrator might build it: fp_contract.h, first, covers the whole unit.
if [ -f "$gnu_obj" ]; then
    d=$("$objdump_arm" -d "$gnu_obj")
    nmul=$(printf '%s\n' "$d" | grep -cE '[[:space:]]vmul\.f32')
    nfma=$(printf '%s\n' "$d" | grep -cE '[[:space:]]vfn?m[as](\.f32|[[:space:]])')
    check "m4f gnu11 -O2 object (no -ffp-contract=off): 0 vfma/vfms/vfnma/vfnms, $nmul vmul.f32" \
        '[ "$nfma" -eq 0 ] && [ "$nmul" -gt 0 ]'
else
    bad "$gnu_obj missing"
fi

# Refusals, on a scratch copy of the tree: exit status 1, the reason on stderr, nothing written
# (an earlier output is kept as it was).
refuse() { # label, expected stderr text, file to edit, sed script
    want=$2
    rm -rf "$t/tree" && mkdir -p "$t/tree" && cp -R tools src include "$t/tree/" &&
        mkdir -p "$t/tree/out" && echo old > "$t/tree/out/tinysubd.c" && echo old > "$t/tree/out/tinysubd.h" &&
        sed -i "$4" "$t/tree/$3"
    "$t/tree/tools/amalgamate.sh" out > "$t/out" 2> "$t/err"
    rc=$?
    check "refuses $1 (exit 1, \"$2\", nothing written)" \
        '[ $rc -eq 1 ] && grep -qF "$want" "$t/err" && [ "$(cat "$t/tree/out/tinysubd.c" "$t/tree/out/tinysubd.h")" = "old
old" ] && [ "$(ls -A "$t/tree/out" | wc -l)" -eq 2 ]'
}
refuse "an unresolvable #include" 'src/mesh.c:2: cannot resolve #include "no_such.h"' src/mesh.c '1a #include "no_such.h"'
refuse "an unresolvable #include in a public header" 'include/subd_tags.h:2: cannot resolve #include "gone.h"' \
    include/subd_tags.h '1a #include "gone.h"'
refuse "a file without the SPDX line" 'src/text.c:1: the first line is not' src/text.c '1s/MIT/BSD-2-Clause/'
refuse "a .c file redefining a header macro" 'src/arena.c:3: SUBD_NONE is a header macro' src/arena.c '2a #undef SUBD_NONE'
refuse "a quoted #include under #if" 'src/status.c:4: #include "layout.h" under #if' src/status.c \
    '2a #if SUBD_FIXED\n#include "layout.h"\n#endif'
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
