#!/bin/sh
# SPDX-License-Identifier: MIT
# Link-time proofs on a Cortex-M library archive (DESIGN.md hard rules, checked with nm):
#   - no heap, stdio or qsort: no reference to malloc, calloc, realloc, free, printf & co, qsort;
#   - m3-fixed: no soft-float helper at all (the fixed build never touches float);
#   - m4f-float: no double-precision helper (no accidental double on a single-precision FPU);
#   - every global symbol the library defines starts with subd_.
# usage: link_proofs.sh NM LIBRARY VARIANT     prints ok/not ok lines and "N passed, M failed"
nm=$1 lib=$2 variant=$3
pass=0 fail=0
check() { # name, offending symbols (empty = pass)
    if [ -z "$2" ]; then pass=$((pass + 1)); echo "ok - $variant: $1"
    else fail=$((fail + 1)); echo "not ok - $variant: $1:"; echo "$2" | sed 's/^/    /'; fi
}
[ -f "$lib" ] || { echo "not ok - $variant: $lib missing"; echo "0 passed, 1 failed"; exit 1; }
undef=$("$nm" -u "$lib" | awk 'NF == 2 && $1 == "U" {print $2} NF == 1 {print $1}' | sort -u)
defined=$("$nm" -g --defined-only "$lib" | awk 'NF == 3 {print $3}' | sort -u)

check "no heap, stdio or qsort references" \
    "$(echo "$undef" | grep -E '^(malloc|calloc|realloc|free|alloca|_malloc_r|_free_r|printf|fprintf|sprintf|snprintf|puts|putchar|fopen|fwrite|qsort|abort|exit)$')"
# Soft-float helpers: AEABI names (__aeabi_fadd, __aeabi_d2f, __aeabi_i2f, __aeabi_cfcmple, ...)
# and libgcc's generic ones (__addsf3, __floatsisf, __fixdfsi, __extendsfdf2, ...).
single='^__aeabi_(f[a-z0-9]*|[iul]+2f|cf[a-z0-9]*)$|^__[a-z]+sf[0-9]$|^__[a-z]+sf$'
double='^__aeabi_(d[a-z0-9]*|[iul]+2d|cd[a-z0-9]*)$|^__[a-z]+df[0-9]$|^__[a-z]+df$'
libm='^(sin|cos|tan|exp|log|pow|sqrt|atan2?|acos|asin|sinh|cosh|tanh|floor|ceil|fmod)f?$'
case $variant in
*fixed*) check "no floating-point helpers (fixed build is integer-only)" \
             "$(echo "$undef" | grep -E "$single|$double")" ;;
*)       check "no double-precision helpers" "$(echo "$undef" | grep -E "$double")" ;;
esac
check "no libm calls" "$(echo "$undef" | grep -E "$libm")"
check "every global symbol starts with subd_" "$(echo "$defined" | grep -v '^subd_')"
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
