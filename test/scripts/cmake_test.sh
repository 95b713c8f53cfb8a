#!/bin/sh
# SPDX-License-Identifier: MIT
# The CMake integration (CMakeLists.txt, cmake/, examples/), as a consumer would use it:
#   per arithmetic (TINYSUBD_FIXED OFF / ON), host compiler:
#     - examples/ via add_subdirectory of this source tree (no build type: -O0): builds, runs,
#       prints the expected triangle counts; compile_commands.json shows the library's own
#       sources with -std=c99 -ffp-contract=off and the Makefile's warnings (-Werror), and the
#       consumer with SUBD_FIXED from the target but none of the library's PRIVATE flags;
#     - the library configured on its own (Release: -O3), cmake --install to a fresh prefix:
#       headers, library and package files installed, package version = include/subd.h's;
#     - examples/ via find_package(tinysubd CONFIG) of that prefix: builds against the
#       installed headers, runs, and prints the same positions hash as the -O0 build;
#   Cortex-M4F (cmake/arm-none-eabi.cmake, Release), when arm-none-eabi-gcc exists:
#     - the library cross-builds, every source with the toolchain file's flags and
#       -std=c99 -ffp-contract=off; it is ARM code with hardware float instructions and no
#       vfma/vfms/vfnma/vfnms (checked to be detectable: the same compiler with
#       -ffp-contract=fast puts them into src/loop.c).
# Build trees persist in BUILD_DIR/cmake (incremental); install prefixes are made afresh.
# usage: cmake_test.sh BUILD_DIR   (prints "N passed, M failed" like the other suites)
B=${1:-build}
ROOT=$(pwd)
case $B in /*) W=$B/cmake ;; *) W=$ROOT/$B/cmake ;; esac
mkdir -p "$W"
p=0 f=0
ok() { echo "ok   $1"; p=$((p + 1)); }
bad() { echo "FAIL $1"; f=$((f + 1)); }
# run LABEL LOGNAME COMMAND...: the command's output goes to W/LOGNAME (shown on failure)
run() {
    label=$1 out=$W/$2
    shift 2
    if "$@" > "$out" 2>&1; then ok "$label"; return 0; fi
    bad "$label: $*"; tail -n 30 "$out"; return 1
}
if ! command -v cmake >/dev/null 2>&1; then
    bad "cmake not found (make deps installs it)"; echo "$p passed, $f failed"; exit 1
fi
if command -v ninja >/dev/null 2>&1; then G=Ninja; else G="Unix Makefiles"; fi
echo "cmake: $(cmake --version | head -n 1), generator $G"

ver=$(sed -nE 's/^#define SUBD_VERSION_(MAJOR|MINOR|PATCH) +([0-9]+).*/\2/p' include/subd.h | paste -sd. -)
nsrc=$(ls src/*.c | wc -l)
expect_run() { # LABEL BINARY ARITH -> checks the example's line, sets $hash
    line=$("$2" 2>&1); rc=$?
    echo "   $line"
    case $line in
    *"tinysubd $ver $3: 8 control triangles, level 3: subd_loop 512 triangles, subd_loop_stream 512 triangles, same bits"*)
        [ $rc -eq 0 ] && { ok "$1"; hash=${line##* }; return 0; } ;;
    esac
    bad "$1 (exit $rc)"; hash=; return 1
}
# the compile command of one source file (compile_commands.json: one "command" line per file)
cmd_of() { grep '"command"' "$1/compile_commands.json" | grep -- "-c [^ ]*$2\""; }

for v in float fixed; do
    if [ $v = fixed ]; then fx=ON n=1 arith=q16.16; else fx=OFF n=0 arith=float32; fi

    # 1. add_subdirectory of the source tree
    S=$W/sub-$v
    if run "add_subdirectory ($v): configure" sub-$v.cfg.log cmake -G "$G" -S examples -B "$S" \
            -DTINYSUBD_SOURCE_DIR="$ROOT" -DTINYSUBD_FIXED=$fx -DCMAKE_EXPORT_COMPILE_COMMANDS=ON &&
       run "add_subdirectory ($v): build" sub-$v.build.log cmake --build "$S" -j2 &&
       expect_run "add_subdirectory ($v): example runs" "$S/tinysubd_example" $arith; then
        hash_sub=$hash
        libcmds=$(grep '"command"' "$S/compile_commands.json" | grep -c -- "-c [^ ]*/src/[^ /]*\.c\"")
        good=$(grep '"command"' "$S/compile_commands.json" | grep -- "-c [^ ]*/src/[^ /]*\.c\"" |
               grep -- "-DSUBD_FIXED=$n " | grep -- "-std=c99" | grep -- "-ffp-contract=off" |
               grep -- "-Wconversion" | grep -- "-Wsign-conversion" | grep -- "-Wshadow" | grep -c -- "-Werror")
        if [ "$libcmds" -eq "$nsrc" ] && [ "$good" -eq "$nsrc" ]; then
            ok "add_subdirectory ($v): all $nsrc src/*.c built with -std=c99 -ffp-contract=off, warnings, -Werror"
        else
            bad "add_subdirectory ($v): $libcmds of $nsrc src/*.c compiled, $good with the required flags"
        fi
        c=$(cmd_of "$S" examples/main.c)
        case $c in
        *-DSUBD_FIXED=$n\ *-ffp-contract* | *-DSUBD_FIXED=$n\ *-Wconversion*) bad "consumer gets the library's PRIVATE flags: $c" ;;
        *-DSUBD_FIXED=$n\ *) ok "add_subdirectory ($v): consumer gets SUBD_FIXED=$n, not the PRIVATE flags" ;;
        *) bad "add_subdirectory ($v): consumer compile line lacks -DSUBD_FIXED=$n: $c" ;;
        esac
    else
        hash_sub=
    fi

    # 2. the library on its own, installed to a fresh prefix
    L=$W/lib-$v P=$W/prefix-$v
    rm -rf "$P"
    if run "install ($v): configure" lib-$v.cfg.log cmake -G "$G" -S . -B "$L" -DCMAKE_BUILD_TYPE=Release \
            -DTINYSUBD_FIXED=$fx -DCMAKE_INSTALL_PREFIX="$P" &&
       run "install ($v): build" lib-$v.build.log cmake --build "$L" -j2 &&
       run "install ($v): cmake --install" lib-$v.install.log cmake --install "$L"; then
        cfg=$(dirname "$(find "$P" -name tinysubdConfig.cmake | head -n 1)")
        miss=
        for x in include/subd.h include/subd_real.h include/subd_config.h include/subd_loop.h; do
            [ -f "$P/$x" ] || miss="$miss $x"
        done
        for x in tinysubdConfig.cmake tinysubdConfigVersion.cmake tinysubdTargets.cmake; do
            [ -f "$cfg/$x" ] || miss="$miss cmake/$x"
        done
        [ -n "$(find "$P" -name libtinysubd.a)" ] || miss="$miss libtinysubd.a"
        if [ -z "$miss" ] && grep -q "PACKAGE_VERSION \"$ver\"" "$cfg/tinysubdConfigVersion.cmake"; then
            ok "install ($v): headers, libtinysubd.a, package $ver (= include/subd.h) in the prefix"
        else
            bad "install ($v): missing:$miss or package version is not $ver"
        fi

        # 3. find_package of the installed package
        E=$W/pkg-$v
        rm -rf "$E"
        if run "find_package ($v): configure" pkg-$v.cfg.log cmake -G "$G" -S examples -B "$E" \
                -DCMAKE_PREFIX_PATH="$P" -DCMAKE_EXPORT_COMPILE_COMMANDS=ON &&
           run "find_package ($v): build" pkg-$v.build.log cmake --build "$E" -j2 &&
           expect_run "find_package ($v): example runs" "$E/tinysubd_example" $arith; then
            c=$(cmd_of "$E" examples/main.c)
            case $c in
            *"$ROOT/include"*) bad "find_package ($v): consumer compiled against the source tree: $c" ;;
            *-DSUBD_FIXED=$n\ *"$P/include"*) ok "find_package ($v): consumer uses the installed headers, SUBD_FIXED=$n" ;;
            *) bad "find_package ($v): consumer compile line: $c" ;;
            esac
            if [ -n "$hash_sub" ] && [ "$hash" = "$hash_sub" ]; then
                ok "find_package ($v): positions hash $hash = the add_subdirectory (-O0) build's"
            else
                bad "find_package ($v): positions hash $hash != add_subdirectory's $hash_sub"
            fi
        fi
    fi
