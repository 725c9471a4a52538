#!/usr/bin/env bash
# Reproduces benchmarks/results/graded-shields.md: the over-refinement of the decoupled mesh
# against the monolithic mesh (same CGAL kernel, same field: pdd-mesh --compare-monolithic) on the
# ../shared/data geometries with the graded path's shields (dissertation 8.3, Theorem 26), for
# N automatic and N = 64, on 2 threads. Run it once with the pdd-mesh of main (before) and once
# with this branch's (after).
#   bash benchmarks/run_graded_shields.sh PDD_MESH TAG FIELD [OUT_DIR]
# FIELD: graded (F = a (1 + 30 u^2), u = x across the bounding box), steep (a (1 + 999 u^2)) or
# const (F = a); a is set per geometry for about 0.2M-1M triangles. Prints one line per run and
# writes the --stats JSON to OUT_DIR (default /tmp/graded-shields).
set -euo pipefail
bin=$1
tag=$2
field=$3
out=${4:-/tmp/graded-shields}
mkdir -p "$out"
data=$(dirname "$0")/../../shared/data
declare -A X=([lake_superior]=0.1 [texas]=-10664 [mesh2d_airfoil_3element]=0 [guitar]=0.5)
declare -A W=([lake_superior]=0.8 [texas]=1313 [mesh2d_airfoil_3element]=1 [guitar]=35.75)
case $field in
graded) declare -A A=([lake_superior]=5.5e-8 [texas]=0.275 [mesh2d_airfoil_3element]=5.2e-7 [guitar]=1.74e-4) g=30 ;;
steep) declare -A A=([lake_superior]=1.06e-8 [texas]=0.0528 [mesh2d_airfoil_3element]=1.0e-7 [guitar]=3.34e-5) g=999 ;;
const) declare -A A=([lake_superior]=2.17e-7 [texas]=1.08 [mesh2d_airfoil_3element]=2.05e-6 [guitar]=6.9e-4) g=0 ;;
*) echo "FIELD: graded, steep or const" >&2; exit 1 ;;
esac
for f in lake_superior texas mesh2d_airfoil_3element guitar; do
  e="${A[$f]}"
  [ "$g" != 0 ] && e="${A[$f]}*(1+$g*((x-(${X[$f]}))/${W[$f]})^2)"
  for n in auto 64; do
    sub=()
    [ "$n" = 64 ] && sub=(--subdomains 64)
    json="$out/${tag}_${field}_${f}_${n}.json"
    nice -n 10 "$bin" "$data/$f.poly" --sizing "$e" "${sub[@]}" --threads 2 --compare-monolithic \
      --stats "$json" -q
    python3 - "$json" "$tag" "$f" "$n" <<'PY'
import json, sys
path, tag, f, n = sys.argv[1:]
j = json.load(open(path))
t = j["timings"]
print(tag, f, n, "triangles", j["triangles"], "monolithic", j["monolithic_triangles"],
      "over%", round(j["over_refinement_pct"], 2), "subdomains", j["subdomains"],
      "graded_path", j.get("graded_path"), "graded_fallback", repr(j.get("graded_fallback", "")),
      "shielded", j["shielded_triangles"], "mesh_s", round(t["mesh"], 2),
      "monolithic_s", round(t["monolithic_comparison"], 2), flush=True)
PY
  done
done
