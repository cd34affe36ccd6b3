#!/usr/bin/env bash
# What textures and cutouts cost (make bench-textures): the glTF demo
# (animations/gltf/demo.gltf: a floor of textured tiles bevelled by a
# normal texture, a trellis cut out by alphaMode MASK) against the same
# file without them, 800x450, 2 threads, double and float, at frame 110
# (the cart under the trellis):
#   textured    the demo as it is;
#   no_mipmaps  every texture read from its image alone, however far
#               away (minFilter = its magFilter), as before mipmaps;
#   no_bevels   its floor without the normal texture;
#   no_cutout   its trellis OPAQUE (its texture still drawn, no holes);
#   untextured  no textures at all (the trellis a solid square, the floor
#               one flat grey), the same triangles, lights and effects.
# The variants are timed in turns, ROUNDS rounds of `firsthit bench --runs
# 3`, and each keeps its fastest round: the machine's noise falls on all.
#   scripts/bench_textures.sh [OUT_DIR] [--rounds N]
# Writes OUT_DIR/textures.txt (default output/) as key: value lines.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
firsthit=${FIRSTHIT:-$here/../build/firsthit}
demo=$here/../animations/gltf/demo.gltf
out=$here/../output rounds=5
while [[ $# -gt 0 ]]; do
  case $1 in
    --rounds) rounds=$2; shift 2 ;;
    *) out=$1; shift ;;
  esac
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp "$demo" "$work/textured.gltf"
python3 - "$demo" "$work" <<'PY'
import json, sys
demo, work = sys.argv[1], sys.argv[2]
g = json.load(open(demo))
flat = json.loads(json.dumps(g))
for m in flat["materials"]:
    m.pop("normalTexture", None)
json.dump(flat, open(work + "/no_bevels.gltf", "w"))
sharp = json.loads(json.dumps(g))
sharp.setdefault("samplers", [])
for t in sharp["textures"]:
    if "sampler" not in t:
        sharp["samplers"].append({})
        t["sampler"] = len(sharp["samplers"]) - 1
for s in sharp["samplers"]:
    s["minFilter"] = s.get("magFilter", 9729)
json.dump(sharp, open(work + "/no_mipmaps.gltf", "w"))
for m in g["materials"]:
    if m.get("alphaMode") == "MASK":
        m["alphaMode"] = "OPAQUE"
json.dump(g, open(work + "/no_cutout.gltf", "w"))
for m in g["materials"]:
    m["pbrMetallicRoughness"].pop("baseColorTexture", None)
    m.pop("normalTexture", None)
json.dump(g, open(work + "/untextured.gltf", "w"))
PY
variants="textured no_mipmaps no_bevels no_cutout untextured"
for precision in double float; do
  for v in $variants; do echo 1e9 > "$work/$v.$precision"; done
  for ((r = 0; r < rounds; r++)); do
    for v in $variants; do
      ms=$("$firsthit" bench "$work/$v.gltf" --frame 110 --threads 2 --runs 3 --precision $precision |
        sed -n 's/^ms_min: //p')
      awk -v a="$ms" -v b="$(cat "$work/$v.$precision")" 'BEGIN {print (a < b ? a : b)}' > "$work/$v.$precision"
    done
  done
done
mkdir -p "$out"
{
  echo "file: animations/gltf/demo.gltf"
  echo "frame: 110"
  for precision in double float; do
    for v in $variants; do echo "${precision}_${v}_ms: $(cat "$work/$v.$precision")"; done
    awk -v t="$(cat "$work/textured.$precision")" -v u="$(cat "$work/untextured.$precision")" \
      -v p="$precision" 'BEGIN {printf "%s_textured_over_untextured: %.3f\n", p, t / u}'
  done
} | tee "$out/textures.txt"
