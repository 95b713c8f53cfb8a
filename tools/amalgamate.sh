#!/bin/sh
# SPDX-License-Identifier: MIT
# Writes the single-file form of the library (make amalgamate):
#   OUTDIR/tinysubd.h  the public headers include/*.h, from include/subd.h in dependency order
#                      (each header expanded where it is first included), include guards and
#                      extern "C" blocks kept;
#   OUTDIR/tinysubd.c  every src/*.c in name order (the order of the Makefile's SRC), each internal
#                      header src/*.h expanded once, where it is first included; the public
#                      headers become one #include "tinysubd.h".
# Why so, where a unity build differs from separate compilation:
#   - A macro a .c file #defines would reach every later file (selfcheck.c's A and C would
#     rename identifiers in sqrt.c onwards): each .c file's own macros are #undef'd at its end,
#     here, so a macro added to a source tomorrow cannot leak either. A .c file that #defines
#     or #undefs a macro of a header stops the script (it would change the later files).
#   - A quoted #include under #if would be expanded once, in whichever branch came first:
#     refused (outside a header's include guard).
#   - Static names that two files share do not compile in one unit: they are renamed in src/
#     (make test compiles this output with the library's -Werror flags, host and Cortex-M).
# Deterministic: the output depends only on the files' bytes (C locale, no dates, no paths
# outside the repository). Fails (exit 1, nothing written) on an #include "..." that resolves
# neither next to the including file nor in include/, and on a file whose first line is not
# the MIT SPDX line.
# usage: tools/amalgamate.sh [OUTDIR]     (default dist; relative to the repository root)
set -eu
LC_ALL=C
export LC_ALL
cd "$(dirname "$0")/.."
out=${1:-dist}

