#!/usr/bin/env bash
# glTF files against their peers (make bench-gltf), 800x800, 1 sample, 2
# threads:
#   1. Debian's 2CylinderEngine.glb (121,496 triangles: 34 meshes placed by
#      115 nodes) as firsthit shows it on its own: load, prepare and frame;
#   2. the same engine placed where the mesh benchmarks put the bunny (a
#      YAML scene holding it as `type: gltf`: the bunny's camera, floor,
#      Lambert + ambient + a directional light with shadows), in float,
#      against the Embree 3 peer tracing the very same triangles (`firsthit
#      export` of that scene; bench/embree_reference.cpp --world), and the
#      peer again with the scene's own 115 instances of its 34 meshes as
#      Embree instances (--scene: the two levels firsthit traces);
#   3. frames per second of the engine and of the glTF demo movie
#      (animations/gltf/demo.gltf) beside Blender 3.4's command line
#      rendering the same files (Cycles, 1 sample, 2 threads; scripts/
#      blender_render.py), when `blender` is installed.
#   scripts/bench_gltf.sh [OUT_DIR] [--runs K] [--blender-frames N]
# Writes OUT_DIR/gltf.txt (default output/) as key: value lines. FIRSTHIT
# and EMBREE_REFERENCE name the programs (defaults: build/firsthit,
# build/bench/firsthit_embree_reference; without the latter, or without
# Blender, their lines are left out).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
firsthit=${FIRSTHIT:-$here/../build/firsthit}
embree=${EMBREE_REFERENCE:-$here/../build/bench/firsthit_embree_reference}
engine=/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb
demo=$here/../animations/gltf/demo.gltf
out=$here/../output runs=9 blender_frames=10
while [[ $# -gt 0 ]]; do
  case $1 in
    --runs) runs=$2; shift 2 ;;
    --blender-frames) blender_frames=$2; shift 2 ;;
    *) out=$1; shift ;;
  esac
done
[[ -f $engine ]] || { echo "bench_gltf: $engine is missing (apt-get install assimp-testmodels)" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# key: value lines of `firsthit bench`, the chosen keys prefixed.
pick() { local prefix=$1; shift; "$firsthit" bench "$@" --threads 2 --runs "$runs" |
  awk -F': ' -v p="$prefix" '$1 ~ /^(load_ms|prepare_ms|ms_per_frame|instances)$/ {print p $1 ": " $2}'; }
{
  pick engine_ "$engine" --resolution 800x800
  pick engine_float_ "$engine" --resolution 800x800 --precision float

  # The engine (bounding sphere radius 396.12 about (0, 6.0, -44.46) once
  # turned z-up) scaled to radius 8, to fill half the frame, and stood on
  # the bunny's floor.
  sed -e '/^surfaces:/,/^lights:/{/^surfaces:/!{/^lights:/!d}}' "$here/../animations/bunny.yaml" |
    sed "s#^surfaces:#surfaces:\n  - {type: gltf, file: $engine, transform: {scale: 0.020196, translate: [0, -0.12118, 1.44710]}}\n  - {type: plane, normal: [0, 0, 1], distance: -2.2078, material: floor}#" \
    > "$work/engine_on_floor.yaml"
  pick placed_float_ "$work/engine_on_floor.yaml" --precision float
  if [[ -x $embree ]]; then
    "$firsthit" export "$work/engine_on_floor.yaml" --quiet -o "$work/engine_on_floor.ply"
    "$embree" --threads 2 --runs "$runs" --max-level 0 --world --bunny "$work/engine_on_floor.ply" 2>/dev/null |
      awk -F, 'NR == 2 {print "placed_embree_build_ms: " $3; print "placed_embree_ms_per_frame: " $4}'
    "$embree" --threads 2 --runs "$runs" --scene "$work/engine_on_floor.yaml" 2>/dev/null |
      awk -F, 'NR == 2 {print "placed_embree_instances_ms_per_frame: " $4}'
  fi

  for f in "$engine" "$demo"; do
    name=$(basename "$f" | sed 's/\..*//')
    fps=$("$firsthit" frames "$f" --out "$work/frames" --resolution 800x800 --quiet --stats --threads 2 |
      sed -n 's/^frames_per_second: //p')
    echo "${name}_firsthit_frames_per_second: $fps"
    rm -rf "$work/frames"
    if command -v blender >/dev/null; then
      blender -b --factory-startup -P "$here/blender_render.py" -- "$f" "$work/blender" "$blender_frames" 800 2>/dev/null |
        sed -n "s/^blender_frames_per_second: /${name}_blender_frames_per_second: /p"
      rm -rf "$work/blender"
    fi
  done
} | tee "$out/gltf.txt.tmp"
mv "$out/gltf.txt.tmp" "$out/gltf.txt"
