#!/usr/bin/env bash
# Vertex sets (Triangle without -p, issue 35): pdd-triangle against Triangle 1.6 on random points
# and the R2 sequence (benchmarks/results/triangle-point-sets.md). Both programs write their
# .node/.ele files (the same work; the counts come from them); Triangle and pdd-triangle
# --threads 1 are pinned to CPU 0, pdd-triangle --threads 2 to CPUs 0 and 1. Raw data:
# benchmarks/results/triangle-point-sets.jsonl (first line: the provenance); the table is printed
# from it.
# Usage: benchmarks/run_triangle_point_sets.sh BUILD_DIR TRIANGLE_EXE
set -euo pipefail
build=${1:?build dir}
triangle=${2:?Triangle 1.6 executable}
pdd="$build/examples/drivers/pdd-triangle"
source "$(dirname "$0")/provenance.sh"
out=benchmarks/results/triangle-point-sets.jsonl
provenance_json "bash benchmarks/run_triangle_point_sets.sh $*" >"$out"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
/usr/bin/python3 - "$dir" <<'PY' # numpy: Debian's python3-numpy
import math, sys
import numpy as np
d = sys.argv[1]
def write(name, pts):
    with open(f"{d}/{name}.node", "w") as f:
        f.write(f"{len(pts)} 2 0 0\n")
        np.savetxt(f, np.c_[np.arange(1, len(pts) + 1), pts], fmt=["%d", "%.17g", "%.17g"])
p = np.random.default_rng(1).random((1000000, 2))  # uniformly random in the unit square
write("m1", p)
write("k100", p[:100000])
write("s100", p[:100])
write("r2", np.array([[math.fmod(i * 0.6180339887498949, 1.0),
                       math.fmod(i * 0.7548776662466927, 1.0)] for i in range(500)]))
write("rand200", np.random.default_rng(5).random((200, 2)))
PY
# one run: LABEL CPUS NAME SWITCHES COMMAND...; the counts from the .1.ele/.1.node it wrote
run() {
  local label=$1 cpus=$2 name=$3 sw=$4
  rm -f "$dir/$name".1.*
  /usr/bin/time -f "%U %S %e %M" -o "$dir/time" taskset -c "$cpus" "${@:5}"
  : >"$dir/stdout"
  if [[ $label == pdd* ]]; then # untimed: the same run without Q and files, for its N
    taskset -c "$cpus" "$5" -"${sw//Q/}"NEP "${@:7}" >"$dir/stdout"
  fi
  python3 - "$out" "$label" "$name" "$sw" "$dir" <<'PY'
import json, re, sys
out, label, name, sw, d = sys.argv[1:]
user, system, wall, rss = open(f"{d}/time").read().split()[-4:]
first = lambda f: int(open(f).readline().split()[0])
subdomains = re.search(r"\((\d+) subdomain", open(f"{d}/stdout").read())
line = {"program": label, "input": name, "switches": sw,
        "triangles": first(f"{d}/{name}.1.ele"), "vertices": first(f"{d}/{name}.1.node"),
        "wall_seconds": float(wall), "cpu_seconds": float(user) + float(system),
        "max_rss_kib": int(rss), "subdomains": int(subdomains[1]) if subdomains else None}
open(out, "a").write(json.dumps(line) + "\n")
PY
}
for case in "m1 Q" "k100 Qq" "k100 Qqa0.00001" "k100 Qq30" "k100 Qq32.5" "k100 Qq33.8" "r2 Q" \
  "r2 Qq" "r2 Qqa0.002" "r2 Qq30a0.001" "rand200 Qa0.01" "k100 Qqa0.000001" "m1 Qq" \
  "m1 Qqa0.0000001" "s100 Qqa0.0000001"; do
  set -- $case
  run "Triangle 1.6" 0 "$1" "$2" "$triangle" -"$2" "$dir/$1.node"
  run "pdd-triangle --threads 1" 0 "$1" "$2" "$pdd" -"$2" "$dir/$1.node" --threads 1
  run "pdd-triangle --threads 2" 0-1 "$1" "$2" "$pdd" -"$2" "$dir/$1.node" --threads 2
done
PYTHONPATH="$(dirname "${BASH_SOURCE[0]}")" python3 - "$out" <<'PY'
import json, sys
from raw_data import read_raw_data
lines = read_raw_data(sys.argv[1])
print("| input | switches | program | triangles | vs Triangle | wall s | CPU s | max RSS MiB | N |")
print("|---|---|---|---|---|---|---|---|---|")
runs = lines[1:]
for r in runs:
    t = next(x for x in runs if x["input"] == r["input"] and x["switches"] == r["switches"]
             and x["program"].startswith("Triangle"))
    print("| %s | `-%s` | %s | %d | %+.1f %% | %.2f | %.2f | %d | %s |" % (
        r["input"], r["switches"], r["program"], r["triangles"],
        100.0 * (r["triangles"] / t["triangles"] - 1.0), r["wall_seconds"], r["cpu_seconds"],
        r["max_rss_kib"] // 1024, r.get("subdomains") or ""))
PY
