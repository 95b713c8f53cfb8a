#!/bin/sh
# SPDX-License-Identifier: MIT
# Host half of `make demo`: runs the subd tool on the demo meshes, one picture per result.
# usage: demo/host_demo.sh BIN_DIR OUT_DIR
bin=$1 out=$2
set -e
mkdir -p "$out"
# run NAME SUBD_ARGS...: writes $out/NAME.png. A scheme command's picture shows its INPUT
# (the first .obj/.off argument) over the result: --with-input INPUT, in orange, with both
# named in the caption. `render` pictures show one mesh. To add a picture, add a run line.
run() {
    name=$1; shift
    overlay=
    if [ "$1" != render ]; then
        for a in "$@"; do
            case $a in *.obj | *.off) overlay=$a; break ;; esac
        done
    fi
    "$bin/subd" "$@" ${overlay:+--with-input "$overlay"} -o "$out/$name.png"
    echo "wrote $out/$name.png  (subd $*${overlay:+ --with-input $overlay})"
}
top="--pitch 0 --yaw 0 --size 400x400"

echo "-- input meshes"
run torus_tri render test/data/torus_tri.obj
run spot_control_mesh render test/data/spot_control_mesh.obj

echo "-- Loop subdivision, limit positions, progressive interpolation"
run loop_icosahedron_l3 loop -l 3 test/data/icosahedron.obj
run loop_hexfan_l3_paper loop -l 3 --boundary paper test/data/hexfan.obj $top
run loop_cube_creases_l3 loop -l 3 --crease-angle 60 demo/cube_tri.obj
run limit_icosahedron limit test/data/icosahedron.obj
run pia_icosahedron_l3 pia --tol 1e-5 test/data/icosahedron.obj

echo "-- quasi 4-8 subdivision (the paper's figures)"
for n in 3 4 5 6 9 12; do
    run quasi48_fan${n}_4steps quasi48 -l 4 --no-smooth demo/fan$n.obj $top
done
run quasi48_warped_hexagon_1step quasi48 -l 1 --no-smooth demo/warped_hexagon.obj $top
run quasi48_torus_4steps quasi48 -l 4 demo/torus_12x6.obj
run quasi48_spot_2steps quasi48 -l 2 demo/spot_triangulated.obj

echo "-- semi-stationary alpha-subdivision"
run alpha_circle_from_square alpha --kernel cos --alpha 1/4 -l 5 demo/square.obj $top
run alpha_bspline_square alpha --kernel bspline -l 5 demo/square.obj $top
"$bin/subd" alpha --kernel cos --alpha 1/4 -l 5 demo/square.obj -o "$out/alpha_circle.xyz"
echo "wrote $out/alpha_circle.xyz  (points for a CNC controller)"
run alpha_ellipse alpha --kernel cos --alpha 1/4 -l 5 demo/ellipse_control.obj $top
run alpha_doo_sabin_spot alpha -l 2 test/data/spot_control_mesh.obj
run alpha_s3_cube alpha --order 3 -l 3 test/data/cube_quad.obj

echo "-- semi-regular 4-8 refinement and variable resolution (the paper's figures 17-20)"
run semireg48_hexfan_preprocessed sr48 -l 0 --no-smooth test/data/hexfan.obj $top
run semireg48_hexfan_4steps_refine sr48 -l 4 --no-smooth test/data/hexfan.obj $top
run semireg48_hexfan_4steps_smooth sr48 -l 4 test/data/hexfan.obj $top
run semireg48_pentagon_prism_4steps sr48 -l 4 demo/pentagon_prism.obj
run semireg48_spot_2steps sr48 -l 2 demo/spot_triangulated.obj
run adapt_torus_point sr48 -l 6 --point 1.4,0,0 demo/torus_12x6.obj --pitch 60
run adapt_torus_ramp sr48 -l 6 --ramp x demo/torus_12x6.obj --pitch 60
run adapt_torus_plane sr48 -l 6 --plane 0,0,0,1,0,0 demo/torus_12x6.obj --pitch 60
run adapt_spot_chord sr48 -l 6 --chord 0.002 demo/spot_triangulated.obj --edges --size 1200x700

