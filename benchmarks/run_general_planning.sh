#!/usr/bin/env bash
# The pipeline's planning and MADD on a large general PSLG (issue 13: a domain not of closed
# loops is decoupled from its faces): a wavy ring of N segments with a dangling crack and an
# isolated well inside, meshed coarsely so that validation, the faces and MADD dominate.
# Usage: benchmarks/run_general_planning.sh BUILD_DIR [N] [OLD_PDD_MESH]
# OLD_PDD_MESH: a pdd-mesh of another commit, run alternately with this one (side by side);
# benchmarks/build_at_commit.sh builds one (the pair in general-planning.md:
#   bash benchmarks/run_general_planning.sh /var/tmp/pdd-at/69d83403dd/build/release 200000 \
#     "$(bash benchmarks/build_at_commit.sh 2fb310a | tail -1)"
# with 69d8340's build from the same script).
# Raw data: benchmarks/results/general-planning.jsonl, or general-planning-pair.jsonl with
# OLD_PDD_MESH (first line: the provenance, then one line per run with its timings and the
# commit of the pdd-mesh that ran, where it is in a git worktree); the table is printed from it
# only.
set -euo pipefail
build=${1:?build dir}
n=${2:-200000}
old=${3:-}
# shellcheck source=provenance.sh source-path=SCRIPTDIR
source "$(dirname "$0")/provenance.sh"
out=benchmarks/results/general-planning.jsonl
[ -z "$old" ] || out=benchmarks/results/general-planning-pair.jsonl
provenance_json "bash benchmarks/run_general_planning.sh $*" >"$out"
tmp=$(mktemp -d)
poly="$tmp/ring.poly"
trap 'rm -rf "$tmp"' EXIT
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
run() { # label rep exe
  /usr/bin/time -f "%e %U %S %M" -o "$tmp/time" "$3" "$poly" --max-area 1e-4 \
    --threads 1 --subdomains 8 --stats "$tmp/stats.json" -q
  python3 - "$out" "$1" "$2" "$n" "$tmp" \
    "$(git -C "$(dirname "$3")" rev-parse --short=10 HEAD 2>/dev/null || echo unknown)" <<'PY'
import json, sys
out, label, rep, n, tmp, commit = sys.argv[1:]
s = json.load(open(f"{tmp}/stats.json"))
t = s["timings"]
wall, user, system, rss = open(f"{tmp}/time").read().split()[-4:]
stages = sum(t[k] for k in ("read", "decompose", "decouple", "mesh", "merge", "write"))
line = {"binary": label, "commit": commit, "rep": int(rep), "ring_segments": int(n), "triangles": s["triangles"],
        "subdomains": s["subdomains"], "path": s["path"], "wall_seconds": float(wall),
        "user_seconds": float(user), "cpu_seconds": float(user) + float(system),
        "max_rss_kib": int(rss), "plan_seconds": t["total"] - stages, "timings": t}
open(out, "a").write(json.dumps(line) + "\n")
PY
}
for rep in 1 2; do
  [ -z "$old" ] || run old "$rep" "$old"
  run new "$rep" "$build/examples/drivers/pdd-mesh"
done
PYTHONPATH="$(dirname "${BASH_SOURCE[0]}")" python3 - "$out" <<'PY'
import json, sys
from raw_data import read_raw_data
lines = read_raw_data(sys.argv[1])
print("| rep | pdd-mesh | commit | triangles | wall s | CPU s | plan s (total - stages) | decompose s "
      "| mesh s | max RSS MiB |")
print("|---|---|---|---|---|---|---|---|---|---|")
for r in lines[1:]:
    t = r["timings"]
    print(f"| {r['rep']} | {r['binary']} | {r.get('commit', '-')} | {r['triangles']} | {r['wall_seconds']:.2f} | "
          f"{r['cpu_seconds']:.2f} | {r['plan_seconds']:.2f} | {t['decompose']:.2f} | "
          f"{t['mesh']:.2f} | {r['max_rss_kib'] // 1024} |")
PY
