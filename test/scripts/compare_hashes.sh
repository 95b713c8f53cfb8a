#!/bin/sh
# SPDX-License-Identifier: MIT
# Bit-exactness check: the HASH lines printed by the host test run and by the QEMU run of
# the same arithmetic must be identical (same names, same values, same order).
# usage: compare_hashes.sh HOST_LOG TARGET_LOG LABEL
a=$(grep '^HASH ' "$1" 2>/dev/null) b=$(grep '^HASH ' "$2" 2>/dev/null)
n=$(printf '%s\n' "$a" | grep -c '^HASH ')
if [ -n "$a" ] && [ "$a" = "$b" ]; then
    echo "ok - $3: $n output hashes identical"
    echo "1 passed, 0 failed"
else
    echo "not ok - $3: output hashes differ ($n on host)"
    printf '%s\n' "$a" > "$1.hashes"; printf '%s\n' "$b" > "$2.hashes"
    diff "$1.hashes" "$2.hashes" | head -20 | sed 's/^/    /'
    echo "0 passed, 1 failed"
    exit 1
fi
