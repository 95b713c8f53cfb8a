#!/bin/sh
# SPDX-License-Identifier: MIT
# Boots one Cortex-M test or demo image in QEMU and returns the image's own exit status.
#
#   qemu/run.sh MACHINE ELF [TIMEOUT_SECONDS]      e.g. qemu/run.sh mps2-an386 build/x.elf
#
# The image talks to the host only through Arm semihosting: its output appears on stdout,
# and SYS_EXIT_EXTENDED makes QEMU exit with the image's status (port/cortex-m/port_cm.c).
# Exit status: the image's (0 pass, 1 test failure, 3 fault report from startup.c);
# 124 on timeout (after printing "TIMEOUT after N s: ELF" on stderr); 127 if QEMU is
# missing; 2 on a usage error. QEMU's own errors (bad ELF, unknown machine) give 1.
#
# -icount shift=0 makes every instruction take exactly 1 ns of virtual time, so timers
# read by the image (port_cycles) count instructions and repeat exactly from run to run.
# It costs about 1.6x in speed. Stdin is never read (</dev/null), so this works in CI and
# under make -j without a terminal. Set QEMU to use another binary.
set -u

if [ $# -lt 2 ] || [ $# -gt 3 ]; then
    echo "usage: $0 MACHINE ELF [TIMEOUT_SECONDS]" >&2
    exit 2
fi
machine=$1
elf=$2
limit=${3:-120}
qemu=${QEMU:-qemu-system-arm}

if ! command -v "$qemu" >/dev/null 2>&1; then
    echo "$0: $qemu not found; install the Debian package qemu-system-arm" >&2
    exit 127
fi
if [ ! -f "$elf" ]; then
    echo "$0: no such image: $elf" >&2
    exit 2
fi

# -nographic with no serial port and no monitor leaves stdout to semihosting alone. The
# second timeout (-k) kills QEMU outright should it ignore SIGTERM.
timeout -k 5 "$limit" "$qemu" -M "$machine" -nographic -monitor none -serial none \
    -semihosting-config enable=on,target=native -icount shift=0 \
    -kernel "$elf" </dev/null
status=$?

# timeout reports 124 when it sent SIGTERM, 137 when it had to send SIGKILL.
if [ $status -eq 124 ] || [ $status -eq 137 ]; then
    echo "TIMEOUT after $limit s: $elf" >&2
    exit 124
fi
exit $status
