#!/usr/bin/env bash
# Writes the forest showcase (make forest): animations/forest.yaml, 10,000
# Stanford bunnies (one mesh, read once: bash scripts/fetch_meshes.sh) in ten
# bands of 1,000 receding from the camera, each band a group holding one
# `instances` set from animations/forest/band_K.csv; and
# animations/forest_movie.yaml, in which a wave runs through them: each band
# hops in turn while the camera glides in. The files are committed; run this
# only to change them (the rows come from a fixed formula, no randomness).
#   bash scripts/forest.sh
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$here/animations/forest"
bands=10 rows=10 cols=100 spacing=5.5
for ((b = 0; b < bands; b++)); do
  awk -v b="$b" -v rows="$rows" -v cols="$cols" -v s="$spacing" 'BEGIN {
    pi = atan2(0, -1)
    print "tx,ty,tz,scale,axis_x,axis_y,axis_z,degrees"
    for (r = 0; r < rows; r++) for (c = 0; c < cols; c++) {
      k = (b * rows + r) * cols + c
      # A fixed scatter: golden-ratio sequences for the jitter, size and turn.
      jx = (k * 0.6180339887) % 1 - 0.5; jy = (k * 0.7548776662) % 1 - 0.5
      size = 3.2 + 2.4 * ((k * 0.5698402910) % 1)
      theta = (k * 137.50776405) % 360 * pi / 180
      # Stand the y-up bunny up (90 degrees about x), then turn it about z:
      # one rotation, q = q_z(theta) q_x(90), as an axis and an angle.
      a = cos(theta / 2); bb = sin(theta / 2); h = sqrt(0.5)
      w = a * h; x = a * h; y = bb * h; z = bb * h
      len = sqrt(x * x + y * y + z * z)
      printf "%.4f,%.4f,%.4f,%.4f,%.7f,%.7f,%.7f,%.5f\n", (c - (cols - 1) / 2 + jx) * s, ((b * rows + r) + jy) * s + 6,
             -3 + 0.49344 * size, size, x / len, y / len, z / len, 2 * atan2(len, w) * 180 / pi
    }
  }' > "$here/animations/forest/band_$b.csv"
done

{
  echo "# The forest showcase's scene (make forest; written by scripts/forest.sh):"
  echo "# 10,000 Stanford bunnies, one mesh read once (bash scripts/fetch_meshes.sh),"
  echo "# in ten bands of 1,000 -- each a group that a movie can move -- on the"
  echo "# ground z = -3, lit by a low sun. See docs/format.md section 3.4."
  echo "materials:"
  for ((b = 0; b < bands; b++)); do
    echo "  fur$b: {color: [$((230 - 14 * b)), $((150 + 10 * b)), $((90 + 15 * b))], ambient: 0.15, diffuse: 0.9, specular: 0.3, phong_exponent: 30}"
  done
  echo "  ground: {color: [110, 150, 90], ambient: 0.15, diffuse: 0.9, specular: 0, phong_exponent: 1}"
  echo "meshes:"
  echo "  bunny: {file: meshes/bunny00.off}"
  echo "surfaces:"
  echo "  - {type: plane, name: ground, normal: [0, 0, 1], distance: -3, material: ground}"
  for ((b = 0; b < bands; b++)); do
    echo "  - {type: group, name: band$b, surfaces: [{type: instances, mesh: bunny, material: fur$b, placements: forest/band_$b.csv}]}"
  done
  echo "lights:"
  echo "  ambient: {type: ambient, color: [255, 255, 255], intensity: 0.006}"
  echo "  sun: {type: directional, color: [255, 240, 210], intensity: 0.004, direction: [-1, 2, -1.2]}"
  echo "cameras:"
  echo "  above: {type: perspective, width: 800, height: 450, view_point: [0, -10, 13], look_at: [0, 22, -10],"
  echo "          up: [0, 0, 1], projection_distance: 10}"
  echo "effects: [ambient, diffuse, specular, shadows]"
} > "$here/animations/forest.yaml"

{
  echo "# The forest showcase (make forest -> output/forest_movie.mp4; written by"
  echo "# scripts/forest.sh): a wave runs through 10,000 bunnies -- each band of"
  echo "# 1,000 hops in turn, front to back -- while the camera glides in. Each"
  echo "# frame moves only instances: their matrices and the top-level BVH are"
  echo "# redone, no triangle is touched (docs/format.md section 5.5)."
  echo "scene: forest.yaml"
  echo "camera: above"
  echo "fps: 30"
  echo "seconds: 5"
  echo "render: {precision: float}"
  echo "animate:"
  echo "  camera.view_point: {keyframes: [{time: 0, value: [0, -10, 13]}, {time: 5, value: [0, 12, 9]}], interpolation: ease_in_out}"
  for ((b = 0; b < bands; b++)); do
    t0=$(awk -v b="$b" 'BEGIN {printf "%.2f", 0.5 + 0.35 * b}')
    t1=$(awk -v b="$b" 'BEGIN {printf "%.2f", 0.5 + 0.35 * b + 0.4}')
    t2=$(awk -v b="$b" 'BEGIN {printf "%.2f", 0.5 + 0.35 * b + 0.8}')
    echo "  surfaces.band$b.transform.translate: {keyframes: [{time: $t0, value: [0, 0, 0]}, {time: $t1, value: [0, 0, 4]}, {time: $t2, value: [0, 0, 0]}], interpolation: catmull_rom}"
  done
} > "$here/animations/forest_movie.yaml"
echo "forest.sh: animations/forest.yaml, animations/forest_movie.yaml, animations/forest/band_0..$((bands - 1)).csv"
