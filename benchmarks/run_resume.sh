#!/usr/bin/env bash
# Reproduces benchmarks/results/resume.md (issue 40): pdd-mesh --output-per-subdomain on the
# bundled pipe, a clean run against a run killed with SIGKILL at FRACTION of the clean run's wall
# time and resumed (--resume), for each of FORMATS; records the wall and CPU seconds of each
# (/usr/bin/time), the pieces kept and meshed, and whether the resumed directory equals the clean
# one file for file (diff -r). Raw data: benchmarks/results/resume.jsonl (first line: the
# provenance, then one line per format); the table is printed from it only.
#   bash benchmarks/run_resume.sh [BUILD_DIR] [MAX_AREA] [N] [FORMATS] [FRACTION]
# Defaults: build/release, 5e-7 (8.3M triangles), 64 subdomains, "binary vtu", 0.8.
set -euo pipefail
build=${1:-build/release}
area=${2:-5e-7}
n=${3:-64}
formats=${4:-binary vtu}
fraction=${5:-0.8}
exe="$build/examples/drivers/pdd-mesh"
# shellcheck source=provenance.sh source-path=SCRIPTDIR
source "$(dirname "$0")/provenance.sh"
out=benchmarks/results/resume.jsonl
provenance_json "bash benchmarks/run_resume.sh ${*@Q}" >"$out"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
timed() { # TIME_FILE COMMAND...: /usr/bin/time's "user system wall" of COMMAND
  /usr/bin/time -f "%U %S %e" -o "$1" "${@:2}"
}
for format in $formats; do
  rm -rf "$tmp/clean" "$tmp/run"
  options=(examples/data/pipe.poly --max-area "$area" --subdomains "$n" --format "$format" -q)
  timed "$tmp/clean.time" "$exe" "${options[@]}" --output-per-subdomain "$tmp/clean"
  kill_at=$(python3 -c "import sys; print(round(float(open(sys.argv[1]).read().split()[-1]) \
    * float(sys.argv[2]), 2))" "$tmp/clean.time" "$fraction")
  status=0
  timed "$tmp/killed.time" timeout -s KILL "$kill_at" "$exe" "${options[@]}" \
    --output-per-subdomain "$tmp/run" || status=$?
  timed "$tmp/resumed.time" "$exe" "${options[@]}" --output-per-subdomain "$tmp/run" --resume \
    --stats "$tmp/r.json"
  same=false
  diff -r "$tmp/clean" "$tmp/run" >/dev/null && same=true
  python3 - "$out" "$tmp" "$format" "$n" "$area" "$fraction" "$kill_at" "$status" "$same" <<'EOF'
import json, sys
out, tmp, fmt, n, area, fraction, kill_at, status, same = sys.argv[1:]
j = json.load(open(f"{tmp}/r.json"))
def timing(name):
    user, system, wall = open(f"{tmp}/{name}.time").read().split()[-3:]
    return {"wall_seconds": float(wall), "cpu_seconds": float(user) + float(system)}
line = {"format": fmt, "subdomains": int(n), "max_area": area, "fraction": float(fraction),
        "triangles": j["triangles"], "clean": timing("clean"), "kill_after_seconds":
        float(kill_at), "killed_exit_status": int(status), "killed": timing("killed"),
        "resumed": timing("resumed"), "pieces_kept": j["pieces_kept"],
        "pieces_meshed": j["pieces_meshed"], "identical": same == "true"}
open(out, "a").write(json.dumps(line) + "\n")
EOF
done
PYTHONPATH="$(dirname "${BASH_SOURCE[0]}")" python3 - "$out" <<'EOF'
import json, sys
from raw_data import read_raw_data
lines = read_raw_data(sys.argv[1])
print("| triangles | N | format | clean wall s | clean CPU s | killed at s | killed exit "
      "| resumed wall s | resumed CPU s | pieces kept | pieces meshed | identical "
      "| (killed + resumed) / clean, wall |")
print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
for r in lines[1:]:
    c, k, s = r["clean"], r["killed"], r["resumed"]
    print(f"| {r['triangles']} | {r['subdomains']} | {r['format']} | {c['wall_seconds']:.2f} | "
          f"{c['cpu_seconds']:.2f} | {r['kill_after_seconds']:.2f} | {r['killed_exit_status']} | "
          f"{s['wall_seconds']:.2f} | {s['cpu_seconds']:.2f} | {r['pieces_kept']} | "
          f"{r['pieces_meshed']} | {'yes' if r['identical'] else 'NO'} | "
          f"{(k['wall_seconds'] + s['wall_seconds']) / c['wall_seconds']:.2f} |")
EOF
