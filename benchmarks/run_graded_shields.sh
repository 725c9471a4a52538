#!/usr/bin/env bash
# Reproduces benchmarks/results/graded-shields.md: the over-refinement of the decoupled mesh
# against the monolithic mesh (same CGAL kernel, same field: pdd-mesh --compare-monolithic) on the
# ../shared/data geometries with the graded path's shields (dissertation 8.3, Theorem 26), for
# N automatic and N = 64 (the N = 64 runs also --verify), on 2 threads. TAG names the binary in
# the raw data (e.g. main, or before/after when comparing two builds).
#   bash benchmarks/run_graded_shields.sh PDD_MESH TAG [FIELDS] [OUT_DIR]
# FIELDS (default "graded steep const"): graded (F = a (1 + 30 u^2), u = x across the bounding
# box), steep (a (1 + 999 u^2)) or const (F = a); a is set per geometry for about 0.2M-1M
# triangles. Raw data: benchmarks/results/graded-shields.jsonl for TAG main, else
# graded-shields-TAG.jsonl (first line: the provenance, then one line per run); the tables are
# printed from it only, and for a TAG other than main also its over-refinement beside main's
# (the history of the shields: TAG 25fb814, a build of that commit by
# benchmarks/build_at_commit.sh). The --stats JSON of each run is kept in OUT_DIR (default
# /tmp/graded-shields).
set -euo pipefail
bin=${1:?usage: run_graded_shields.sh PDD_MESH TAG [FIELDS] [OUT_DIR]}
tag=${2:?usage: run_graded_shields.sh PDD_MESH TAG [FIELDS] [OUT_DIR]}
fields=${3:-graded steep const}
dir=${4:-/tmp/graded-shields}
mkdir -p "$dir"
# shellcheck source=provenance.sh source-path=SCRIPTDIR
source "$(dirname "$0")/provenance.sh"
main_out=benchmarks/results/graded-shields.jsonl
out=$main_out
[ "$tag" = main ] || out=benchmarks/results/graded-shields-$tag.jsonl
provenance_json "bash benchmarks/run_graded_shields.sh $*" >"$out"
data=$(dirname "$0")/../../shared/data
declare -A X=([lake_superior]=0.1 [texas]=-10664 [mesh2d_airfoil_3element]=0 [guitar]=0.5)
declare -A W=([lake_superior]=0.8 [texas]=1313 [mesh2d_airfoil_3element]=1 [guitar]=35.75)
for field in $fields; do
  case $field in
  graded) declare -A A=([lake_superior]=5.5e-8 [texas]=0.275 [mesh2d_airfoil_3element]=5.2e-7 [guitar]=1.74e-4); g=30 ;;
  steep) declare -A A=([lake_superior]=1.06e-8 [texas]=0.0528 [mesh2d_airfoil_3element]=1.0e-7 [guitar]=3.34e-5); g=999 ;;
  const) declare -A A=([lake_superior]=2.17e-7 [texas]=1.08 [mesh2d_airfoil_3element]=2.05e-6 [guitar]=6.9e-4); g=0 ;;
  *) echo "FIELDS: graded, steep or const" >&2; exit 1 ;;
  esac
  for f in lake_superior texas mesh2d_airfoil_3element guitar; do
    e="${A[$f]}"
    [ "$g" != 0 ] && e="${A[$f]}*(1+$g*((x-(${X[$f]}))/${W[$f]})^2)"
    for n in auto 64; do
      opts=()
      [ "$n" = 64 ] && opts=(--subdomains 64 --verify)
      json="$dir/${tag}_${field}_${f}_${n}.json"
      /usr/bin/time -f "%U %S %e %M" -o "$dir/time" nice -n 10 "$bin" "$data/$f.poly" \
        --sizing "$e" "${opts[@]}" --threads 2 --compare-monolithic --stats "$json" -q
      python3 - "$out" "$json" "$dir/time" "$tag" "$field" "$f" "$n" "$e" <<'PY'
