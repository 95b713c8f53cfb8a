#!/bin/sh
# SPDX-License-Identifier: MIT
# Runs one test image (host binary or QEMU), keeps its whole output in LOG, and prints a
# one-line result (or the whole log when something failed). A non-zero exit status with no
# failure counted (a sanitizer report, a fault, a timeout) is recorded as one failure, so
# the summary can never read "0 failed" for a run that did not end cleanly. The result line
# ends with the stage's cost, "[N.N s, cpu N.N s]": wall seconds and the user+system CPU
# seconds of everything it ran (what counts on a shared machine); the log keeps its own last
# line "N passed, M failed" for summary.sh.
# usage: run_suite.sh LABEL LOG COMMAND...
label=$1 log=$2
shift 2
t0=$(date +%s%N)
"$@" > "$log" 2>&1
rc=$?
t1=$(date +%s%N)
# The second line of `times` (run by this shell, not a subshell): user and system time of
# the waited-for children, "XmY.YYYs".
times > "$log.cpu"
cost=$(awk -v ns=$((t1 - t0)) 'NR == 2 {
    split($1, u, /[ms]/); split($2, s, /[ms]/)
    printf "[%.1f s, cpu %.1f s]", ns / 1e9, u[1] * 60 + u[2] + s[1] * 60 + s[2] }' "$log.cpu")
rm -f "$log.cpu"
last=$(grep -E '^[0-9]+ passed, [0-9]+ failed$' "$log" | tail -n 1)
p=0 f=0
if [ -n "$last" ]; then p=${last%% passed*}; f=${last#*passed, }; f=${f%% failed}; fi
if [ $rc -ne 0 ] && [ "$f" -eq 0 ]; then
    echo "$p passed, 1 failed" >> "$log"
    f=1
fi
if [ "$f" -ne 0 ] || [ $rc -ne 0 ]; then
    echo "== $label: FAILED (exit $rc) $cost; log $log:"
    sed 's/^/   /' "$log" | grep -v '^   ok ' | tail -n 60
else
    printf '== %-34s %s  %s\n' "$label" "$(tail -n 1 "$log")" "$cost"
fi
exit 0
