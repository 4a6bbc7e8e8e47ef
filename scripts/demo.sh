#!/usr/bin/env bash
# The README's main job: installs what is missing, builds the demo and the tools, and runs them
# on built-in data and on real meshes from Debian's libcgal-demo. Output files go to demo-output/.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc 2>/dev/null || echo 2)
bash scripts/install-deps.sh
bash scripts/test-data.sh build/test-data >/dev/null
cmake -S . -B build/demo -G Ninja -DCMAKE_BUILD_TYPE=Release -DHMIRA_BUILD_TESTS=OFF -DHMIRA_BUILD_EXAMPLES=OFF \
      -DHMIRA_BUILD_APPS=ON >/dev/null
cmake --build build/demo -j"$jobs" >/dev/null
./build/demo/apps/demo/hmira-demo --out demo-output --data build/test-data
if [ -x apps/hmira/demo-cli.sh ] || [ -f apps/hmira/demo-cli.sh ]; then
  echo
  bash apps/hmira/demo-cli.sh build/demo demo-output/cli
fi
# The viewer bundle is committed (viewer/dist/hmira-viewer.js), so this build's `hmira view`
# works without node: a page to open in any browser.
echo
./build/demo/apps/hmira/hmira generate icosahedron demo-output/icosahedron.off -q
./build/demo/apps/hmira/hmira view demo-output/icosahedron.off demo-output/icosahedron.html
