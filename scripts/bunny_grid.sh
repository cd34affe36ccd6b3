#!/usr/bin/env bash
# The scene of the instancing benchmark (make bench-instances): N copies of
# the Stanford bunny (animations/meshes/bunny00.off, bash
# scripts/fetch_meshes.sh) stood up and resting on the ground z = -3, on a
# grid that recedes from the camera at (0, -12, 6) looking along (0, 12, -6),
# each copy turned about z by a golden-angle step; Lambert + ambient + one
# directional light with shadows, 800x800.
#   scripts/bunny_grid.sh N OUT_DIR     writes OUT_DIR/grid_N.csv and OUT_DIR/grid_N.yaml
# Each CSV row is one rotation -- standing up (90 degrees about x), then the
# turn about z, composed into one axis and angle -- a scale (the bunny's of
# animations/bunny.yaml) and a move. bench/embree_reference.cpp reads the
# same CSV, so both renderers place the same bunnies.
set -euo pipefail
n=$1
out=$2
here=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$out"
awk -v n="$n" 'BEGIN {
  pi = atan2(0, -1); cols = int(sqrt(n)); if (cols * cols < n) cols++
  spacing = 8; scale = 4.4743; tz = -3 + 2.2078   # the bunny stood up reaches 2.2078 below its origin
  print "tx,ty,tz,scale,axis_x,axis_y,axis_z,degrees"
  for (k = 0; k < n; k++) {
    r = int(k / cols); c = k % cols
    theta = (k * 137.50776405) % 360 * pi / 180
    # q = q_z(theta) q_x(90 degrees): w = ac, v = (ad, bd, cb) with a = cos(theta/2),
    # b = sin(theta/2), c = d = cos(45 degrees)
    a = cos(theta / 2); b = sin(theta / 2); h = sqrt(0.5)
    w = a * h; x = a * h; y = b * h; z = b * h
    len = sqrt(x * x + y * y + z * z)
    printf "%.6f,%.6f,%.6f,%.4f,%.9f,%.9f,%.9f,%.9f\n", (c - (cols - 1) / 2) * spacing, r * spacing, tz, scale,
           x / len, y / len, z / len, 2 * atan2(len, w) * 180 / pi
  }
}' > "$out/grid_$n.csv"
cat > "$out/grid_$n.yaml" <<YAML
# $n bunnies on a grid (scripts/bunny_grid.sh): the instancing benchmark's scene.
materials:
  grey:  {color: [200, 200, 200], ambient: 0.1, diffuse: 0.9, specular: 0, phong_exponent: 1}
  floor: {color: [140, 170, 200], ambient: 0.1, diffuse: 0.9, specular: 0, phong_exponent: 1}
meshes:
  bunny: {file: $here/animations/meshes/bunny00.off}
surfaces:
  - {type: instances, mesh: bunny, material: grey, placements: grid_$n.csv}
  - {type: plane, normal: [0, 0, 1], distance: -3, material: floor}
lights:
  ambient: {type: ambient, color: [255, 255, 255], intensity: 0.006}
  sun:     {type: directional, color: [255, 255, 255], intensity: 0.004, direction: [-1, 1, -2]}
cameras:
  front: {type: perspective, width: 800, height: 800, view_point: [0, -12, 6], look_at: [0, 12, -6],
          up: [0, 0, 1], projection_distance: 10}
effects: [ambient, diffuse, shadows]
YAML
