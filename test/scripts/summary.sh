#!/bin/sh
# SPDX-License-Identifier: MIT
# Sums the final "N passed, M failed" line of every suite log into one line and fails when
# any suite failed or a log has no summary line (a crash or hang before the end).
# usage: summary.sh LOG...
tp=0 tf=0
for f in "$@"; do
    line=$(grep -E '^[0-9]+ passed, [0-9]+ failed$' "$f" 2>/dev/null | tail -n 1)
    if [ -z "$line" ]; then
        echo "no summary in $f (suite crashed, hung or did not run)"
        tf=$((tf + 1))
        continue
    fi
    p=${line%% passed*}; q=${line#*passed, }; q=${q%% failed}
    tp=$((tp + p)); tf=$((tf + q))
    [ "$q" -eq 0 ] || echo "failures in $f"
done
echo "$tp passed, $tf failed"
[ "$tf" -eq 0 ]
