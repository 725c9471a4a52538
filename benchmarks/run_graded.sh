#!/usr/bin/env bash
# Reproduces benchmarks/results/graded.md (the dissertation's Table 7.1 on this machine): the
# bundled pipe (examples/data/pipe.poly: unit circle, 9 holes of radius 0.12, the inner one at
# the origin) with the area functions of Table 7.1, R1 = 1.425, R2 = 1.5:
#   d, d^2, d^4: F = s (a + d)^p, d = distance from the inner hole, a = 0.88/28, so
#                max F / min F = 29^p (1/29, 1/841, 1/707281 as in the thesis);
#   f_s:         F = s rho^3, rho = distance from the nearest hole centre (sources at the hole
#                centres, gradation about 1/72; the thesis' f_s has 1/77).
# s is chosen so that the expected mesh (integral of 1 / (0.656 F), Algorithm 7.2) has
# TRIANGLES triangles. Per field: pdd-mesh --subdomains 2 (at least 2: Algorithm 7.1's
# conditions decide the count, as in the thesis; the automatic plan would fall back to the
# monolithic kernel where the separators carry more than 5% of the triangles, see
# generate_options::max_split_point_fraction) on 1 thread with --compare-monolithic (the same
# kernel on the whole domain with the same F), then on 2 threads.
#   bash benchmarks/run_graded.sh [BUILD_DIR] [TRIANGLES] [FIELDS] [OUT.jsonl]
# Defaults: build/release, 5e6, "d d2 d4 fs". KERNEL=cgal|native picks the kernel of every run
# (default cgal); RUNS lists the thread counts (default "1 2"; the first one also runs the
# monolithic comparison). Writes JSON lines to
# benchmarks/results/graded-<TRIANGLES>.jsonl and prints the markdown table.
set -euo pipefail
build=${1:-build/release}
target=${2:-5000000}
fields=${3:-"d d2 d4 fs"}
kernel=${KERNEL:-cgal}
runs=${RUNS:-"1 2"}
exe="$build/examples/drivers/pdd-mesh"
cmake --build "$build" --target pdd-mesh >/dev/null
out=${4:-"benchmarks/results/graded-${target}.jsonl"}
: > "$out"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
expr_of() { # field scale
  local d="(0.88/28+max(0,sqrt(x^2+y^2)-0.12))"
  # the squares of sums as products: muParser turns only a variable's power (x^2) into a
  # product and evaluates (x+0.5)^2 with pow(), which made f_s 2.1x slower to evaluate (245
  # against 115 ns) and had been 58 % of its run; the values are the same
  local px="(x+0.5)*(x+0.5)" mx="(x-0.5)*(x-0.5)" py="(y+0.5)*(y+0.5)" my="(y-0.5)*(y-0.5)"
  local rho="min($px+$py,x^2+$py,$mx+$py,$px+y^2,x^2+y^2,$mx+y^2,$px+$my,x^2+$my,$mx+$my)"
  case "$1" in
    d) echo "$2*$d" ;;
    d2) echo "$2*$d^2" ;;
    d4) echo "$2*$d^4" ;;
    fs) echo "$2*max(0.0144,$rho)^1.5" ;;
  esac
}
for f in $fields; do
  # the scale s: integral of 1 / F at s = 1 by the midpoint rule on a fine grid over the pipe
  s=$(/usr/bin/python3 - "$f" "$target" <<'PY'
import sys, numpy as np
f, target = sys.argv[1], float(sys.argv[2])
n = 2000
x = (np.arange(n) + 0.5) / n * 2 - 1
X, Y = np.meshgrid(x, x)
inside = X**2 + Y**2 < 1
for i in (-0.5, 0, 0.5):
    for j in (-0.5, 0, 0.5):
        inside &= (X - i)**2 + (Y - j)**2 > 0.12**2
d = 0.88 / 28 + np.maximum(0, np.sqrt(X**2 + Y**2) - 0.12)
rho2 = np.min([(X - i)**2 + (Y - j)**2 for i in (-0.5, 0, 0.5) for j in (-0.5, 0, 0.5)], axis=0)
F = {'d': d, 'd2': d**2, 'd4': d**4, 'fs': rho2**1.5}[f]
integral = np.sum(1 / F[inside]) * (2 / n)**2
print('%.17g' % (integral / (0.656 * target)))
PY
)
  e=$(expr_of "$f" "$s")
  run() { # threads [extra options]
    "$exe" examples/data/pipe.poly --sizing "$e" --r1 1.425 --r2 1.5 --subdomains 2 --threads "$1" \
      --kernel "$kernel" --stats "$tmp/s.json" -q "${@:2}"
    /usr/bin/python3 -c "
import json; j = json.load(open('$tmp/s.json')); j['field'] = '$f'; j['expression'] = '''$e'''
j.pop('subdomain_k', None); j.pop('angle_histogram_deg', None); print(json.dumps(j))" >> "$out"
    echo "$f threads=$1 done" >&2
  }
  first=1
  for t in $runs; do
    if [ "$first" = 1 ]; then run "$t" --compare-monolithic; else run "$t"; fi
    first=0
  done
done
/usr/bin/python3 - "$out" <<'PY'
import json, sys
rows = [json.loads(l) for l in open(sys.argv[1])]
print('kernel:', rows[0]['kernel'] if rows else '-')
print('| F | gradation | subdomains | r1_max | r2_max | lowered k | monolithic triangles | decoupled triangles | over-refinement % | monolithic s | decoupled s, 1 thread | 2 threads | speed-up vs monolithic (2 threads) | speed-up 1 -> 2 threads |')
print('|---|---|---|---|---|---|---|---|---|---|---|---|---|---|')
def total(field, threads):
    r = next((r for r in rows if r['field'] == field and r['threads'] == threads), None)
    return r['timings']['total'] if r else None
fmt = lambda v: '-' if v is None else '%.1f' % v
for one in rows:
    if 'over_refinement_pct' not in one:
        continue
    mono_t = one['timings']['monolithic_comparison']
    t1, t2 = total(one['field'], 1), total(one['field'], 2)
    mono = one['monolithic_triangles']
    print('| %s | 1/%.0f | %d | %.3f | %.3f | %d | %.0f | %d | %.2f | %.1f | %s | %s | %s | %s |' % (
        one['field'], one['gradation'], one['subdomains'], one.get('r1_max', 0), one.get('r2_max', 0),
        one.get('lowered_k', 0), mono, one['triangles'], one['over_refinement_pct'], mono_t, fmt(t1),
        fmt(t2), '-' if t2 is None else '%.2f' % (mono_t / t2),
        '-' if None in (t1, t2) else '%.2f' % (t1 / t2)))
PY
