#!/bin/sh
# SPDX-License-Identifier: MIT
# Compiles test/cpp/smoke.cpp as C++11 with warnings as errors against the library objects of
# both arithmetics (the tool variants' objects, built by `make tool`) and runs it.
# usage: cpp_test.sh BUILD_DIR   (prints "N passed, M failed" like the other suites)
B=$1
CXX=${CXX:-g++}
p=0 f=0
for v in float fixed; do
    fixed=0; [ "$v" = fixed ] && fixed=1
    out="$B/cpp/smoke-$v"
    mkdir -p "$B/cpp"
    if $CXX -std=c++11 -Wall -Wextra -Werror -pedantic -Iinclude -DSUBD_FIXED=$fixed test/cpp/smoke.cpp \
        "$B"/tool-$v/src/*.o -o "$out" && "$out"; then
        echo "ok   c++ smoke ($v)"; p=$((p + 1))
    else
        echo "FAIL c++ smoke ($v)"; f=$((f + 1))
    fi
done
echo "$p passed, $f failed"
[ "$f" -eq 0 ]
