#!/usr/bin/env bash
# End-to-end demo of the `hmira` tool: built-in solids (generate, info, convert, flip) and
# real meshes from Debian's libcgal-demo, summarised in a short report.
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
