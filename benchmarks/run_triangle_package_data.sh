#!/usr/bin/env bash
# The `triangle` Python package's documented calls on its own data sets (issue 35 item 5):
# pdd-triangle against Triangle 1.6, the triangle counts side by side and the wall time of each
# (both programs write their .node/.ele: the same work; the counts come from the files). The
# data sets are the package's `triangle/data` folder (drufat/triangle on GitHub; not bundled:
# pdd bundles only geometries it generates), e.g.
#   git -C triangle-clone archive HEAD triangle/data | tar -x -C /tmp/pkg
# Raw data: benchmarks/results/triangle-package-data.jsonl (first line: the provenance); the
# table is printed from it.
# Usage: benchmarks/run_triangle_package_data.sh BUILD_DIR TRIANGLE_EXE DATA_DIR
set -euo pipefail
build=${1:?build dir}
triangle=${2:?Triangle 1.6 executable}
data=${3:?the triangle package data folder}
pdd="$build/examples/drivers/pdd-triangle"
source "$(dirname "$0")/provenance.sh"
out=benchmarks/results/triangle-package-data.jsonl
provenance_json "bash benchmarks/run_triangle_package_data.sh $*" >"$out"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
# one run: LABEL INPUT SWITCHES COMMAND...; the count from the .1.ele it wrote
run() {
  local label=$1 input=$2 sw=$3 stem=${2%.*}
  rm -f "$dir/$stem".1.*
  /usr/bin/time -f "%e" -o "$dir/time" "${@:4}" >/dev/null 2>"$dir/err" || true
  python3 - "$out" "$label" "$input" "$sw" "$dir/$stem.1.ele" "$dir/time" "$dir/err" <<'PY'
import json, os, sys
out, label, name, sw, ele, timing, err = sys.argv[1:]
line = {"program": label, "input": name, "switches": sw,
        "triangles": int(open(ele).readline().split()[0]) if os.path.exists(ele) else None,
        "error": open(err).read().strip().splitlines()[-1] if not os.path.exists(ele) else None,
        "wall_seconds": float(open(timing).read().split()[-1])}
open(out, "a").write(json.dumps(line) + "\n")
PY
}
# the package's documented calls (doc/plot/*.py) on its data, and Triangle's angle range
for case in "face.poly p" "face.poly pq" "face.poly pq10" "face.poly pq30" "face.poly pq33" \
  "A.poly p" "A.poly pq" "A.poly pq30" "A.poly pq33" "la.poly pq" "la.poly pqa" \
  "la.poly pq30" "la.poly pqa0.01" "box.poly pc" "box.poly pq" "double_hex.poly pq" \
  "square_circle_hole.poly pq" "square_circle_hole.poly pq30" "spiral.node Q" \
  "spiral.node q" "spiral.node q32.5" "spiral.node a.2" "dots.node q" \
  "diamond_02_00009.node q"; do
  set -- $case
  for f in "$data/${1%.*}".*; do
    case "$f" in *.1.* | *.2.* | *.3.* | *.4.* | *.q.* | *.r.*) ;; *) cp "$f" "$dir/" ;; esac
  done
  sw=${2#Q}
  run "Triangle 1.6" "$1" "$2" "$triangle" -Q"$sw" "$dir/$1"
  run "pdd-triangle" "$1" "$2" "$pdd" -Q"$sw" "$dir/$1"
done
PYTHONPATH="$(dirname "${BASH_SOURCE[0]}")" python3 - "$out" <<'PY'
import json, sys
from raw_data import read_raw_data
lines = read_raw_data(sys.argv[1])
print("| input | switches | Triangle 1.6 | pdd-triangle | difference | within 15 % or 12 | Triangle s | pdd s |")
print("|---|---|--:|--:|--:|---|--:|--:|")
runs = lines[1:]
for t in (r for r in runs if r["program"].startswith("Triangle")):
    p = next(x for x in runs if x["input"] == t["input"] and x["switches"] == t["switches"]
             and x["program"] == "pdd-triangle")
    if p["triangles"] is None:
        print("| %s | `-%s` | %d | error: %s | | **no** | %.2f | |" % (
            t["input"], t["switches"], t["triangles"], p["error"], t["wall_seconds"]))
        continue
    d = p["triangles"] - t["triangles"]
    ok = abs(d) <= max(12, 0.15 * t["triangles"])
    print("| %s | `-%s` | %d | %d | %+d (%+.1f %%) | %s | %.2f | %.2f |" % (
        t["input"], t["switches"], t["triangles"], p["triangles"], d,
        100.0 * d / t["triangles"] if t["triangles"] else 0.0, "yes" if ok else "**no**",
        t["wall_seconds"],
        p["wall_seconds"]))
PY
