#!/usr/bin/env bash
# The Python package's check: builds and installs `hmira` with `pip install .` into a fresh
# venv (nanobind + scikit-build-core from PyPI), checks that the committed type stubs equal
# what nanobind's stubgen makes now, and runs the pytest suite. It builds the viewer bundle first
# (viewer/build.sh: node and npm), so hmira.view and hmira.render are tested, never skipped.
#   HMIRA_TEST_DATA  libcgal-demo data (default: build/test-data, as scripts/test-data.sh makes it)
#   HMIRA_CLI        the C++ `hmira` binary the tests compare with (unset: those comparisons skip)
#   HMIRA_PY_VENV    where the venv goes (default: build/python-venv; always made anew)
#   HMIRA_PY_OPT     optimisation flags for the extension instead of the Release -O3 a user's
#                    `pip install .` gets (scripts/test.sh passes -O1: the wheel is tested, not timed)
set -euo pipefail
cd "$(dirname "$0")/.."
start=$(date +%s)
venv=${HMIRA_PY_VENV:-build/python-venv}
case $venv in /*) ;; *) venv=$PWD/$venv ;; esac
export HMIRA_TEST_DATA=${HMIRA_TEST_DATA:-$PWD/build/test-data}
export CCACHE_BASEDIR=${CCACHE_BASEDIR:-$PWD}

echo "== fresh venv at $venv"
rm -rf "$venv"
python3 -m venv "$venv"
"$venv/bin/python" -m pip install -q --upgrade pip
"$venv/bin/python" -m pip install -q -r python/requirements-test.txt

echo "== viewer bundle (viewer/build.sh), compiled into hmira._core for hmira.view and hmira.render"
viewer/build.sh

echo "== pip wheel . (builds hmira._core), then pip install of that wheel"
# The build requirements (pinned in pyproject.toml) are already in the venv from the
# requirements file: building without isolation keeps nanobind's path stable from run to run,
# so ccache (CMAKE_CXX_COMPILER_LAUNCHER, set by the project) hits on an unchanged tree.
wheels=$(mktemp -d)
opt=()
if [ -n "${HMIRA_PY_OPT:-}" ]; then
  opt=(-C "cmake.define.CMAKE_CXX_FLAGS_RELEASE=$HMIRA_PY_OPT -DNDEBUG")
fi
"$venv/bin/python" -m pip wheel -q --no-build-isolation --no-deps "${opt[@]}" -w "$wheels" .
"$venv/bin/python" -m pip install -q "$wheels"/hmira-*.whl
echo "built and installed after $(( $(date +%s) - start )) s"

echo "== the wheel is self-contained: _core finds oneTBB inside the installed package"
core=$("$venv/bin/python" -c 'import hmira._core as c; print(c.__file__)')
pkg=$(dirname "$core")
if ldd "$core" | grep -q libtbb; then
  if ! ldd "$core" | grep libtbb | grep -q "=> $pkg/"; then
    echo "hmira._core resolves oneTBB outside the wheel:" >&2
    ldd "$core" | grep libtbb >&2
    exit 1
  fi
  "$venv/bin/python" -c 'import sys, zipfile
names = zipfile.ZipFile(sys.argv[1]).namelist()
sys.exit(0 if any(n.startswith("hmira/libtbb") for n in names) else "the wheel carries no libtbb")' "$wheels"/hmira-*.whl
fi
rm -rf "$wheels"

echo "== type stubs: committed python/hmira/_core.pyi must equal nanobind's stubgen output"
stubs=$(mktemp -d)
trap 'rm -rf "$stubs"' EXIT
(cd "$stubs" && "$venv/bin/python" -m nanobind.stubgen -q -m hmira._core -o "$stubs/_core.pyi")
if ! diff -u python/hmira/_core.pyi "$stubs/_core.pyi"; then
  echo "python/hmira/_core.pyi is out of date: regenerate it with" >&2
  echo "  $venv/bin/python -m nanobind.stubgen -m hmira._core -o python/hmira/_core.pyi" >&2
  exit 1
fi

echo "== pytest (installed package, not the source tree)"
(cd python/tests && "$venv/bin/python" -m pytest -q -p no:cacheprovider .)
echo "python checks finished after $(( $(date +%s) - start )) s"
