#!/usr/bin/env bash
# Reproduces the two profiles in benchmarks/results/native-kernel.md ("Where the time goes" and
# "pdd-mesh's own passes over the mesh"): perf's share of the samples per function,
#   kernel:   bench_kernel pipe 1000000 20.7048 native (pdd::native::mesher once, about 1M
#             triangles, then bench_kernel's own statistics pass);
#   pdd-mesh: pdd-mesh examples/data/pipe.poly --max-area 1.3e-6 --kernel native --threads 1
#             --quiet (decoupled, automatic N; the checks and statistics included).
# Each run is pinned to CPU 0 and sampled at 2 kHz (perf record -F 2000, no call graphs: a
# function's own samples; what the compiler inlined counts in its caller).
#   pdd-mesh-old: the same pdd-mesh command with OLD_PDD_MESH, a pdd-mesh of another commit
#             (benchmarks/build_at_commit.sh), when it is given (not empty);
#   kernel-old: the kernel command with OLD_BENCH_KERNEL, a bench_kernel of another commit
#             (build_at_commit.sh COMMIT WORK_DIR bench_kernel), when it is given.
#   bash benchmarks/run_native_profiles.sh [BUILD_DIR] [OLD_PDD_MESH] [OLD_BENCH_KERNEL]
# Needs perf (Debian: linux-perf) and perf_event_paranoid <= 2. Raw data:
# benchmarks/results/native-kernel-profiles.jsonl (first line: the provenance, then one line per
# function over 0.5 % of a run's samples, with perf's full symbol); the tables are printed from
# it only.
set -euo pipefail
build=${1:-build/release}
old=${2:-}
old_bench=${3:-}
# shellcheck source=provenance.sh source-path=SCRIPTDIR
source "$(dirname "$0")/provenance.sh"
out=benchmarks/results/native-kernel-profiles.jsonl
provenance_json "bash benchmarks/run_native_profiles.sh $*" >"$out"
bench="$build/benchmarks/bench_kernel"
[ -x "$bench" ] || cmake --build "$build" --target bench_kernel >/dev/null
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
profile() { # PART COMMAND...
  local part=$1
  shift
  perf record -q -F 2000 -o "$tmp/$part.data" taskset -c 0 "$@" >/dev/null 2>"$tmp/err" ||
    { cat "$tmp/err" >&2; exit 1; }
  perf report -i "$tmp/$part.data" --stdio --no-children -F overhead,sample,sym -t ';' \
    2>/dev/null >"$tmp/$part.txt"
  python3 - "$out" "$part" "$tmp/$part.txt" "$*" <<'PY'
import json, re, sys
out, part, report, command = sys.argv[1:]
rows = []
for line in open(report):
    m = re.match(r"^\s*([\d.]+)%\s*;\s*(\d+)\s*;\[(.)\] (.*?)\s*$", line)
    if m:
        rows.append({"part": part, "command": command, "samples": int(m.group(2)),
                     "space": "kernel" if m.group(3) == "k" else "user",
                     "symbol": m.group(4)})
total = sum(r["samples"] for r in rows)
with open(out, "a") as f:
    for r in rows:
        r["share_pct"] = 100.0 * r["samples"] / total
        if r["share_pct"] >= 0.5:
            f.write(json.dumps({**r, "total_samples": total}) + "\n")
PY
}
profile kernel "$bench" pipe 1000000 20.7048 native
[ -z "$old_bench" ] || profile kernel-old "$old_bench" pipe 1000000 20.7048 native
pdd_mesh_args=(examples/data/pipe.poly --max-area 1.3e-6 --kernel native --threads 1 --quiet)
profile pdd-mesh "$build/examples/drivers/pdd-mesh" "${pdd_mesh_args[@]}"
[ -z "$old" ] || profile pdd-mesh-old "$old" "${pdd_mesh_args[@]}"
PYTHONPATH="$(dirname "${BASH_SOURCE[0]}")" python3 - "$out" <<'PY'
import re
import sys
from raw_data import read_raw_data

def strip_templates(s):
    out, depth = [], 0
    for c in s:
        depth += c == "<"
        if depth == 0:
            out.append(c)
        depth -= c == ">" and depth > 0
    return "".join(out)

def label(symbol):
    """A short name: template arguments and pdd's detail namespaces dropped; a task body
    (std::function's handler) named by the first pdd functions inside it."""
    if symbol.startswith("std::_Function_handler") and "pdd::" in symbol:
        inner = [label(n) for n in re.findall(r"pdd::[A-Za-z_:]+(?=[<(])", symbol)]
        inner = [n for n in dict.fromkeys(inner) if "accumulator" not in n and "sizing" not in n]
        return "a task body in " + " / ".join(inner[:3])
    name = strip_templates(symbol).split("(")[0]
    return re.sub(r"^pdd::(detail::)?(native_mesh::)?", "", name)

lines = read_raw_data(sys.argv[1], blank_line=False)
for part in dict.fromkeys(r["part"] for r in lines[1:]):
    rows = [r for r in lines[1:] if r["part"] == part]
    kernel_share = sum(r["share_pct"] for r in rows if r["space"] == "kernel")
    print(f"\n### `{part}`: {rows[0]['total_samples']} samples of `{rows[0]['command']}`\n")
    print("| share % | function |")
    print("|---|---|")
    shares = {}  # by label: the instantiations of one function summed
    for r in rows:
        if r["space"] == "user":
            shares[label(r["symbol"])] = shares.get(label(r["symbol"]), 0.0) + r["share_pct"]
    for name, share in sorted(shares.items(), key=lambda item: -item[1]):
        print(f"| {share:.1f} | `{name}` |")
    print(f"| {kernel_share:.1f} | the operating system's kernel (page faults, clearing pages, "
          "mapping; the rows over 0.5 % summed) |")
PY