import json, sys
out, path, time_file, tag, field, f, n, sizing = sys.argv[1:]
j = json.load(open(path))
user, system, wall, rss = open(time_file).read().split()[-4:]
keys = ("triangles", "monolithic_triangles", "over_refinement_pct", "subdomains", "path",
        "graded_path", "graded_fallback", "shielded_triangles", "verified",
        "delaunay_violations", "conforming", "interface_splits", "max_area_ratio",
        "min_angle_unshielded_deg", "timings")
line = {"binary": tag, "field": field, "geometry": f, "n": n, "sizing": sizing}
line.update({k: j.get(k) for k in keys})
line.update({"wall_seconds": float(wall), "cpu_seconds": float(user) + float(system),
             "max_rss_kib": int(rss)})
open(out, "a").write(json.dumps(line) + "\n")
PY
    done
  done
done
PYTHONPATH="$(dirname "${BASH_SOURCE[0]}")" python3 - "$out" "$main_out" <<'PY'
import json, sys
from raw_data import read_raw_data
lines = read_raw_data(sys.argv[1], blank_line=False)
runs = lines[1:]
names = {"lake_superior": "Lake Superior", "texas": "Texas",
         "mesh2d_airfoil_3element": "airfoil (3 elements)", "guitar": "guitar"}


def f(value, spec=""):
    """value formatted, or '-' where an older binary's --stats has no such field"""
    return "-" if value is None else format(value, spec)


for field in dict.fromkeys(r["field"] for r in runs):
    print(f"\n### Field `{field}`\n")
    print("| binary | geometry | N | subdomains | path | graded path | over % | triangles "
          "| monolithic triangles | shielded | mesh s | monolithic s | wall s | CPU s "
          "| max RSS MiB |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for r in (r for r in runs if r["field"] == field):
        t = r["timings"]
        print(f"| {r['binary']} | {names.get(r['geometry'], r['geometry'])} | {r['n']} | "
              f"{r['subdomains']} | {f(r['path'])} | {f(r['graded_path'])} | "
              f"{r['over_refinement_pct']:.2f} | {r['triangles']} | "
              f"{r['monolithic_triangles']} | {f(r['shielded_triangles'])} | {t['mesh']:.2f} | "
              f"{f(t.get('monolithic_comparison'), '.2f')} | {r['wall_seconds']:.2f} | "
              f"{r['cpu_seconds']:.2f} | {r['max_rss_kib'] // 1024} |")
verified = [r for r in runs if r["delaunay_violations"] is not None]
if verified:
    print("\n### Verified (`--verify`, N = 64)\n")
    print("| binary | field | geometry | triangles | verified | Delaunay violations | conforming "
          "| interface splits | max area / F | smallest unshielded angle deg |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for r in verified:
        print(f"| {r['binary']} | {r['field']} | {names.get(r['geometry'], r['geometry'])} | "
              f"{r['triangles']} | {r['verified']} | {r['delaunay_violations']} | "
              f"{r['conforming']} | {f(r['interface_splits'])} | {f(r['max_area_ratio'], '.6f')} | "
              f"{f(r['min_angle_unshielded_deg'], '.2f')} |")
if sys.argv[1] != sys.argv[2]:
    main = {(r["field"], r["geometry"], r["n"]): r
            for r in (json.loads(l) for l in list(open(sys.argv[2]))[1:])}
    print(f"\n### Over-refinement, {runs[0]['binary']} against main ({sys.argv[2]})\n")
    print("| field | geometry | N | over % then | subdomains then | over % main "
          "| subdomains main | graded path then / main |")
    print("|---|---|---|---|---|---|---|---|")
    for r in runs:
        m = main.get((r["field"], r["geometry"], r["n"]))
        if m:
            print(f"| {r['field']} | {names.get(r['geometry'], r['geometry'])} | {r['n']} | "
                  f"{r['over_refinement_pct']:.2f} | {r['subdomains']} | "
                  f"{m['over_refinement_pct']:.2f} | {m['subdomains']} | "
                  f"{f(r['graded_path'])} / {m['graded_path']} |")
PY
