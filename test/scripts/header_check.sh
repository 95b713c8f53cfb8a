#!/bin/sh
# SPDX-License-Identifier: MIT
# Checks the public headers' documentation template (issue 14): every exported call
# (a non-static prototype of a subd_* function in include/*.h) is preceded by a comment whose
# text has the sections "Memory:", "Errors:" and "Cost:" (a summary first; "Notes:" optional;
# prototypes written one after another share the comment above the first), and no header
# names a file outside the repository (papers are cited by authors, title and year).
# usage: test/scripts/header_check.sh [include-dir]
dir=${1:-include}
fails=0
for h in "$dir"/*.h; do
    out=$(awk -v file="$h" '
        function check(name) {
            miss = ""
            if (index(doc, "Memory:") == 0) miss = miss " Memory:"
            if (index(doc, "Errors:") == 0) miss = miss " Errors:"
            if (index(doc, "Cost:") == 0) miss = miss " Cost:"
            if (miss != "") printf "%s:%d: %s: comment lacks%s\n", file, NR, name, miss
        }
        /^\/\*/ { incomment = 1; cur = "" }
        incomment { cur = cur " " $0 }
        incomment && /\*\// { incomment = 0; doc = cur; last = "comment"; next }
        incomment { next }
        /^[a-z][a-z0-9_ ]*[ *]subd_[a-z0-9_]+\(/ && !/^static/ && !/^typedef/ {
            match($0, /subd_[a-z0-9_]+\(/)
            name = substr($0, RSTART, RLENGTH - 1)
            if (last == "comment" || last == "proto") check(name)
            else printf "%s:%d: %s: no comment directly above\n", file, NR, name
            last = "proto"; proto_open = ($0 !~ /;/); next
        }
        proto_open { if ($0 ~ /;/) proto_open = 0; next }
        /^[ \t]*$/ { if (last == "proto") last = "gap"; else if (last == "comment") last = "gap"; next }
        { last = "other" }
    ' "$h")
    if [ -n "$out" ]; then echo "$out"; fails=$((fails + $(echo "$out" | wc -l))); fi
    if grep -nE '\.\./shared|REFERENCE\.md|DESIGN\.md|STYLE\.md|papers/|[a-z0-9-]+\.txt' "$h"; then
        echo "$h: names a file outside the repository (cite the paper by authors, title, year)"
        fails=$((fails + 1))
    fi
done
n=$(grep -hcE '^[a-z][a-z0-9_ ]*[ *]subd_[a-z0-9_]+\(' "$dir"/*.h | awk '{s += $1} END {print s}')
if [ $fails -ne 0 ]; then echo "FAIL header template: $fails problem(s)"; echo "$((n - fails)) passed, $fails failed"; exit 1; fi
echo "PASS header template: $n exported calls documented (Memory, Errors, Cost), no outside file named"
echo "$n passed, 0 failed"
