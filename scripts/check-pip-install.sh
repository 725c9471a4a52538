#!/usr/bin/env bash
# Proves that `pip install .` builds and installs the Python module offline (issue 38 item 4):
# copies the clone's files (tracked and untracked, not the ignored build trees) to a scratch
# folder, makes a venv over Debian's python3 (--system-site-packages: its numpy, setuptools,
# wheel), runs `pip install --no-build-isolation --no-index` there, then imports pdd from
# outside any source tree and checks its version, a mesh, its docstring and its metadata.
# It compiles the module from scratch: minutes (CMAKE_BUILD_PARALLEL_LEVEL limits the jobs).
#
# Usage: scripts/check-pip-install.sh [SOURCE_DIR]      (default: this clone; needs git)
#        PDD_PIP_PYTHON: the interpreter (default /usr/bin/python3, Debian's)
# Debian packages: python3-venv python3-pip (scripts/install-deps.sh), and pdd's C++ ones.
set -euo pipefail
src=$(cd "${1:-$(dirname "$0")/..}" && pwd)
python=${PDD_PIP_PYTHON:-/usr/bin/python3}
scratch=$(mktemp -d /tmp/pdd-pip-check.XXXXXX)
trap 'rm -rf "$scratch"' EXIT

mkdir "$scratch/clone"
(cd "$src" && git ls-files -z --cached --others --exclude-standard |
  xargs -0 cp --parents -t "$scratch/clone")

"$python" -m venv --system-site-packages "$scratch/venv"
"$scratch/venv/bin/python" -m pip install --no-build-isolation --no-index "$scratch/clone"

version=$(sed -n 's/^project(pdd VERSION \([0-9.]*\).*/\1/p' "$src/CMakeLists.txt")
cd "$scratch"  # neither the clone nor a build tree: the installed module only
PDD_EXPECTED_VERSION=$version "$scratch/venv/bin/python" - <<'EOF'
import importlib.metadata, os, pydoc, sys
import pdd

print(pdd.__version__, pdd.triangulate({'vertices': [[0, 0], [1, 0], [0, 1]],
                                        'segments': [[0, 1], [1, 2], [2, 0]]}, 'pq'))
assert pdd.__version__ == os.environ["PDD_EXPECTED_VERSION"], pdd.__version__
assert pdd.__file__.startswith(sys.prefix), pdd.__file__
assert "Meshes a PSLG" in pydoc.render_doc(pdd.triangulate), "no docstring in help()"
meta = importlib.metadata.metadata("pdd")
assert meta["Version"] == pdd.__version__, meta["Version"]
for key in ("Name", "Version", "Summary", "License", "Requires-Python", "Requires-Dist"):
    print(f"{key}: {meta[key]}")
print("check-pip-install: OK,", pdd.__file__)
EOF
