#!/usr/bin/env bash
# Reproduces the "100 million triangles, binary output, and pdd-verify on it" section of
# benchmarks/results/scale.md (and, with MAX_AREA 4.18e-9 and vtu, the billion-triangle one):
# pdd-mesh on the bundled pipe with --output-per-subdomain on 2 threads, then pdd-verify on what
# it wrote, both nice'd and timed with /usr/bin/time -v; the bytes on disk (du -sb); the output is
# deleted afterwards. Raw data: benchmarks/results/scale-large-FORMAT-MAX_AREA.jsonl (first line:
# the provenance, then one line for pdd-mesh and one for pdd-verify, with their --stats JSON,
# and one for the same pdd-mesh run with --verify, which checks every piece in memory before
# writing it: the cost of a verified run against the unverified one plus pdd-verify); the table
# is printed from it only.
#   bash benchmarks/run_large_output.sh [BUILD_DIR] [MAX_AREA] [FORMAT] [OUT_PARENT]
# Defaults: build/release, 4.18e-8 (about 100 M triangles: 1.4 GB binary, about 170 s of CPU),
# binary, /tmp (the output folder is made there and removed).
set -euo pipefail
build=${1:-build/release}
area=${2:-4.18e-8}
format=${3:-binary}
parent=${4:-/tmp}
input=examples/data/pipe.poly
# shellcheck source=provenance.sh source-path=SCRIPTDIR
source "$(dirname "$0")/provenance.sh"
out=benchmarks/results/scale-large-$format-$area.jsonl
provenance_json "bash benchmarks/run_large_output.sh ${*@Q}" >"$out"
dir=$(mktemp -d -p "$parent")
trap 'rm -rf "$dir"' EXIT
index=$([ "$format" = binary ] && echo mesh.pddi || echo mesh.pvtu)
record() { # PROGRAM TIME_FILE STATS_JSON [BYTES FILES]
  python3 - "$out" "$@" <<'EOF'
import json, sys
out, program, time_file, stats = sys.argv[1:5]
fields = {}
for l in open(time_file):
    k, _, v = l.strip().rpartition(": ")
    fields[k] = v
line = {"program": program, "user_seconds": float(fields["User time (seconds)"]),
        "system_seconds": float(fields["System time (seconds)"]),
        "wall_clock": fields["Elapsed (wall clock) time (h:mm:ss or m:ss)"],
        "max_rss_kib": int(fields["Maximum resident set size (kbytes)"]),
        "stats": json.load(open(stats))}
w = [float(x) for x in line["wall_clock"].split(":")]
line["wall_seconds"] = sum(x * 60 ** i for i, x in enumerate(reversed(w)))
if len(sys.argv) > 5:
    line["bytes_on_disk"], line["files"] = int(sys.argv[5]), int(sys.argv[6])
open(out, "a").write(json.dumps(line) + "\n")
EOF
}
/usr/bin/time -v -o "$dir/mesh.time" nice -n 10 "$build/examples/drivers/pdd-mesh" "$input" \
  --max-area "$area" --threads 2 --format "$format" --output-per-subdomain "$dir/out" \
  --stats "$dir/mesh.json" -q
record pdd-mesh "$dir/mesh.time" "$dir/mesh.json" "$(du -sb "$dir/out" | cut -f1)" \
  "$(find "$dir/out" -type f | wc -l)"
/usr/bin/time -v -o "$dir/verify.time" nice -n 10 "$build/examples/drivers/pdd-verify" \
  "$dir/out/$index" "$input" --max-area "$area" --stats "$dir/verify.json" -q
record pdd-verify "$dir/verify.time" "$dir/verify.json"
rm -rf "$dir/out"
/usr/bin/time -v -o "$dir/mesh-verify.time" nice -n 10 "$build/examples/drivers/pdd-mesh" \
  "$input" --max-area "$area" --threads 2 --format "$format" --output-per-subdomain "$dir/out" \
  --verify --stats "$dir/mesh-verify.json" -q
