#!/bin/sh
# SPDX-License-Identifier: MIT
# Every source, header, script, build and linker file carries "SPDX-License-Identifier: MIT"
# in its first three lines (issue 14). Data (meshes, corpora, pictures) and prose (*.md,
# LICENSE) are not source. Lists the repository's files with git when it can, else find.
# usage: test/scripts/spdx_check.sh [ROOT]
cd "${1:-.}" || exit 1
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then list="git ls-files"; else list="find . -type f ! -path ./build/* ! -path ./dist/* ! -path ./.git/*"; fi
n=0 bad=0
for f in $($list); do
    case $f in
        *.c | *.h | *.cpp | *.hpp | *.sh | *.ld | *.cmake | *.cmake.in | *.py | *.awk | */CMakeLists.txt | CMakeLists.txt | Makefile | */Makefile | .ci/*) ;;
        *) continue ;;
    esac
    n=$((n + 1))
    if ! head -n 3 "$f" | grep -q "SPDX-License-Identifier: MIT"; then
        echo "FAIL $f: no 'SPDX-License-Identifier: MIT' in its first three lines"
        bad=$((bad + 1))
    fi
done
[ $n -gt 0 ] || { echo "FAIL no source files found"; exit 1; }
[ $bad -eq 0 ] || { echo "FAIL SPDX: $bad of $n files"; echo "$((n - bad)) passed, $bad failed"; exit 1; }
echo "PASS SPDX line in all $n source, header, script, build and linker files"
echo "$n passed, 0 failed"
