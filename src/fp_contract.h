/* SPDX-License-Identifier: MIT */
/* No floating-point contraction in library code, whatever flags the integrator compiles with.
 *
 * Bit-exact host = device needs every float product rounded before it is added. A fused
 * multiply-add (vfma/vfms/vfnma/vfnms on Cortex-M4F/M7, vfmadd... on x86 with FMA) rounds once
 * and changes the bits. GCC contracts across statements in its GNU modes: the default
 * -std=gnu11 means -ffp-contract=fast (only -std=c99/c11 or -ffp-contract=off do not), and
 * the library must not depend on the integrator passing either.
 *
 * This header is the first #include of every .c file in src/ (test/scripts/contract_proofs.sh checks), so the
 * pragmas cover every function of the translation unit, subd_real.h's inline operations
 * included (contraction is decided per function after inlining, by the caller's setting):
 *   GCC:   #pragma GCC optimize("fp-contract=off"): each function defined after it is compiled
 *          as with -ffp-contract=off. GCC 12 checked: the code of every src file is identical
 *          to a -ffp-contract=off build (x86-64 -march=haswell and Cortex-M4F); GCC ignores
 *          #pragma STDC FP_CONTRACT, hence the GCC form.
 *   Clang: #pragma STDC FP_CONTRACT OFF (C99 7.12.2), honoured under clang's default
 *          -ffp-contract=on. clang's -ffp-contract=fast disregards pragmas by design (its
 *          -ffp-contract=fast-honor-pragmas does not); subd_selfcheck() reports such a build.
 * The Q16.16 build has no float code; the pragmas change nothing there.
 */
#ifndef SUBD_FP_CONTRACT_H
#define SUBD_FP_CONTRACT_H
#if defined(__clang__)
#pragma STDC FP_CONTRACT OFF
#elif defined(__GNUC__)
#pragma GCC optimize("fp-contract=off")
#endif
#endif