echo "-- alpha tags (semi-stationary paper, section 3, figure 4(d))"
# one cube corner (vertex 1, at (-1,-1,-1)) tagged alpha = 9 rad, the rest 0;
# cos kernel, S_3: the tagged corner is pulled in; the untagged run beside it for comparison
run alpha_tags_fig4d alpha --order 3 --kernel cos -l 4 --tags demo/fig4d_alpha.tags test/data/cube_quad.obj --yaw 45 --pitch 0
run alpha_tags_fig4d_untagged alpha --order 3 --kernel cos -l 4 test/data/cube_quad.obj --yaw 45 --pitch 0

echo "-- semi-regular 4-8 streams: the firmware demo's checksums = the host tool's"
# port/cortex-m/demo_sr48.c streams test/data/icosahedron.obj (chordal, eps 0.01, 9 binary
# steps; uniform, 6 and 8 steps) under QEMU; `make demo` keeps each image's output in OUT_DIR/*.log.
# The tool's --stats checksum is the same FNV-1a over the same triangles' position bits.
sr48_device_sum() { # LOG SECTION_START: the first checksum after the section's title line
    awk -v s="$2" 'index($0, s) == 1 { f = 1 } f && $1 == "checksum" { print $2; exit }' "$1" | sed 's/^0x//'
}
sr48_host_sum() { "$@" --stats | sed -n 's/.*"checksum":"\([0-9a-f]*\)".*/\1/p'; }
for v in "m4f-float subd" "m3-fixed subd-fixed"; do
    set -- $v
    log=$out/$1.log
    [ -f "$log" ] || { echo "no $log (run make demo): not compared"; continue; }
    hc=$(sr48_host_sum "$bin/$2" sr48 --stream --chord 0.01 -l 9 test/data/icosahedron.obj)
    hu=$(sr48_host_sum "$bin/$2" sr48 --stream -l 6 test/data/icosahedron.obj)
    h8=$(sr48_host_sum "$bin/$2" sr48 --stream -l 8 test/data/icosahedron.obj)
    dc=$(sr48_device_sum "$log" "chordal stream, eps 0.01") du=$(sr48_device_sum "$log" "uniform stream, 6 binary")
    d8=$(sr48_device_sum "$log" "uniform stream, 8 binary")
    echo "$1: chordal checksum device $dc, host $hc; uniform device $du, host $hu; 8 steps device $d8, host $h8"
    if [ -z "$hc" ] || [ "$hc" != "$dc" ] || [ -z "$hu" ] || [ "$hu" != "$du" ] || [ -z "$h8" ] || [ "$h8" != "$d8" ]; then
        echo "FAILED: the device's 4-8 stream checksums differ from $2's" >&2
        exit 1
    fi
done
echo "-- the pipeline (issue 22): points -> progressive interpolation -> adaptive limit stream to a chord tolerance"
# The host half of port/cortex-m/demo_pipe.c, the same file and numbers (tol 2^-12, max level 3,
# eps 2^-7): the fitted control mesh, the adaptive stream's checksum (`make demo` compares it with
# the Cortex-M4F's), the adaptive mesh drawn with its edges, and the uniform level that meets the
# same tolerance, found by brute force in double (adapt_measure, built by `make demo`).
"$bin/subd" pia --method paper --tol 0.000244140625 demo/spot_control_tri.obj -o "$out/pipe_fit.obj"
"$bin/subd" loop -l 3 --stream --limit --chord 0.0078125 "$out/pipe_fit.obj" --stats > "$out/pipe_stream_stats.json"
sed -n 's/.*"triangles":\([0-9]*\),"checksum":"\([0-9a-f]*\)".*/  host: adaptive triangles \1, checksum 0x\2/p' "$out/pipe_stream_stats.json"
"$bin/subd" loop -l 3 --stream --limit --chord 0.0078125 "$out/pipe_fit.obj" -o "$out/pipe_adaptive.obj"
run pipe_spot_adaptive render "$out/pipe_adaptive.obj" --edges --size 1000x700
"$bin/adapt_measure" "$out/pipe_fit.obj" 3 0.0078125 | sed 's/^/  /'
