#!/bin/sh
# SPDX-License-Identifier: MIT
# Proves the test machinery can fail: on each target, an image whose check fails, one that
# HardFaults and one that hangs must each make the run fail (non-zero / timeout), and a
# passing image must pass. The injected-failure test image must end "N passed, 1 failed"
# and make summary.sh fail.
# usage: harness_selftest.sh MACHINE DIR      (DIR holds selftest0..3.elf, test-fail.elf)
m=$1 d=$2
pass=0 fail=0
expect() { # label, wanted ("0", "nonzero" or a number), actual
    case $2 in
    nonzero) [ "$3" -ne 0 ] ;;
    *) [ "$3" -eq "$2" ] ;;
    esac
    if [ $? -eq 0 ]; then pass=$((pass + 1)); echo "ok - $m: $1 (exit $3)"
    else fail=$((fail + 1)); echo "not ok - $m: $1: wanted $2, got $3"; fi
}
here=$(dirname "$0")
qemu/run.sh "$m" "$d/selftest0.elf" 60 >/dev/null 2>&1; expect "passing image passes" 0 $?
qemu/run.sh "$m" "$d/selftest1.elf" 60 >/dev/null 2>&1; expect "failing check fails" nonzero $?
qemu/run.sh "$m" "$d/selftest2.elf" 60 > "$d/selftest2.log" 2>&1; rc=$?
expect "HardFault fails" nonzero $rc
grep -q HARDFAULT "$d/selftest2.log"; expect "HardFault is reported" 0 $?
qemu/run.sh "$m" "$d/selftest3.elf" 3 >/dev/null 2>&1; expect "hang times out" 124 $?
qemu/run.sh "$m" "$d/test-fail.elf" 600 > "$d/test-fail.log" 2>&1; expect "injected CHECK failure fails the suite" 1 $?
grep -Eq '^[0-9]+ passed, 1 failed$' "$d/test-fail.log"; expect "injected failure is counted" 0 $?
"$here/summary.sh" "$d/test-fail.log" >/dev/null 2>&1; expect "summary fails on it" nonzero $?
echo "$pass passed, $fail failed"
