#!/bin/sh
# SPDX-License-Identifier: MIT
# Runs one test image (host binary or QEMU), keeps its whole output in LOG, and prints a
# one-line result (or the whole log when something failed). A non-zero exit status with no
# failure counted (a sanitizer report, a fault, a timeout) is recorded as one failure, so
# the summary can never read "0 failed" for a run that did not end cleanly.
# usage: run_suite.sh LABEL LOG COMMAND...
label=$1 log=$2
shift 2
"$@" > "$log" 2>&1
rc=$?
last=$(grep -E '^[0-9]+ passed, [0-9]+ failed$' "$log" | tail -n 1)
p=0 f=0
if [ -n "$last" ]; then p=${last%% passed*}; f=${last#*passed, }; f=${f%% failed}; fi
if [ $rc -ne 0 ] && [ "$f" -eq 0 ]; then
    echo "$p passed, 1 failed" >> "$log"
    f=1
fi
if [ "$f" -ne 0 ] || [ $rc -ne 0 ]; then
    echo "== $label: FAILED (exit $rc); log $log:"
    sed 's/^/   /' "$log" | grep -v '^   ok ' | tail -n 60
else
    printf '== %-34s %s\n' "$label" "$(tail -n 1 "$log")"
fi
exit 0
