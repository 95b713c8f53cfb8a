#!/bin/sh
# SPDX-License-Identifier: MIT
# Instructions per function of the uniform semi-regular 4-8 stream on the Cortex-M, from a
# QEMU execution trace (a development tool; never part of make test).
#
#   tools/profile_qemu.sh [VARIANT [STEPS [MESH]]]
#       VARIANT  m4f-float (default, mps2-an386) or m3-fixed (mps2-an385)
#       STEPS    the stream's max_level (default 8)
#       MESH     an OBJ file linked into the image (default test/data/icosahedron.obj)
#   e.g. tools/profile_qemu.sh m4f-float 8
#
# Builds the variant's libsubd.a (make), then a trimmed image (build/VARIANT/profile/) whose
# main reads the mesh, makes its subd_sr48_base and streams it uniformly at STEPS into a
# counting sink (the demo's counting-sink measurement, port/cortex-m/demo_sr48.c, alone), and
# runs it under QEMU with `-d in_asm,exec,nochain`: every translation block's instruction
# count (in_asm) times its executions (exec; nochain logs each one), summed per function
# (arm-none-eabi-nm; static inline functions count in their callers). Prints the functions
# by instructions, the total, and per output face (the stream call only: the base and the
# parse run before the trace starts counting, between two marker calls). The trace is
# large (about 0.2 GB at 8 steps on the icosahedron); it is read through a FIFO, not kept.
set -eu

variant=${1:-m4f-float}
steps=${2:-8}
mesh=${3:-test/data/icosahedron.obj}
case $variant in
    m4f-float) machine=mps2-an386 ;;
    m3-fixed) machine=mps2-an385 ;;
    *) echo "usage: $0 [m4f-float|m3-fixed [STEPS [MESH]]]" >&2; exit 2 ;;
esac
cd "$(dirname "$0")/.."
make -s "build/$variant/libsubd.a" "build/$variant/port/cortex-m/startup.o" \
    "build/$variant/port/cortex-m/port_cm.o" "build/$variant/port/print.o"
dir=build/$variant/profile
mkdir -p "$dir"

# the mesh as a C string
{
    printf 'static const char prof_obj[] =\n'
    sed -e 's/\\/\\\\/g' -e 's/"/\\"/g' -e 's/^/    "/' -e 's/$/\\n"/' "$mesh"
    printf ';\n'
} >"$dir/mesh.h"

cat >"$dir/main.c" <<EOF
#include "subd.h"
#include "print.h"
#include "port_cm.h"
#include "mesh.h"
static uint8_t prof_arena[256u * 1024u] __attribute__((aligned(8)));
static uint8_t prof_stream[128u * 1024u] __attribute__((aligned(8)));
static int prof_count(void *ctx, const subd_tri *t)
{
    (void)t;
    ++*(uint32_t *)ctx;
    return 0;
}
/* the trace counts between the two calls of this (not inlined: its address is the marker) */
__attribute__((noinline)) void prof_mark(uint32_t on);
__attribute__((noinline)) void prof_mark(uint32_t on) { __asm__ volatile("" : : "r"(on) : "memory"); }
int main(void)
{
    subd_arena a, sa;
    subd_mesh m;
    subd_sr48 base;
    subd_sr48_stream_opts so;
    subd_tri_sink sink;
    subd_diag d;
    uint32_t plan = 0, n = 0;
    int st;
    subd_arena_init(&a, prof_arena, sizeof prof_arena);
    if ((st = subd_obj_read(&a, prof_obj, sizeof prof_obj - 1u, &m, &d)) != SUBD_OK) return 10;
    if ((st = subd_sr48_base(&a, &m, 0, &base, &d)) != SUBD_OK) return 11;
    so.adapt.mode = SUBD_SR48_ADAPT_UNIFORM;
    so.adapt.max_level = $steps;
    if ((st = subd_sr48_stream_plan(&base, &so, &plan, &d)) != SUBD_OK || plan > sizeof prof_stream) return 12;
    subd_arena_init(&sa, prof_stream, plan);
    sink.tri = prof_count;
    sink.ctx = &n;
    prof_mark(1u);
    st = subd_sr48_stream(&sa, &base, &so, &sink, &d);
    prof_mark(0u);
    if (st != SUBD_OK) return 13;
    print_str("faces ");
    print_u32(n);
    print_nl();
    return 0;
}
EOF

