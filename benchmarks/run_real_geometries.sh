#!/usr/bin/env bash
# Reproduces benchmarks/results/real-geometries.md (issue 17): real geometries with tiny features
# and small angles under a uniform --max-area for about TRIANGLES triangles: the monolithic kernel
# (--subdomains 1, 1 thread) vs automatic pdd-mesh (no --subdomains: the geometric path where a
# feature is smaller than the mesh) at 1 and 2 threads, and Triangle 1.6 (-pq20.7a<A>QNEP: no
# output file, as pdd-mesh writes none here) on the same input and bound. One process per run,
# CPU seconds (user + sys) from /usr/bin/time. One-thread runs (the monolithic kernel, automatic at
# 1 thread, Triangle) are pinned to CPU 0 and two-thread runs to CPUs 0 and 1 (taskset), so one
# thread is compared with one thread. The first line of the raw data is the run's provenance
# (benchmarks/provenance.sh: command, commit, machine, date).
#   nice -n 10 bash benchmarks/run_real_geometries.sh [BUILD_DIR] [TRIANGLES] [GEOMETRIES] [TRIANGLE_EXE]
# Defaults: build/release, 2e6, "bahamas_islands lake_superior texas mesh2d_airfoil_3element"
# from ../shared/data, /tmp/tri/triangle (build it with ../shared/anchors/triangle/build.sh
# /tmp/tri). Writes JSON lines to benchmarks/results/real-geometries-<TRIANGLES>.jsonl and
# prints the markdown table.
set -euo pipefail
build=${1:-build/release}
target=${2:-2000000}
geometries=${3:-"bahamas_islands lake_superior texas mesh2d_airfoil_3element"}
triangle=${4:-/tmp/tri/triangle}
data=../shared/data
exe="$build/examples/drivers/pdd-mesh"
out="benchmarks/results/real-geometries-${target}.jsonl"
source "$(dirname "$0")/provenance.sh"
provenance_json "bash benchmarks/run_real_geometries.sh $*" > "$out"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cpus() { [ "$1" = 1 ] && echo 0 || echo "0-$(($1 - 1))"; } # the CPUs a run of $1 threads gets
for g in $geometries; do
  poly="$data/$g.poly"
  [ -f "$poly" ] || { echo "skip $g: $poly is absent" >&2; continue; }
  # the area bound for about $target triangles (mean triangle area 0.656 A), as a plain
  # decimal: Triangle's -a does not read scientific notation
  "$exe" "$poly" --subdomains 1 --stats "$tmp/a.json" -q
  area=$(/usr/bin/python3 -c "
import json; print('%.12f' % (json.load(open('$tmp/a.json'))['area_domain'] / ($target * 0.656)))")
  run() { # label threads [extra options]
    /usr/bin/time -f "%U %S %e %M" -o "$tmp/time" taskset -c "$(cpus "$2")" \
      "$exe" "$poly" --max-area "$area" --threads "$2" --stats "$tmp/s.json" -q "${@:3}"
    /usr/bin/python3 -c "
import json; j = json.load(open('$tmp/s.json')); u, s, e, m = open('$tmp/time').read().split()[-4:]
j.pop('angle_histogram_deg', None); j.pop('subdomain_k', None)
j.update(domain='$g', label='$1', cpu_seconds=float(u) + float(s), wall_seconds=float(e),
         max_rss_kib=int(m), max_area='$area')
print(json.dumps(j))" >> "$out"
    echo "$g $1 done" >&2
  }
  run monolithic 1 --subdomains 1
  run automatic-1 1
  run automatic-2 2
  if [ -x "$triangle" ]; then
    cp "$poly" "$tmp/in.poly"
    # the same work as pdd-mesh here, which writes no file: -Q and -NEP (no .node, .ele, .poly);
    # the count from a second, untimed run that prints Triangle's statistics
    /usr/bin/time -f "%U %S %e %M" -o "$tmp/time" taskset -c 0 "$triangle" -pq20.7a"$area"QNEP "$tmp/in.poly"
    "$triangle" -pq20.7a"$area"NEP "$tmp/in.poly" | sed -n 's/^ *Mesh triangles: *//p' >"$tmp/count"
    /usr/bin/python3 -c "
import json; u, s, e, m = open('$tmp/time').read().split()[-4:]
n = int(open('$tmp/count').read())
print(json.dumps(dict(domain='$g', label='triangle', triangles=n, cpu_seconds=float(u) + float(s),
                      wall_seconds=float(e), max_rss_kib=int(m), max_area='$area')))" >> "$out"
    rm -f "$tmp"/in.1.*
  fi
done
/usr/bin/python3 - "$out" <<'PY'
import json, sys
lines = [json.loads(l) for l in open(sys.argv[1])]
p = lines[0].get("provenance", {})
print("Measured %s at commit `%s` on %s (load average at start %s); command: `%s`\n" % (
    p.get("date"), p.get("commit"), p.get("machine"), p.get("load_average_at_start"),
    p.get("command")))
rows = [r for r in lines if "provenance" not in r]
print("| domain | run | triangles | over-refinement | subdomains | path | rounds / est. over-ref. | CPU s | wall s | vs monolithic (CPU, wall) | Triangle's wall / this wall |")
print("|---|---|---|---|---|---|---|---|---|---|---|")
for d in dict.fromkeys(r["domain"] for r in rows):
    mono = next(r for r in rows if r["domain"] == d and r["label"] == "monolithic")
    tri = next((r for r in rows if r["domain"] == d and r["label"] == "triangle"), None)
    for r in (r for r in rows if r["domain"] == d):
        over = 100.0 * (r["triangles"] / mono["triangles"] - 1.0)
        est = r.get("estimated_over_refinement") or []
        rounds = "%d / %s" % (r.get("sizing_rounds", 0), ", ".join("%.3g %%" % (100 * x) for x in est)) if est else "-"
        versus = "%.2fx" % (tri["wall_seconds"] / r["wall_seconds"]) if tri else "-"
        print("| %s | %s | %d | %+.2f %% | %s | %s | %s | %.2f | %.2f | %.2fx, %.2fx | %s |" % (
            d, r["label"], r["triangles"], over, r.get("subdomains", "-"), r.get("path", "-"), rounds,
            r["cpu_seconds"], r["wall_seconds"], mono["cpu_seconds"] / r["cpu_seconds"],
            mono["wall_seconds"] / r["wall_seconds"], versus))
PY
