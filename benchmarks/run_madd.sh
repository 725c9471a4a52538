#!/usr/bin/env bash
# Reproduces benchmarks/results/madd.md: MADD (1 and 2 threads) against METIS on a background
# Delaunay mesh (~120 triangles per part) for the key, the pipe and bahamas_islands.poly (skipped
# when the shared data folder is absent), N = 16, 64, 256, 1024. Every run is one process
# printing one JSON line (benchmarks/bench_madd.cpp). Raw data: benchmarks/results/madd.jsonl
# (first line: the provenance, then the runs' lines, then one line with the other work the
# machine did during the runs); the markdown table is printed from it only. Each run is timed 5
# times, the fastest counts. bench_madd is built (cmake --build) only when it is missing.
#   bash benchmarks/run_madd.sh [BUILD_DIR [DATA_DIR]]   (defaults build/release, ../shared/data)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/release}
data=${2:-../shared/data}
if [[ ! -f "$build/CMakeCache.txt" ]]; then
  cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DPDD_BUILD_BENCHMARKS=ON >/dev/null
fi
bench="$build/benchmarks/bench_madd"
[ -x "$bench" ] || cmake --build "$build" --target bench_madd -j1 >/dev/null
# shellcheck source=provenance.sh source-path=SCRIPTDIR
source benchmarks/provenance.sh
out=benchmarks/results/madd.jsonl
provenance_json "bash benchmarks/run_madd.sh $*" >"$out"
repeats=5
domains=(key pipe)
if [[ -f "$data/bahamas_islands.poly" ]]; then
  domains+=("$data/bahamas_islands.poly")
else
  echo "note: $data/bahamas_islands.poly not found, bahamas skipped" >&2
fi
# CPU time of the whole machine (/proc/stat) and of this script's children (/proc/$$/stat),
# in clock ticks, to state how busy the other users kept the machine during the runs.
machine_busy() { awk '/^cpu /{print $2+$3+$4+$7+$8+$9}' /proc/stat; }
own_busy() { awk '{print $16+$17}' "/proc/$$/stat"; }
busy0=$(machine_busy); own0=$(own_busy); start=$(date +%s.%N)
for d in "${domains[@]}"; do
  for n in 16 64 256 1024; do
    "$bench" "$d" madd "$n" 1 "$repeats"
    "$bench" "$d" madd "$n" 2 "$repeats"
    "$bench" "$d" metis "$n" 1 "$repeats"
  done
done >>"$out"
python3 - "$out" "$busy0" "$(machine_busy)" "$own0" "$(own_busy)" "$start" "$(date +%s.%N)" \
  "$(getconf CLK_TCK)" "$repeats" <<'EOF'
import json, sys
out, b0, b1, o0, o1, t0, t1, hz, repeats = sys.argv[1:]
seconds = float(t1) - float(t0)
others = ((float(b1) - float(b0)) - (float(o1) - float(o0))) / float(hz) / seconds
open(out, "a").write(json.dumps({"machine_load": {"other_work_cores": others,
                                                  "seconds": seconds,
                                                  "repeats": int(repeats)}}) + "\n")
EOF
PYTHONPATH="$(dirname "${BASH_SOURCE[0]}")" python3 - "$out" <<'EOF'
import json, sys
from raw_data import read_raw_data
lines = read_raw_data(sys.argv[1])
load = next(l["machine_load"] for l in lines if "machine_load" in l)
print("Shared machine: %.2f cores busy with other work over %.0f s; fastest of %d per run.\n" % (
    load["other_work_cores"], load["seconds"], load["repeats"]))
runs = [l for l in lines[1:] if "method" in l]
key = lambda r: (r["domain"], r["N"])
madd1 = {key(r): r for r in runs if r["method"] == "madd" and r["threads"] == 1}
madd2 = {key(r): r for r in runs if r["method"] == "madd" and r["threads"] == 2}
metis = {key(r): r for r in runs if r["method"] == "metis"}
print("| domain | N | method | time 1 thr (s) | time 2 thr (s) | min angle | median | 90% | "
      "junction angles < 60 | min incl. bends | max/mean area | sep. length / subdomain | "
      "sep. / sqrt(mean area) | valid |")
print("|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|")
for k in madd1:
    a, b, m = madd1[k], madd2.get(k), metis.get(k)
    same = b is not None and b["digest"] == a["digest"]
    t2 = f'{b["time_s"]:.3f}' if b else "-"
    ok = ("yes" if a["valid"] else "NO") + (", same for 2 thr" if same else ", 2 thr DIFFERS")
    rows = [(a, "MADD", f'{a["time_s"]:.3f}', t2, ok)]
    if m:
        mt = f'{m["time_s"]:.3f} ({m["mesh_s"]:.3f} mesh, {m["triangles"]} tri)'
        mok = "connected" if m["valid"] else f'{m["disconnected_parts"]} parts disconnected'
        rows.append((m, "METIS", mt, "-", mok))
    for r, name, t1, tt2, v in rows:
        print(f'| {k[0]} | {k[1]} | {name} | {t1} | {tt2} | {r["min_angle"]:.2f} | '
              f'{r["median_angle"]:.1f} | {r["q90_angle"]:.1f} | {r["below_60"]} of '
              f'{r["junction_corners"]} | {r["min_angle_all"]:.2f} | {r["max_over_mean"]:.3f} | '
              f'{r["sep_len_per_subdomain"]:.4g} | {r["sep_len_rel"]:.2f} | {v} |')
EOF
