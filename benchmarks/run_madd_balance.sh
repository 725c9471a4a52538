#!/usr/bin/env bash
# Reproduces benchmarks/results/madd-balance.md (issue 36 item 4): MADD's largest/mean subdomain
# area at every N of a scan (2-39, then every 17th to 397, then every 150th to 4050: 86 counts)
# on the real geometries of ../shared/data, for this build and for the build of BASE_COMMIT
# (default 2d2ed8c, the last one that halved the largest subdomain first), both as
# `pdd-decompose INPUT -n N --threads 1 --no-smoothing --stats` (the library's defaults; the
# time is MADD's own time_s). Raw data: benchmarks/results/madd-balance.jsonl (first line: the
# provenance).
#   bash benchmarks/run_madd_balance.sh [BUILD_DIR] [BASE_COMMIT]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/release}
base=${2:-2d2ed8c}
data=../shared/data
[ -d "$data" ] || { echo "run_madd_balance.sh: $data is absent" >&2; exit 1; }
new="$build/examples/drivers/pdd-decompose"
[ -x "$new" ] || cmake --build "$build" --target pdd-decompose -j1 >/dev/null
old=$(bash benchmarks/build_at_commit.sh "$base" /var/tmp/pdd-at pdd-decompose | tail -1)
# shellcheck source=provenance.sh source-path=SCRIPTDIR
source benchmarks/provenance.sh
out=benchmarks/results/madd-balance.jsonl
provenance_json "bash benchmarks/run_madd_balance.sh $*" >"$out"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
counts="$(seq 2 39) $(seq 40 17 399) $(seq 400 150 4199)"
for input in lake_superior texas guitar mesh2d_airfoil_3element bahamas_islands; do
  for n in $counts; do
    for which in base head; do
      exe=$new
      [ "$which" = base ] && exe=$old
      "$exe" "$data/$input.poly" -n "$n" --threads 1 --no-smoothing -q --stats "$tmp/s.json"
      python3 - "$tmp/s.json" "$input" "$n" "$which" "$base" >>"$out" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
print(json.dumps({"input": sys.argv[2], "N": int(sys.argv[3]), "build": sys.argv[4],
                  "base_commit": sys.argv[5], "subdomains": s["subdomains"],
                  "max_area_over_mean": s["max_area_over_mean"], "time_s": s["time_s"],
                  "min_separator_angle_deg": s["min_separator_angle_deg"],
                  "separator_length_total": s["separator_length_total"], "valid": s["valid"]}))
PY
    done
  done
done
PYTHONPATH=benchmarks python3 - "$out" <<'PY'
import sys
from raw_data import read_raw_data
runs = [l for l in read_raw_data(sys.argv[1]) if "max_area_over_mean" in l]
base = runs[0]["base_commit"]
print(f"Largest/mean subdomain area over {len({r['N'] for r in runs})} subdomain counts N "
      f"(2-4050), base = {base} (largest first), head = this build (quotas); MADD's time on one "
      "thread summed over the counts; separator length summed likewise.\n")
print("| input | build | median | 90th percentile | worst (N) | N above 1.5 | time (s) | "
      "separator length | all valid, angle >= 60 |")
print("|---|---|---:|---:|---:|---:|---:|---:|---|")
for name in dict.fromkeys(r["input"] for r in runs):
    for b in ("base", "head"):
        rs = [r for r in runs if r["input"] == name and r["build"] == b]
        v = sorted(r["max_area_over_mean"] for r in rs)
        worst = max(rs, key=lambda r: r["max_area_over_mean"])
        ok = all(r["valid"] and r["min_separator_angle_deg"] >= 60.0 for r in rs)
        print(f"| {name} | {b} | {v[len(v) // 2]:.3f} | {v[int(0.9 * len(v))]:.3f} | "
              f"{worst['max_area_over_mean']:.3f} ({worst['N']}) | "
              f"{sum(x > 1.5 for x in v)} of {len(v)} | {sum(r['time_s'] for r in rs):.2f} | "
              f"{sum(r['separator_length_total'] for r in rs):.4g} | {'yes' if ok else 'NO'} |")
PY