done

# 4. Cortex-M4F cross build of the library
if command -v arm-none-eabi-gcc >/dev/null 2>&1; then
    X=$W/m4f-float
    if run "Cortex-M4F: configure with cmake/arm-none-eabi.cmake" m4f.cfg.log cmake -G "$G" -S . -B "$X" \
            -DCMAKE_TOOLCHAIN_FILE="$ROOT/cmake/arm-none-eabi.cmake" -DCMAKE_BUILD_TYPE=Release \
            -DCMAKE_EXPORT_COMPILE_COMMANDS=ON &&
       run "Cortex-M4F: build libtinysubd.a" m4f.build.log cmake --build "$X" -j2; then
        # gcc's -std=c99 alone already means -ffp-contract=off, so check the flag itself too
        good=$(grep '"command"' "$X/compile_commands.json" | grep -- "-c [^ ]*/src/[^ /]*\.c\"" |
               grep -- "-mcpu=cortex-m4" | grep -- "-mfloat-abi=hard" | grep -- "-std=c99" |
               grep -c -- "-ffp-contract=off")
        if [ "$good" -eq "$nsrc" ]; then
            ok "Cortex-M4F: all $nsrc src/*.c built with -mcpu=cortex-m4 -mfloat-abi=hard -std=c99 -ffp-contract=off"
        else
            bad "Cortex-M4F: $good of $nsrc src/*.c built with the toolchain and bit-exactness flags"
        fi
        arm-none-eabi-objdump -d "$X/libtinysubd.a" > "$W/m4f.dis" 2>&1
        fpu=$(grep -cE '\sv(add|mul|sub)\.f32\s' "$W/m4f.dis")
        fma=$(grep -cE '\sv(fma|fms|fnma|fnms)\.' "$W/m4f.dis")
        if grep -q 'file format elf32-littlearm' "$W/m4f.dis" && [ "$fpu" -gt 0 ]; then
            ok "Cortex-M4F: ARM objects with hardware float ($fpu vadd/vsub/vmul.f32)"
        else
            bad "Cortex-M4F: not hard-float ARM code ($fpu float instructions)"
        fi
        # control: the same compiler fuses a plain a*b+c (src/ files are immune: fp_contract.h)
        printf 'float ctl(float a, float b, float c) { return a * b + c; }\n' > "$W/ctl.c"
        arm-none-eabi-gcc -mcpu=cortex-m4 -mthumb -mfpu=fpv4-sp-d16 -mfloat-abi=hard -O3 -std=gnu99 \
            -ffp-contract=fast -c "$W/ctl.c" -o "$W/m4f-contract.o" &&
            ctl=$(arm-none-eabi-objdump -d "$W/m4f-contract.o" | grep -cE '\sv(fma|fms|fnma|fnms)\.')
        if [ "$fma" -eq 0 ] && [ "${ctl:-0}" -gt 0 ]; then
            ok "Cortex-M4F: no vfma-family instruction in libtinysubd.a (the same compiler fuses a*b+c outside it)"
        else
            bad "Cortex-M4F: $fma vfma-family instructions in libtinysubd.a (control: ${ctl:-0})"
            grep -E '\sv(fma|fms|fnma|fnms)\.' "$W/m4f.dis" | head -n 5
        fi
    fi
else
    echo "skip Cortex-M cross build: arm-none-eabi-gcc not found"
fi

echo "$p passed, $f failed"
[ "$f" -eq 0 ]
