#!/usr/bin/env bash
# Regenerates every figure of docs/gallery.md. Run from anywhere:
#   docs/figures/make_figures.sh [path/to/stitch]
# (default: build/bin/stitch). Headless: needs Mesa's EGL (llvmpipe), no display.
# Each command is printed before it runs; docs/gallery.md quotes the same commands.
set -euo pipefail
cd "$(dirname "$0")/../.."
STITCH=${1:-build/bin/stitch}
if [[ ! -x $STITCH ]]; then
  echo "make_figures.sh: $STITCH is not an executable (build it, or pass its path)" >&2
  exit 2
fi
failed=()
run() {
  echo "+ stitch $*"
  if ! "$STITCH" "$@" > /dev/null; then
    failed+=("stitch $*")
  fi
}
F=docs/figures
T=examples/tetrahedron.obj
C=examples/cube.obj
H=examples/cube_hole.obj
W=examples/two_cubes.obj

# 1. The five steps on a tetrahedron.
run render $T -o $F/tet_1_mesh.png --size 400x400 --draw input --show mesh,ev
run render $T -o $F/tet_2_kgons.png --size 400x400 --draw none --show mesh,kgons
run render $T -o $F/tet_3_nets.png --size 400x400 --draw none --show mesh,nets
run render $T -o $F/tet_4_surface.png --size 400x400 --mode patches --show mesh
run render $T -o $F/tet_5_polygon_mesh.png --size 400x400 --show tess --resolution 6

# 2. The cube with an inserted edge (one 10-sided face, genus 1), before and after smoothing.
run render $H -o $F/cube_hole_mesh.png --size 480x480 --view top --draw input --show mesh,ev
run render $H -o $F/cube_hole_smooth.png --size 480x480 --view top --show mesh,ev
run render $H -o $F/cube_hole_smooth_iso.png --size 480x480 --eye -3,-4,5 --show ev

# 3. AS&C against ours: zebra close-ups of a 3-valent point and of the 10-valent point.
run render $C -o $F/valence3_asc.png --size 480x480 --method asc --mode zebra --focus-ev --stripes 32 --resolution 24
run render $C -o $F/valence3_mdc.png --size 480x480 --method mdc --mode zebra --focus-ev --stripes 32 --resolution 24
run render $H -o $F/valence10_asc.png --size 480x480 --method asc --mode zebra --focus-ev --stripes 32 --resolution 24
run render $H -o $F/valence10_mdc.png --size 480x480 --method mdc --mode zebra --focus-ev --stripes 32 --resolution 24

# 4. Catmull-Clark against ours on the cube with a hole and on two cubes joined by an edge.
run render $H -o $F/cube_hole_cc.png --size 480x480 --view top --method cc --mode zebra --resolution 16
run render $H -o $F/cube_hole_mdc.png --size 480x480 --view top --method mdc --mode zebra --resolution 16
run render $W -o $F/two_cubes_cc.png --size 640x400 --view top --method cc --mode zebra --resolution 16
run render $W -o $F/two_cubes_mdc.png --size 640x400 --view top --method mdc --mode zebra --resolution 16
#    A hole made by connect-faces instead: both faces dented, then joined by a tube (all quads).
run edit $C --op "extrude-face 1 -0.4 0.5" --op "extrude-face 2 -0.4 0.5" --op "connect-faces 1 2" -o $F/cube_tunnel.obj
run render $F/cube_tunnel.obj -o $F/cube_tunnel_cc.png --size 480x480 --eye 2.5,-3.5,4 --method cc --mode zebra --resolution 16
run render $F/cube_tunnel.obj -o $F/cube_tunnel_mdc.png --size 480x480 --eye 2.5,-3.5,4 --method mdc --mode zebra --resolution 16

# 5. Star-shaped against regularised K-gons: the K-gons of the star prism's non-convex
#    10-sided faces (docs/figures/star_prism.obj), and the surfaces they give.
P=docs/figures/star_prism.obj
run render $P -o $F/kgon_star.png --size 400x400 --view top --show mesh,kgons
run render $P -o $F/kgon_regularized.png --size 400x400 --view top --show mesh,kgons --regularize
run render $P -o $F/kgon_star_surface.png --size 400x400 --eye 1.2,-2.4,3.2 --mode isophote
run render $P -o $F/kgon_regularized_surface.png --size 400x400 --eye 1.2,-2.4,3.2 --mode isophote --regularize