cc=arm-none-eabi-gcc
eval "$(make -s -p -n 2>/dev/null | awk -v v="$variant" '
    $1 == "ARCH_" v { sub(/^[^=]*= */, ""); print "arch=\"" $0 "\"" }
    $1 == "LDS_" v { sub(/^[^=]*= */, ""); print "lds=\"" $0 "\"" }')"
fixed=0
[ "$variant" = m3-fixed ] && fixed=1
# shellcheck disable=SC2086
$cc $arch -O2 -g -std=c99 -DSUBD_FIXED=$fixed -Iinclude -Iport -Iport/cortex-m -I"$dir" \
    -c "$dir/main.c" -o "$dir/main.o"
# shellcheck disable=SC2086
$cc $arch -nostartfiles --specs=nano.specs -Wl,--gc-sections -T "$lds" \
    "build/$variant/port/cortex-m/startup.o" "build/$variant/port/cortex-m/port_cm.o" \
    "build/$variant/port/print.o" "$dir/main.o" "build/$variant/libsubd.a" -o "$dir/profile.elf"

arm-none-eabi-nm -n --defined-only "$dir/profile.elf" | awk '$2 ~ /^[tTwW]$/ { print $1, $3 }' >"$dir/syms.txt"
mark=$(awk '$2 == "prof_mark" { print $1 }' "$dir/syms.txt")

fifo=$dir/trace.fifo
rm -f "$fifo"
mkfifo "$fifo"
# in_asm: "IN: sym", then one "0xADDR:  ..." line per instruction; exec (nochain: every
# execution): "Trace N: HOSTPTR [CSBASE/PC/FLAGS/CFLAGS] sym". Counting starts after the
# first execution of prof_mark and stops at its second. Per block (instructions, start
# address, length, function) into build/VARIANT/profile/blocks.txt, for addr2line.
awk -v syms="$dir/syms.txt" -v mark="$mark" -v tbs="$dir/blocks.txt" '
    function hex(s,  i, c, n) { n = 0; s = tolower(s); sub(/^0x/, "", s)
        for (i = 1; i <= length(s); i++) { c = index("0123456789abcdef", substr(s, i, 1)) - 1; n = n * 16 + c }
        return n }
    BEGIN { ns = 0; while ((getline l < syms) > 0) { split(l, sf, " "); sa[ns] = hex(sf[1]); sn[ns] = sf[2]; ns++ }
            mk = hex(mark); on = 0; marks = 0 }
    /^IN:/ { inb = 1; start = -1; next }
    inb && /^0x[0-9a-f]+:/ { a = hex(substr($1, 1, length($1) - 1)); if (start < 0) start = a; cnt[start]++; next }
    inb && /^$/ { inb = 0; next }
    /^Trace / { split($0, b, "/"); pc = hex(b[2])
        if (pc == mk) { marks++; on = (marks == 1); next }
        if (on) exec[pc]++ }
    END {
        for (pc in exec) {
            lo = 0; hi = ns - 1
            while (lo < hi) { mid = int((lo + hi + 1) / 2); if (sa[mid] <= pc + 0) lo = mid; else hi = mid - 1 }
            fn[sn[lo]] += exec[pc] * cnt[pc]; tot += exec[pc] * cnt[pc]
            printf "%12d %08x %4d %s\n", exec[pc] * cnt[pc], pc, cnt[pc], sn[lo] | "sort -rn > " tbs
        }
        close("sort -rn > " tbs)
        for (g in fn) printf "%12d %6.2f%% %s\n", fn[g], 100 * fn[g] / tot, g | "sort -rn"
        close("sort -rn")
        printf "%12d total\n", tot
    }' <"$fifo" >"$dir/profile.txt" &
awk_pid=$!
qemu-system-arm -M "$machine" -nographic -monitor none -serial none \
    -semihosting-config enable=on,target=native -icount shift=0 \
    -d in_asm,exec,nochain -D "$fifo" -kernel "$dir/profile.elf" </dev/null >"$dir/out.txt"
wait "$awk_pid"
rm -f "$fifo"
faces=$(awk '$1 == "faces" { print $2 }' "$dir/out.txt")
cat "$dir/profile.txt"
tot=$(awk '$2 == "total" { print $1 }' "$dir/profile.txt")
echo "faces $faces, instructions per face $((tot / faces))"
