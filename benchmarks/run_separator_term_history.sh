#!/usr/bin/env bash
# Reproduces the two figures of benchmarks/results/real-geometries.md that compare old commits:
#   separator term: a5f69b8 (k_i <= L_i / 4) against d0a7e8c (k_i <= sqrt 3 L_i / 4, L_i the
#     shortest separator segment of D_i) on the Bahamas at 20M and 5M and the airfoil at 2M:
#     automatic N on 2 threads (pinned to CPUs 0-1) and the same commit's monolithic kernel
#     (--subdomains 1, pinned to CPU 0) for the over-refinement;
#   8.3 at a5f69b8: the Bahamas at 2M, --subdomains 64 --geometric-sizing on
#     --geometric-field 8.3, 2 threads (its run at the current code is run_geometric_history.sh's).
# Each commit's pdd-mesh is built by benchmarks/build_at_commit.sh (under WORK_DIR, default
# /var/tmp/pdd-at; a built one is reused). The area bound for about T triangles is
# area_domain / (0.656 T), as run_real_geometries.sh computes it. About 10 minutes once built.
#   bash benchmarks/run_separator_term_history.sh [WORK_DIR]
# Raw data: benchmarks/results/separator-term-history.jsonl (first line: the provenance, then one
# line per run with the commit that ran); the tables are printed from it only.
set -euo pipefail
work=${1:-/var/tmp/pdd-at}
here=$(dirname "$0")
data=$here/../../shared/data
# shellcheck source=provenance.sh source-path=SCRIPTDIR
source "$here/provenance.sh"
out=benchmarks/results/separator-term-history.jsonl
provenance_json "bash benchmarks/run_separator_term_history.sh $*" >"$out"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for g in bahamas_islands mesh2d_airfoil_3element; do
  [ -f "$data/$g.poly" ] || { echo "skip: $data/$g.poly is absent" >&2; exit 0; }
done
declare -A exe
for commit in a5f69b8 d0a7e8c; do
  exe[$commit]=$(bash "$here/build_at_commit.sh" "$commit" "$work" | tail -1)
done
area_for() { # GEOMETRY TRIANGLES: the area bound as a plain decimal
  "${exe[d0a7e8c]}" "$data/$1.poly" --subdomains 1 --stats "$tmp/a.json" -q
  python3 -c "import json, sys; print('%.12f' % (json.load(open(sys.argv[1]))['area_domain']
    / (int(sys.argv[2]) * 0.656)))" "$tmp/a.json" "$2"
}
run() { # PART COMMIT GEOMETRY TRIANGLES AREA LABEL CPUS THREADS [OPTIONS...]
  local part=$1 commit=$2 geometry=$3 target=$4 area=$5 label=$6 cpus=$7 threads=$8
  shift 8
  /usr/bin/time -f "%U %S %e %M" -o "$tmp/time" taskset -c "$cpus" "${exe[$commit]}" \
    "$data/$geometry.poly" --max-area "$area" --threads "$threads" --stats "$tmp/s.json" -q "$@"
  python3 - "$out" "$tmp" "$part" "$commit" "$geometry" "$target" "$area" "$label" "$*" <<'PY'
import json, sys
out, tmp, part, commit, geometry, target, area, label, options = sys.argv[1:]
s = json.load(open(f"{tmp}/s.json"))
user, system, wall, rss = open(f"{tmp}/time").read().split()[-4:]
line = {"part": part, "commit": commit, "geometry": geometry, "target_triangles": int(target),
        "max_area": float(area), "run": label, "options": options,
        "triangles": s["triangles"], "subdomains": s["subdomains"],
        "split_points": s.get("split_points"), "path": s.get("path"),
        "wall_seconds": float(wall), "cpu_seconds": float(user) + float(system),
        "max_rss_kib": int(rss)}
open(out, "a").write(json.dumps(line) + "\n")
PY
}
for case in "bahamas_islands 20000000" "bahamas_islands 5000000" "mesh2d_airfoil_3element 2000000"; do
  read -r geometry target <<<"$case"
  area=$(area_for "$geometry" "$target")
  for commit in a5f69b8 d0a7e8c; do
    run separator "$commit" "$geometry" "$target" "$area" monolithic 0 1 --subdomains 1
    run separator "$commit" "$geometry" "$target" "$area" automatic-2 0-1 2
  done
done
area=$(area_for bahamas_islands 2000000)
run field-8.3 a5f69b8 bahamas_islands 2000000 "$area" 8.3 0-1 2 --subdomains 64 \
  --geometric-sizing on --geometric-field 8.3
PYTHONPATH="$here" python3 - "$out" <<'PY'
import sys
from raw_data import read_raw_data
runs = read_raw_data(sys.argv[1])[1:]
names = {"bahamas_islands": "Bahamas", "mesh2d_airfoil_3element": "airfoil"}
mono = {(r["commit"], r["geometry"], r["target_triangles"]): r["triangles"]
        for r in runs if r["run"] == "monolithic"}
print("| run | commit | triangles | over-refinement | subdomains | split points | wall s |")
print("|---|---|---|---|---|---|---|")
for r in runs:
    if r["part"] != "separator" or r["run"] == "monolithic":
        continue
    m = mono[(r["commit"], r["geometry"], r["target_triangles"])]
    print(f"| {names[r['geometry']]} {r['target_triangles'] / 1e6:g}M, {r['run']} | {r['commit']} | "
          f"{r['triangles']:,} | {100 * (r['triangles'] / m - 1):+.2f} % (of {m:,}) | "
          f"{r['subdomains']} | {r['split_points']:,} | {r['wall_seconds']:.2f} |")
for r in runs:
    if r["part"] == "field-8.3":
        print(f"\nAlgorithm 8.3's F at {r['commit']}, the Bahamas at 2M (`{r['options']}`): "
              f"{r['triangles']:,} triangles, {r['subdomains']} subdomains, "
              f"{r['split_points']:,} split points, {r['wall_seconds']:.1f} s wall, "
              f"{r['max_rss_kib'] / 1048576:.2f} GiB max RSS")
PY
