#!/usr/bin/env bash
# Regenerates the README's gallery: runs the real hmira commands (edits of built-in solids, marching
# cubes of CT/MR volumes, a voxelized bunny, a Delaunay terrain), writes each result's page with
# `hmira view`, and screenshots it in headless Chromium into docs/gallery/<name>.png. Each PNG
# carries the commands that made it in a tEXt chunk ("hmira-command"); docs/gallery/README.md
# lists them too.
#   scripts/gallery.sh [build-dir]     (default build)
# On a fresh clone (after scripts/install-deps.sh) it builds what it needs: the viewer bundle
# (viewer/build.sh: npm ci + esbuild) and the hmira tool in <build-dir>.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
mkdir -p "${1:-$root/build}"
build="$(cd "${1:-$root/build}" && pwd)"
hmira="$build/apps/hmira/hmira"
bash "$root/viewer/build.sh" > /dev/null
if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DHMIRA_BUILD_APPS=ON -DHMIRA_BUILD_TESTS=OFF > /dev/null
fi
cmake --build "$build" --target hmira_cli > /dev/null
out="$root/docs/gallery"
work="$build/gallery"
rm -rf "$work"
mkdir -p "$work" "$out"
bash "$root/scripts/test-data.sh" "$build/test-data" > /dev/null
ln -s "$build/test-data" "$work/test-data"
venv="$(bash "$root/tests/browser/venv.sh" "$build/browser-venv")"
cd "$work"

shots=()      # page png commands fragment, four per picture
listing=()    # markdown rows
commands=""   # the commands of the picture being made
run() {  # run <hmira args...>: runs hmira here and records the command as a reader would type it
  commands+="hmira $*"$'\n'
  "$hmira" "$@" --quiet
}
picture() {  # picture <name> <mesh> <fragment> <caption>: the page of <mesh>, then a screenshot
  local name="$1" mesh="$2" fragment="$3" caption="$4"
  run view "$mesh" "$name.html"
  shots+=("$work/$name.html" "$out/$name.png" "${commands%$'\n'}" "$fragment")
  local cell="\`${commands%$'\n'}\`"
  listing+=("| ![$caption]($name.png) | $caption | ${cell//$'\n'/\`<br>\`}${fragment:+<br>(page opened with \`#$fragment\`)} |")
  commands=""
}

echo "gallery: running the commands in $work"
run generate cube cube.obj
run bevel cube.obj cube_rounded.obj --angle 60 --width 0.2 --segments 3
picture bevel_cube cube_rounded.obj "" "Cube with every edge given a rounded bevel (3 segments)"

run generate dodecahedron dodecahedron.obj
run truncate dodecahedron.obj truncated_dodecahedron.obj --all --fraction 0.3
picture truncated_dodecahedron truncated_dodecahedron.obj "" "Truncated dodecahedron: every corner cut off"

run generate cube cube.obj
run extrude cube.obj cube_tower.obj --face 4 --distance 2
picture tower cube_tower.obj "" "Tower: one face of a cube extruded by twice its size"

run mc test-data/images/skull_2.9.inr skull.ply --iso 2.9 --inside above
picture skull skull.ply "up=z&view=front" "Marching cubes of a CT skull (skull_2.9.inr, iso 2.9)"

run mc test-data/images/liver.inr.gz liver.ply --iso 0.5 --inside above
picture liver liver.ply "up=z" "Marching cubes of a segmented liver (liver.inr.gz)"

run voxelize test-data/meshes/bunny00.off bunny.raw -n 64
mc_line=$(sed -n 's/^mc: hmira //p' bunny.raw.txt | sed 's| surface.obj | bunny_voxels.obj |')
eval "run $mc_line"
picture bunny_voxels bunny_voxels.obj "" "Bunny voxelized at 64 voxels, then marching cubes of its voxels"

run delaunay test-data/points_3/b9_training.ply terrain.ply
picture terrain terrain.ply "up=z" "Delaunay terrain: 2.5D triangulation of a LiDAR scan (b9_training.ply)"

echo "gallery: screenshots into $out"
"$venv/bin/python" "$root/tests/browser/screenshot.py" "${shots[@]}"

{
  echo "# Gallery"
  echo
  echo "Made by \`scripts/gallery.sh\` from the commands below (run in a folder where \`test-data\` is the"
  echo "data \`scripts/test-data.sh\` extracts), then \`hmira view\` and a headless-Chromium screenshot. Each PNG"
  echo "also carries its commands in a \`hmira-command\` text chunk."
  echo
  echo "| picture | what | commands |"
  echo "|---|---|---|"
  printf '%s\n' "${listing[@]}"
} > "$out/README.md"
ls -l "$out"/*.png | awk '{ printf "  %s %6.0f KB\n", $NF, $5 / 1024 }'
big=$(find "$out" -name '*.png' -size +200k)
[ -z "$big" ] || { echo "gallery: larger than 200 KB: $big" >&2; exit 1; }
