#!/usr/bin/env bash
# The pipeline's planning and MADD on a large general PSLG (issue 13: a domain not of closed
# loops is decoupled from its faces): a wavy ring of N segments with a dangling crack and an
# isolated well inside, meshed coarsely so that validation, the faces and MADD dominate.
# Usage: benchmarks/run_general_planning.sh BUILD_DIR [N] [OLD_PDD_MESH]
# OLD_PDD_MESH: a pdd-mesh of another commit, run alternately with this one (side by side).
set -euo pipefail
build=${1:?build dir}
n=${2:-200000}
old=${3:-}
poly=$(mktemp --suffix=.poly)
trap 'rm -f "$poly" /tmp/general_planning_*.json' EXIT
python3 - "$n" "$poly" <<'PY'
import math, sys
n, path = int(sys.argv[1]), sys.argv[2]
r = lambda t: 1 + 0.05 * math.sin(40 * t)
pts = [(math.cos(t) * r(t), math.sin(t) * r(t)) for t in (2 * math.pi * i / n for i in range(n))]
pts += [(-0.1, 0.0), (0.1, 0.0), (0.0, 0.5)]  # a dangling crack and an isolated well
with open(path, "w") as f:
    f.write(f"{len(pts)} 2 0 0\n")
    f.writelines(f"{i + 1} {x!r} {y!r}\n" for i, (x, y) in enumerate(pts))
    f.write(f"{n + 1} 0\n")
    f.writelines(f"{i + 1} {i + 1} {(i + 1) % n + 1}\n" for i in range(n))
    f.write(f"{n + 1} {n + 1} {n + 2}\n0\n")
PY
run() { # label exe
  /usr/bin/time -f "%e %U %M" -o /tmp/general_planning_time "$2" "$poly" --max-area 1e-4 \
    --threads 1 --subdomains 8 --stats "/tmp/general_planning_$1.json" -q
  python3 - "$1" <<'PY'
import json, sys
label = sys.argv[1]
s = json.load(open(f"/tmp/general_planning_{label}.json"))
t = s["timings"]
wall, user, rss = open("/tmp/general_planning_time").read().split()
stages = sum(t[k] for k in ("read", "decompose", "decouple", "mesh", "merge", "write"))
print(f"| {label} | {s['triangles']} | {wall} | {user} | {t['total'] - stages:.2f} | "
      f"{t['decompose']:.2f} | {t['mesh']:.2f} | {int(rss) // 1024} |")
PY
}
echo "| pdd-mesh | triangles | wall s | user s | plan s (total - stages) | decompose s | mesh s | max RSS MiB |"
echo "|---|---|---|---|---|---|---|---|"
for _ in 1 2; do
  [ -z "$old" ] || run old "$old"
  run new "$build/examples/drivers/pdd-mesh"
done
