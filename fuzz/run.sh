#!/bin/sh
# SPDX-License-Identifier: MIT
# Runs every fuzz target for SECONDS seconds, one process each (no -jobs/-workers: a single
# process per target, one target at a time), new inputs into build/fuzz/work/<target>-<arith>/
# (the committed corpus fuzz/corpus/<target>/ is read, not written), crash artifacts into
# build/fuzz/artifacts/. Prints the executions of each run and fails if any target failed.
# usage: fuzz/run.sh SECONDS BINDIR_FLOAT BINDIR_FIXED
secs=$1 bf=$2 bx=$3
out=build/fuzz
mkdir -p $out/work $out/artifacts $out/logs
fails=0
summary=""
for arith in float fixed; do
    [ $arith = float ] && bin=$bf || bin=$bx
    for t in obj off schemes stl ply sr48s; do
        case $t in obj|off|stl|ply) maxlen=4096 ;; *) maxlen=512 ;; esac
        w=$out/work/$t-$arith log=$out/logs/$t-$arith.log
        mkdir -p $w
        echo "== fuzz $t ($arith), $secs s"
        $bin/fuzz_$t $w fuzz/corpus/$t -max_total_time=$secs -max_len=$maxlen -timeout=20 \
            -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix=$out/artifacts/$t-$arith- > $log 2>&1
        rc=$?
        execs=$(grep -E '^stat::number_of_executed_units' $log | awk '{print $2}')
        cov=$(grep -E '^#[0-9]+.*(DONE|cov:)' $log | tail -n 1 | sed 's/^#[0-9]* *//')
        line="fuzz_$t $arith: ${execs:-?} executions in $secs s, exit $rc ($cov)"
        echo "   $line"
        summary="$summary
$line"
        if [ $rc -ne 0 ]; then
            fails=$((fails + 1))
            grep -E 'ERROR|fuzz check failed|runtime error|SUMMARY|Test unit written' $log | head -n 8 | sed 's/^/   /'
        fi
    done
done
echo "== fuzz summary$summary"
[ $fails -eq 0 ] || { echo "$fails fuzz run(s) failed; logs in $out/logs, inputs in $out/artifacts"; exit 1; }