srcs= pubs= hdrs=
for f in src/*.c; do srcs="$srcs $f"; done
for f in include/*.h; do pubs="$pubs $f"; done
for f in src/*.h include/*.h; do hdrs="$hdrs $f"; done
case "$srcs$pubs$hdrs" in *'*'*) echo "$0: no sources found" >&2; exit 1 ;; esac

version=$(awk '$1 == "#define" && $2 ~ /^SUBD_VERSION_(MAJOR|MINOR|PATCH)$/ { v[$2] = $3 }
    END { print v["SUBD_VERSION_MAJOR"] "." v["SUBD_VERSION_MINOR"] "." v["SUBD_VERSION_PATCH"] }' \
    include/subd.h)
case $version in [0-9]*.[0-9]*.[0-9]*) ;; *) echo "$0: no SUBD_VERSION_* in include/subd.h" >&2; exit 1 ;; esac

# mode c: expand the files of `files` as translation unit parts; mode h: as headers.
amalg() { # mode, files...
    mode=$1
    shift
    awk -v mode="$mode" -v files="$*" -v pub="$pubs" -v hdrs="$hdrs" '
    function die(msg) { print "tools/amalgamate.sh: " msg > "/dev/stderr"; failed = 1; exit 1 }
    function readable(p,    l, r) {
        if (p in active || p in done) return 1
        r = (getline l < p)
        if (r < 0) return 0
        close(p)
        return 1
    }
    # Like the compiler: next to the including file first, then the public include/ directory.
    function resolve(name, from,    d) {
        d = from
        sub(/[^\/]*$/, "", d)
        if (readable(d name)) return d name
        if (readable("include/" name)) return "include/" name
        return ""
    }
    function macro_name(line,    s) {
        s = line
        sub(/^[ \t]*#[ \t]*(define|undef)[ \t]+/, "", s)
        match(s, /^[A-Za-z_][A-Za-z0-9_]*/)
        return substr(s, 1, RLENGTH)
    }
    # Emits path with its quoted includes expanded (each file once); top = a .c file of the unit.
    function expand(path, top,    line, r, nr, name, q, depth, nd, defs, k, m) {
        active[path] = 1
        done[path] = 1
        print "/* ---- " path " ---- */"
        nr = 0; depth = 0; nd = 0
        while ((r = (getline line < path)) > 0) {
            nr++
            if (nr == 1) {
                if (line != spdx) die(path ":1: the first line is not " spdx)
                continue
            }
            if (line ~ /^[ \t]*#[ \t]*if/) depth++
            if (line ~ /^[ \t]*#[ \t]*endif/) depth--
            if (line ~ /^[ \t]*#[ \t]*include[ \t]*"/) {
                name = line
                sub(/^[ \t]*#[ \t]*include[ \t]*"/, "", name)
                if (name !~ /"/) die(path ":" nr ": malformed #include")
                sub(/".*$/, "", name)
                if (depth > (top ? 0 : 1))
                    die(path ":" nr ": #include \"" name "\" under #if cannot be expanded once")
                q = resolve(name, path)
                if (q == "") die(path ":" nr ": cannot resolve #include \"" name "\"")
                if (mode == "c" && (q in ispub)) {
                    if (!pubdone) print "#include \"tinysubd.h\" /* " name " and the other public headers */"
                    else print "/* #include \"" name "\": in tinysubd.h */"
                    pubdone = 1
                } else if (q in done) {
                    print "/* #include \"" name "\": above */"
                } else {
                    # Clang warns about an unused static inline function of the main file,
                    # not of a header: an internal header keeps its header status here.
                    if (mode == "c") print "#if defined(__GNUC__)\n#pragma GCC diagnostic push\n#pragma GCC diagnostic ignored \"-Wunused-function\"\n#endif"
                    expand(q, 0)
                    if (mode == "c") print "#if defined(__GNUC__)\n#pragma GCC diagnostic pop\n#endif"
                    print "/* ---- (" path ", continued) ---- */"
                }
                continue
            }
            if (top && line ~ /^[ \t]*#[ \t]*(define|undef)[ \t]/) {
                m = macro_name(line)
                if (m in hdrmacro) die(path ":" nr ": " m " is a header macro: a unity build would change it for the later files")
                if (line ~ /^[ \t]*#[ \t]*define/ && !(m in defs)) { defs[m] = 1; nd++; order[nd] = m }
            }
            print line
        }
        if (r < 0) die("cannot read " path)
        close(path)
        delete active[path]
        if (nd > 0) {
            print "/* " path "'"'"'s own macros end with it (one translation unit) */"
            for (k = 1; k <= nd; k++) print "#undef " order[k]
        }
    }
    BEGIN {
        spdx = "/* SPDX-License-Identifier: MIT */"
        n = split(pub, P, " ")
        for (i = 1; i <= n; i++) ispub[P[i]] = 1
        n = split(hdrs, H, " ")
        for (i = 1; i <= n; i++) {
            while ((r = (getline line < H[i])) > 0)
                if (line ~ /^[ \t]*#[ \t]*define[ \t]/) hdrmacro[macro_name(line)] = 1
            if (r < 0) die("cannot read " H[i])
            close(H[i])
        }
        n = split(files, F, " ")
        for (i = 1; i <= n; i++) {
            if (F[i] in done) continue
            expand(F[i], mode == "c")
            print ""
        }
    }
    END { if (failed) exit 1 }'
}

header() { # what, body file: the files in the order of their banners
    printf '%s\n' "/* SPDX-License-Identifier: MIT */" \
        "/* tinysubd $version, single-file form: $1" \
        " * Generated by tools/amalgamate.sh (make amalgamate) from these files, in this order:"
    sed -n 's|^/\* ---- \([^ (]*\) ---- \*/$|\1|p' "$2" | awk '
        s != "" && length(s) + 1 + length($0) > 88 { print " *   " s; s = "" }
        { s = s (s == "" ? "" : " ") $0 } END { if (s != "") print " *   " s }'
    printf '%s\n' " * Edit those files, not this one: make amalgamate regenerates it byte for byte." " */" ""
}

mkdir -p "$out"
tmp="$out/.amalgamate.tmp"
trap 'rm -f "$tmp" "$out/tinysubd.h.tmp" "$out/tinysubd.c.tmp"' EXIT
amalg h include/subd.h $pubs > "$tmp"
{
    header "the public API: the headers of include/, include
 * guards and extern \"C\" blocks kept. Compile tinysubd.c with the same SUBD_* options." "$tmp"
    cat "$tmp"
} > "$out/tinysubd.h.tmp"
amalg c $srcs > "$tmp"
{
    header "the whole library as one translation unit. Build it
 * as C99 next to tinysubd.h, e.g. cc -std=c99 -O2 [-DSUBD_FIXED=1] -c tinysubd.c, with the
 * same SUBD_* options for every file that includes tinysubd.h. Bit-exactness needs no flag:
 * src/fp_contract.h (first, below) turns float contraction off for the whole unit (clang's
 * -ffp-contract=fast overrides it: don't use that)." "$tmp"
    cat "$tmp"
} > "$out/tinysubd.c.tmp"
mv "$out/tinysubd.h.tmp" "$out/tinysubd.h"
mv "$out/tinysubd.c.tmp" "$out/tinysubd.c"
rm -f "$tmp"
trap - EXIT
echo "tools/amalgamate.sh: wrote $out/tinysubd.c ($(wc -l < "$out/tinysubd.c") lines), $out/tinysubd.h ($(wc -l < "$out/tinysubd.h") lines)"