# 6. Bulkier against smoother: the size of the extraordinary K-gons (the cube's 3-gons).
run render $C -o $F/kgon_scale_1.5.png --size 400x400 --mode isophote --show kgons --kgon-scale 1.5
run render $C -o $F/kgon_scale_1.0.png --size 400x400 --mode isophote --show kgons
run render $C -o $F/kgon_scale_0.5.png --size 400x400 --mode isophote --show kgons --kgon-scale 0.5

# 7. All K-gons rotated (every K-gon with K != 4, in its plane).
run render $C -o $F/kgon_rotate_0.png --size 400x400 --mode isophote --show kgons
run render $C -o $F/kgon_rotate_45.png --size 400x400 --mode isophote --show kgons --kgon-rotate 45

# 8. stitch compare on the cube (zebra of asc, mdc, cc; jump plot; index.html).
run compare $C -o $F/compare_cube --size 320x320

# 10. Boundaries, creases and corners: OpenSubdiv's pawn and car (open, with sharpness 6
#     creases) by stitch and by Catmull-Clark, a cube with a creased edge loop, an open box.
S=tests/data/opensubdiv-shapes
for m in mdc cc; do
  run render $S/catmark_pawn.obj -o $F/pawn_$m.png --size 300x400 --eye 1.75,-2.5,0.75 --target 1.75,-1.27,0.27 --method $m
  run render $S/catmark_car.obj -o $F/car_$m.png --size 300x500 --eye 6.5,-0.9,4.0 --target 0.62,-1.88,0.3 --method $m
done
run render examples/cube_creased.obj -o $F/cube_creased.png --size 400x400 --eye 3,-4,4 --show mesh
run render examples/cube_creased.obj -o $F/cube_creased_zebra.png --size 400x400 --eye 3,-4,4 --mode zebra --resolution 16
run render examples/open_box.obj -o $F/open_box.png --size 400x400 --eye 3,-4,5 --show mesh

# 11. Texture coordinates: the cube with a cross-shaped UV unwrap (examples/cube_uv.obj) as a
#     checker of 16 x 16 squares over the unit square, through the smooth UVs, through bilinear
#     UVs per patch, and on the input polygons.
U=examples/cube_uv.obj
run render $U -o $F/cube_uv_checker.png --size 400x400 --mode checker --checks 16
run render $U -o $F/cube_uv_checker_linear.png --size 400x400 --mode checker --checks 16 --uv linear
run render $U -o $F/cube_uv_input.png --size 400x400 --mode checker --checks 16 --draw input --show mesh

# 12. Twisted and bent tunnels: one edge from vertex 1 of the bottom face to each corner of the
#     top face (straight, a quarter turn either way, a half turn), seen from below; and a tunnel
#     from the bottom face to the front face, by one inserted edge and by connect-faces with
#     three segments.
for t in "straight 5" "quarter 6" "quarter_back 8" "half 7"; do
  set -- $t
  run edit $C --op "insert-edge 1@1 $2@2" -o $F/twist_$1.obj
  run render $F/twist_$1.obj -o $F/twist_$1.png --size 300x300 --eye 1,-1.5,-5 --resolution 16
done
run edit $C --op "insert-edge 3@1 5@3" -o $F/bent_insert_edge.obj
run edit $C --op "connect-faces 1 3 auto 3" -o $F/bent_handle.obj
run render $F/bent_insert_edge.obj -o $F/bent_insert_edge.png --size 400x400 --eye 2.5,-4,-3 --resolution 16
run render $F/bent_handle.obj -o $F/bent_handle.png --size 400x400 --eye 2.5,-4,-3 --resolution 16 --show mesh
# A bent tunnel by one inserted edge between two faces of the icosahedron that share no vertex
# (the bent-tube placement), seen into each opening.
run primitive icosahedron -o $F/icosahedron.obj
run edit $F/icosahedron.obj --op "insert-edge 12@1 7@9" -o $F/bent_icosahedron.obj
run render $F/bent_icosahedron.obj -o $F/bent_icosahedron_1.png --size 400x400 --eye -5,5,5 --target 0,0,0 --resolution 16 --show mesh
run render $F/bent_icosahedron.obj -o $F/bent_icosahedron_9.png --size 400x400 --eye -2,1.5,-6 --target 0,0,0 --resolution 16 --show mesh

if ((${#failed[@]})); then
  echo "make_figures.sh: these commands failed:" >&2
  printf '  %s\n' "${failed[@]}" >&2
  exit 1
fi
