#!/bin/sh
# SPDX-License-Identifier: MIT
# Flag-proof bit-exactness, the static half (the run-time half is host-gnu's hashes and
# subd_selfcheck): the library built as an integrator might (-std=gnu11 -O2, which lets GCC
# contract a*b+c into one fused multiply-add, and no -ffp-contract=off) has no fused
# multiply-add instruction, because every src/*.c starts with src/fp_contract.h.
# usage: contract_proofs.sh ARM_OBJDUMP M4F_GNU_LIB HOST_GNU_SRC_OBJ_DIR
objdump_arm=$1 lib=$2 hostdir=$3
pass=0 fail=0
ok() { pass=$((pass + 1)); echo "ok - $1"; }
bad() { fail=$((fail + 1)); echo "not ok - $1"; }

missing=
for f in src/*.c; do
    first=$(grep -m 1 '^#include' "$f")
    case $first in '#include "fp_contract.h"'*) ;; *) missing="$missing $f" ;; esac
done
if [ -z "$missing" ]; then ok "every src/*.c includes fp_contract.h first"
else bad "src files whose first #include is not fp_contract.h:$missing"; fi

# VFPv4 fused forms: vfma.f32 vfms.f32 vfnma.f32 vfnms.f32
n=$("$objdump_arm" -d "$lib" | grep -cE '[[:space:]]vfn?m[as](\.f32|[[:space:]])')
if [ -f "$lib" ] && [ "$n" -eq 0 ]; then ok "m4f-gnu libsubd.a (gnu11 -O2, no -ffp-contract=off): 0 vfma/vfms/vfnma/vfnms"
else bad "m4f-gnu libsubd.a: $n fused multiply-add instructions"
    "$objdump_arm" -d "$lib" | grep -E '^[0-9a-f]+ <|[[:space:]]vfn?m[as](\.f32|[[:space:]])' |
        grep -B1 -E '[[:space:]]vfn?m[as]' | grep '^[0-9a-f]* <' | head -10 | sed 's/^/    in /'; fi

# x86 FMA3 forms: vfmadd/vfmsub/vfnmadd/vfnmsub (and vfmaddsub/vfmsubadd)
if ls "$hostdir"/*.o > /dev/null 2>&1 && command -v objdump > /dev/null 2>&1; then
    n=0
    for o in "$hostdir"/*.o; do
        k=$(objdump -d "$o" | grep -cE '[[:space:]]vfn?m(add|sub)')
        [ "$k" -eq 0 ] || echo "    $(basename "$o"): $k"
        n=$((n + k))
    done
    if [ "$n" -eq 0 ]; then ok "host-gnu library objects (gnu11 -O2 $(uname -m)): 0 fused multiply-add instructions"
    else bad "host-gnu library objects: $n fused multiply-add instructions"; fi
else
    bad "no host-gnu objects in $hostdir"
fi
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
