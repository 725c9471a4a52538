#!/usr/bin/env bash
# pdd-mesh and Triangle 1.6 side by side on one .poly, the same work on both sides (issue 37
# item 5): pdd-mesh writes no mesh (its --stats JSON only) and Triangle runs with -QNEP (no
# .node, .ele, .poly; its triangle count from a second, untimed run that prints its statistics).
# One-thread runs are pinned to CPU 0, Triangle's included, and two-thread runs to CPUs 0 and 1
# (taskset), so one thread is compared with one thread. Sourced by run_faulted.sh,
# run_pinched.sh and run_dense_features.sh:
#   side_by_side_begin OUT.jsonl "COMMAND"           raw data file, its first line the provenance
#   pdd_timed OUT.jsonl EXE POLY LABEL REP THREADS [pdd-mesh options...]
#   triangle_timed OUT.jsonl EXE POLY REP SWITCHES   (SWITCHES without Q, N, E, P)
#   side_by_side_runs OUT.jsonl EXE POLY AREA [TRIANGLE_EXE]   the standard runs of one input
#   side_by_side_table OUT.jsonl                     the Markdown table, from the raw data only
source "$(dirname "${BASH_SOURCE[0]}")/provenance.sh"

side_by_side_begin() {
  provenance_json "$2" >"$1"
}

side_by_side_cpus() { [ "$1" = 1 ] && echo 0 || echo "0-$(($1 - 1))"; }

# appends one run: label, rep, threads, triangles, subdomains, path, wall, CPU (user + sys), RSS
side_by_side_record() { # OUT LABEL REP THREADS TIME_FILE TRIANGLES [STATS_JSON]
  python3 - "$@" <<'EOF'
import json, sys
out, label, rep, threads, time_file, triangles = sys.argv[1:7]
stats = json.load(open(sys.argv[7])) if len(sys.argv) > 7 else {}
user, system, wall, rss = open(time_file).read().split()[-4:]
line = {"label": label, "rep": int(rep), "threads": int(threads), "triangles": int(triangles),
        "subdomains": stats.get("subdomains", 1), "path": stats.get("path", "-"),
        "shielded_triangles": stats.get("shielded_triangles"),
        "wall_seconds": float(wall), "cpu_seconds": float(user) + float(system),
        "max_rss_kib": int(rss)}
with open(out, "a") as f:
    f.write(json.dumps(line) + "\n")
EOF
}

pdd_timed() { # OUT EXE POLY LABEL REP THREADS [options...]
  local out=$1 exe=$2 poly=$3 label=$4 rep=$5 threads=$6
  local tmp
  tmp=$(mktemp -d)
  /usr/bin/time -f "%U %S %e %M" -o "$tmp/time" taskset -c "$(side_by_side_cpus "$threads")" \
    "$exe" "$poly" --threads "$threads" "${@:7}" --stats "$tmp/stats.json" -q
  side_by_side_record "$out" "$label" "$rep" "$threads" "$tmp/time" \
    "$(python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['triangles'])" \
      "$tmp/stats.json")" "$tmp/stats.json"
  rm -rf "$tmp"
}

triangle_timed() { # OUT EXE POLY REP SWITCHES
  local out=$1 exe=$2 poly=$3 rep=$4 switches=$5
  local tmp
  tmp=$(mktemp -d)
  cp "$poly" "$tmp/in.poly"
  /usr/bin/time -f "%U %S %e %M" -o "$tmp/time" taskset -c 0 "$exe" -"$switches"QNEP "$tmp/in.poly"
  "$exe" -"$switches"NEP "$tmp/in.poly" | sed -n 's/^ *Mesh triangles: *//p' >"$tmp/count"
  side_by_side_record "$out" "Triangle 1.6 -$switches" "$rep" 1 "$tmp/time" "$(cat "$tmp/count")"
  rm -rf "$tmp"
}

# The standard runs of one input, REPS (default 2) times: pdd-mesh's automatic plan with each of
# KERNELS (default "cgal native") on 2 threads and on 1, pdd-mesh --subdomains 1 (the default
# kernel: the domain meshed whole), and Triangle -pq20.7a<AREA> when TRIANGLE_EXE is given.
side_by_side_runs() { # OUT EXE POLY AREA [TRIANGLE_EXE]
  local out=$1 exe=$2 poly=$3 area=$4 triangle=${5:-} rep kernel threads decimal
  # Triangle's -a takes no exponent
  decimal=$(python3 -c "import sys; print(format(float(sys.argv[1]), 'f').rstrip('0'))" "$area")
  for rep in $(seq "${REPS:-2}"); do
    for kernel in ${KERNELS:-cgal native}; do
      for threads in 2 1; do
        pdd_timed "$out" "$exe" "$poly" "pdd-mesh --kernel $kernel, automatic" "$rep" "$threads" \
          --max-area "$area" --kernel "$kernel"
      done
    done
    pdd_timed "$out" "$exe" "$poly" "pdd-mesh --subdomains 1" "$rep" 1 --max-area "$area" \
      --subdomains 1
    if [ -n "$triangle" ]; then triangle_timed "$out" "$triangle" "$poly" "$rep" "pq20.7a$decimal"; fi
  done
}

side_by_side_table() { # OUT
  PYTHONPATH="$(dirname "${BASH_SOURCE[0]}")" python3 - "$1" <<'EOF'
import json, sys
from raw_data import read_raw_data
lines = read_raw_data(sys.argv[1])
runs = lines[1:]
print("| rep | run | threads | triangles | subdomains | path | wall s | CPU s | max RSS MiB "
      "| Triangle's wall / this wall |")
print("|---|---|---|---|---|---|---|---|---|---|")
for r in runs:
    tri = next((t for t in runs if t["rep"] == r["rep"] and t["label"].startswith("Triangle")),
               None)
    versus = "%.2fx" % (tri["wall_seconds"] / r["wall_seconds"]) if tri else "-"
    print("| %d | %s | %d | %d | %s | %s | %.2f | %.2f | %d | %s |" % (
        r["rep"], r["label"], r["threads"], r["triangles"], r["subdomains"], r["path"],
        r["wall_seconds"], r["cpu_seconds"], r["max_rss_kib"] // 1024, versus))
EOF
}
