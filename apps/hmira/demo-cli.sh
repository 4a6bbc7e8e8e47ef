#!/usr/bin/env bash
# End-to-end demo of the `hmira` tool: built-in solids (generate, info, convert, flip,
# truncate, bevel, extrude, voxelize, mc on the .raw it writes) and real meshes from Debian's
# libcgal-demo, summarised in a short report.
#   apps/hmira/demo-cli.sh <build-dir> <out-dir>
set -euo pipefail
if [ $# -ne 2 ]; then echo "usage: $0 <build-dir> <out-dir>" >&2; exit 2; fi
build="$(cd "$1" && pwd)"
mkdir -p "$2"
out="$(cd "$2" && pwd)"
root="$(cd "$(dirname "$0")/../.." && pwd)"
hmira="$build/apps/hmira/hmira"
[ -x "$hmira" ] || { echo "demo-cli: $hmira not built (cmake --build $build --target hmira_cli)" >&2; exit 1; }
field() { python3 -c 'import json,sys; d=json.loads(sys.argv[1]); print("|".join(str(d[k]) for k in sys.argv[2:]))' "$@"; }

echo "== $("$hmira" --version 2>/dev/null || echo hmira): command-line demo =="
echo
echo "-- built-in solids: generate, then info (V E F genus closed) --"
printf '%-14s %5s %5s %5s %6s %7s\n' solid V E F genus closed
for s in tetrahedron cube octahedron dodecahedron icosahedron; do
  "$hmira" generate "$s" "$out/$s.off" --scale 2 --quiet
  j=$("$hmira" info --json "$out/$s.off")
  IFS='|' read -r v e f g c <<<"$(field "$j" vertices edges faces genus closed)"
  printf '%-14s %5s %5s %5s %6s %7s\n' "$s" "$v" "$e" "$f" "$g" "$c"
done
echo
echo "-- convert the dodecahedron to every format and back: same counts? --"
for t in obj ply stl; do
  "$hmira" convert "$out/dodecahedron.off" "$out/dodecahedron.$t" --quiet
  j=$("$hmira" info --json "$out/dodecahedron.$t")
  IFS='|' read -r fmt v f <<<"$(field "$j" format vertices faces)"
  printf '  %-20s %-28s V=%s F=%s\n' "dodecahedron.$t" "$fmt" "$v" "$f"
done
echo "  (STL holds triangles only: 12 pentagons become 36 triangles, welded back to 20 vertices)"
echo
echo "-- flip: the orientation reverses, twice gives the same file --"
"$hmira" flip "$out/cube.off" "$out/cube_flipped.off" --quiet
"$hmira" flip "$out/cube_flipped.off" "$out/cube_twice.off" --quiet
if cmp -s "$out/cube.off" "$out/cube_twice.off"; then echo "  flip(flip(cube)) == cube: yes"; else echo "  flip(flip(cube)) == cube: NO"; fi
echo
echo "-- editing and voxels on the generated cube (V E F and enclosed volume after each step) --"
volume() { python3 - "$1" <<'PY'
import sys
pts, vol = [], 0.0
for line in open(sys.argv[1]):
    w = line.split()
    if w and w[0] == 'v': pts.append([float(x) for x in w[1:4]])
    if w and w[0] == 'f':
        p = [pts[int(x.split('/')[0]) - 1] for x in w[1:]]
        for i in range(1, len(p) - 1):
            a, b, c = p[0], p[i], p[i + 1]
            vol += (a[0]*(b[1]*c[2]-b[2]*c[1]) - a[1]*(b[0]*c[2]-b[2]*c[0]) + a[2]*(b[0]*c[1]-b[1]*c[0])) / 6
print(f"{vol:.4f}")
PY
}
"$hmira" generate cube "$out/cube.obj" --quiet
edit() {  # edit <label> <output> <hmira args...>
  local label="$1" file="$2"; shift 2
  local line; line=$("$hmira" "$@")
  line="${line#*: *: }"
  printf '  %-44s %-34s volume %s\n' "$label" "${line% (*}" "$(volume "$out/$file")"
}
edit "truncate --all" cube_truncated.obj truncate "$out/cube.obj" "$out/cube_truncated.obj" --all
edit "truncate --all --fraction 0.5" cuboctahedron.obj truncate "$out/cube.obj" "$out/cuboctahedron.obj" --all --fraction 0.5
edit "bevel --edge 0,1 --width 0.25" cube_chamfer.obj bevel "$out/cube.obj" "$out/cube_chamfer.obj" --edge 0,1 --width 0.25
edit "bevel --angle 60 --width 0.2 --segments 3" cube_rounded.obj bevel "$out/cube.obj" "$out/cube_rounded.obj" --angle 60 --width 0.2 --segments 3
edit "extrude --face 4 --distance 2" cube_tower.obj extrude "$out/cube.obj" "$out/cube_tower.obj" --face 4 --distance 2
edit "extrude --face 0,1 --distance 0.5 (region)" cube_block.obj extrude "$out/cube.obj" "$out/cube_block.obj" --face 0,1 --distance 0.5
echo "  (cube volume 8: truncation cuts 8 x (2/3)^3/6, the chamfer 0.25^2, the tower adds 4 x 2)"
"$hmira" voxelize "$out/cube_tower.obj" "$out/cube_tower.raw" -n 32 --quiet
mc_line=$(sed -n 's/^mc: hmira //p' "$out/cube_tower.raw.txt" | sed "s| surface.obj | $out/tower_back.obj |")
(cd "$out" && eval "\"$hmira\" $mc_line --quiet")
IFS='|' read -r v f cl <<<"$(field "$("$hmira" info --json "$out/tower_back.obj")" vertices faces closed)"
echo "  voxelize tower -n 32 -> $(sed -n 's/^dims: //p' "$out/cube_tower.raw.txt") voxels, $(sed -n 's/^set: //p' "$out/cube_tower.raw.txt") set; mc of the .raw (command from its sidecar): V=$v F=$f closed=$cl"
echo
data="$build/test-data/meshes"
[ -d "$data" ] || "$root/scripts/test-data.sh" "$build/test-data" > /dev/null || true
echo "-- real meshes (Debian libcgal-demo) --"
if [ -d "$data" ]; then
  printf '%-22s %-26s %7s %7s %5s %6s %7s %8s  %s\n' file format V F comps genus closed manifold validate
  for m in elephant.off fandisk.off bunny00.off cross.off colored_tetra.ply sphere.ply pig.stl; do
    [ -f "$data/$m" ] || continue
    if j=$("$hmira" info --json "$data/$m" 2> "$out/err.txt"); then
      IFS='|' read -r fmt v f c g cl ma p <<<"$(field "$j" format vertices faces components genus closed manifold problems)"
      printf '%-22s %-26s %7s %7s %5s %6s %7s %8s  %s\n' "$m" "$fmt" "$v" "$f" "$c" "$g" "$cl" "$ma" "$([ "$p" = 0 ] && echo ok || echo "$p problem(s)")"
    else
      printf '%-22s error: %s\n' "$m" "$(cat "$out/err.txt")"
    fi
  done
  if [ -f "$data/elephant.off" ]; then
    start=$(date +%s%N)
    "$hmira" convert "$data/elephant.off" "$out/elephant.ply" --quiet
    "$hmira" convert "$out/elephant.ply" "$out/elephant.stl" --quiet
    ms=$(( ($(date +%s%N) - start) / 1000000 ))
    j=$("$hmira" info --json "$out/elephant.stl")
    IFS='|' read -r v f <<<"$(field "$j" vertices faces)"
    echo "  elephant.off -> .ply -> .stl in ${ms} ms (two runs of the tool); back from STL: V=$v F=$f (welded)"
  fi
  if [ -f "$data/fandisk.off" ]; then
    echo "  fandisk.off: $("$hmira" bevel "$data/fandisk.off" "$out/fandisk_bevel.off" --angle 60 --width 0.002 | sed 's|^.*fandisk.off: ||; s| (/.*)$||')"
    echo "  fandisk.off: $("$hmira" truncate "$data/fandisk.off" "$out/fandisk_cut.off" --vertex 0,1,2 --fraction 0.3 | sed 's|^.*fandisk.off: ||; s| (/.*)$||')"
    echo "  fandisk.off: $("$hmira" extrude "$data/fandisk.off" "$out/fandisk_extrude.off" --face 0 --distance 0.05 | sed 's|^.*fandisk.off: ||; s| (/.*)$||')"
    echo "  fandisk.off: $("$hmira" voxelize "$data/fandisk.off" "$out/fandisk.binvox" -n 128 | sed 's|^.*fandisk.off: ||; s| -> .*||')"
    for f in fandisk_bevel fandisk_cut fandisk_extrude; do
      IFS='|' read -r cl ma p <<<"$(field "$("$hmira" info --json "$out/$f.off")" closed manifold problems)"
      printf '    %-20s closed=%s manifold=%s problems=%s\n' "$f.off" "$cl" "$ma" "$p"
    done
  fi
else
  echo "  (no libcgal-demo data: install libcgal-demo and run scripts/test-data.sh)"
fi
echo
echo "-- errors are one line, with an exit code --"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n' > "$out/broken.obj"
set +e
"$hmira" convert "$out/broken.obj" "$out/never.ply" 2> "$out/err.txt"; rc=$?
set -e
echo "  hmira convert broken.obj never.ply -> exit $rc: $(sed "s|$out/||" "$out/err.txt")"
echo "  never.ply written: $([ -e "$out/never.ply" ] && echo yes || echo no)"
rm -f "$out/err.txt"
echo
echo "demo-cli: outputs in $out"