record "pdd-mesh --verify" "$dir/mesh-verify.time" "$dir/mesh-verify.json"
PYTHONPATH="$(dirname "${BASH_SOURCE[0]}")" python3 - "$out" <<'EOF'
import json, sys
from raw_data import read_raw_data
lines = read_raw_data(sys.argv[1])
m, v = lines[1], lines[2]
s, t = m["stats"], m["stats"]["timings"]
cpu = lambda r: r["user_seconds"] + r["system_seconds"]
print("| what | value |\n|---|---|")
print(f"| triangles | {s['triangles']:,} (estimate {s['estimated_triangles']:,.0f}) in "
      f"{s['subdomains']:,} subdomains |")
print(f"| pdd-mesh wall / CPU (user + sys) | {m['wall_seconds']:.1f} s / {cpu(m):.1f} s "
      f"({m['user_seconds']:.1f} + {m['system_seconds']:.1f}): "
      f"{1e6 * cpu(m) / s['triangles']:.2f} CPU us per triangle |")
print(f"| pdd-mesh stages | read {t['read']:.2f} s, MADD {t['decompose']:.1f} s, decoupling path "
      f"{t['decouple']:.2f} s, meshing and writing {t['mesh']:.1f} s |")
print(f"| pdd-mesh peak RSS | {m['max_rss_kib']:,} KB ({m['max_rss_kib'] / 1024:.1f} MiB) |")
print(f"| quality | min angle {s['min_angle_deg']:.2f} deg, {s['shielded_triangles']} shielded "
      "triangles |")
print(f"| on disk | {m['bytes_on_disk']:,} bytes (`du -sb`, {m['files']:,} files): "
      f"{m['bytes_on_disk'] / s['triangles']:.2f} bytes per triangle |")
vs = v["stats"]
print(f"| pdd-verify wall / CPU | {v['wall_seconds']:.1f} s / {cpu(v):.1f} s "
      f"({v['user_seconds']:.1f} + {v['system_seconds']:.1f}): "
      f"{1e6 * cpu(v) / vs['triangles']:.2f} CPU us per triangle; "
      f"{'**passed**' if vs['ok'] else '**FAILED**'} |")
print(f"| pdd-verify peak RSS | {v['max_rss_kib']:,} KB ({v['max_rss_kib'] / 1024:.1f} MiB) |")
print(f"| pdd-verify checked | {vs['pieces']:,} pieces, {vs['triangles']:,} triangles, "
      f"{vs['vertices']:,} vertices; {vs['interface_edges']:,} interface edges; "
      f"{vs['domain_boundary_edges']:,} domain boundary edges; at most {vs['max_open_edges']:,} "
      f"open boundary edges; largest piece {vs['largest_piece_triangles']:,} triangles; area "
      f"{vs['area_mesh']!r} against the domain's {vs['area_domain']!r}; violations: Delaunay "
      f"{vs['delaunay_violations']}, interface Delaunay {vs['interface_delaunay_violations']}, "
      f"quality {vs['quality_violations']}, area {vs['area_violations']}, unmatched edges "
      f"{vs['unmatched_edges']} |")
if len(lines) > 3:
    mv = lines[3]
    sv = mv["stats"]
    print(f"| pdd-mesh --verify wall / CPU | {mv['wall_seconds']:.1f} s / {cpu(mv):.1f} s: "
          f"{mv['wall_seconds'] / m['wall_seconds']:.2f}x the unverified run's wall time, "
          f"{(mv['wall_seconds']) / (m['wall_seconds'] + v['wall_seconds']):.2f}x pdd-mesh + "
          f"pdd-verify; the checks {sv['timings']['verify']:.1f} s summed over the threads; "
          f"{sv['interface_edges_verified']:,} interface edges; "
          f"{'**passed**' if sv['conforming'] else '**FAILED**'} |")
    print(f"| pdd-mesh --verify peak RSS | {mv['max_rss_kib']:,} KB "
          f"({mv['max_rss_kib'] / 1024:.1f} MiB) |")
EOF
