#!/usr/bin/env bash
# Reproduces benchmarks/results/compile-times.md (issue 34): what it costs to compile a program
# that uses pdd, one file at a time with GCC -O2 on an otherwise idle machine (/usr/bin/time:
# wall and CPU seconds, peak memory), against a file that uses CGAL's kernel alone:
#   kernel    CGAL's Epick kernel and one orientation test (the yardstick)
#   generate  <pdd/generate.hpp> + <pdd/io/poly.hpp>: reads a .poly, calls pdd::generate
#   umbrella  the same calls through <pdd/pdd.hpp> (every public header)
# each against libpdd (compiled), header-only (-DPDD_HEADER_ONLY=1: every template compiled in
# the file, as before libpdd) and, with BEFORE_REV, the headers of that commit (a temporary git
# worktree). Also the preprocessed lines of the main headers. Several minutes in all.
# Raw data: benchmarks/results/compile-times.jsonl (first line: the provenance).
#   bash benchmarks/run_compile_times.sh [BUILD_DIR] [BEFORE_REV]
set -euo pipefail
build=${1:-build/release}
before=${2:-}
# shellcheck source=provenance.sh source-path=SCRIPTDIR
source "$(dirname "$0")/provenance.sh"
out=benchmarks/results/compile-times.jsonl
provenance_json "bash benchmarks/run_compile_times.sh $*" >"$out"
tmp=$(mktemp -d)
cleanup() {
  [ -z "$before" ] || git worktree remove --force "$tmp/before" 2>/dev/null || true
  rm -rf "$tmp"
}
trap cleanup EXIT
flags=(-O2 -std=gnu++20 -frounding-math -DBOOST_ALL_NO_LIB -DCGAL_USE_GMPXX=1)
grep -q "PDD_HAVE_METIS" "$build/build.ninja" && flags+=(-DPDD_HAVE_METIS=1)

cat >"$tmp/kernel.cpp" <<'EOF'
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <cstdio>
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
int main(int argc, char**) {
  const K::Point_2 a(0, 0), b(1, 0), c(0, argc);
  std::printf("%d\n", static_cast<int>(CGAL::orientation(a, b, c)));
}
EOF
body='int main(int argc, char** argv) {
  if (argc != 2) return 2;
  const pdd::pslg domain = pdd::read_poly(argv[1]);
  pdd::generate_options options;
  options.criteria.max_area = 1e-3;
  const pdd::generate_result r = pdd::generate(domain, options);
  std::printf("%zu triangles\n", r.mesh.triangles.size());
}'
printf '#include <pdd/generate.hpp>\n#include <pdd/io/poly.hpp>\n#include <cstdio>\n%s\n' \
  "$body" >"$tmp/generate.cpp"
printf '#include <pdd/pdd.hpp>\n#include <cstdio>\n%s\n' "$body" >"$tmp/umbrella.cpp"

record() { # file mode include_dir [extra flags...]
  local file=$1 mode=$2 inc=$3
  shift 3
  /usr/bin/time -f "%e %U %S %M" -o "$tmp/time" g++ "${flags[@]}" "$@" -I"$inc" \
    -I"$build/include" -c "$tmp/$file.cpp" -o "$tmp/$file.o" 2>"$tmp/log" ||
    { cat "$tmp/log" >&2; exit 1; }
  read -r wall user sys rss <"$tmp/time"
  python3 -c 'import json, sys; f, m, w, u, s, r = sys.argv[1:]; print(json.dumps({"file": f, "mode": m, "wall_s": float(w), "cpu_s": round(float(u) + float(s), 2), "peak_mib": round(int(r) / 1024)}))' \
    "$file" "$mode" "$wall" "$user" "$sys" "$rss" | tee -a "$out"
}
lines() { # header mode include_dir
  local n
  n=$(echo "#include <$1>" | g++ "${flags[@]}" -I"$3" -I"$build/include" -x c++ -E - | wc -l)
  echo "{\"header\": \"$1\", \"mode\": \"$2\", \"preprocessed_lines\": $n}" | tee -a "$out"
}

headers=(pdd/pdd.hpp pdd/generate.hpp pdd/pipeline.hpp pdd/pipeline/options.hpp
         pdd/kernels/cgal/mesher.hpp pdd/kernels/native/mesher.hpp)
record kernel kernel include
record generate libpdd include
record umbrella libpdd include
record generate header_only include -DPDD_HEADER_ONLY=1
record umbrella header_only include -DPDD_HEADER_ONLY=1
for h in "${headers[@]}"; do lines "$h" libpdd include; done
if [ -n "$before" ]; then
  git worktree add --detach "$tmp/before" "$before" >/dev/null 2>&1
  record generate "before ($before)" "$tmp/before/include"
  record umbrella "before ($before)" "$tmp/before/include"
  for h in "${headers[@]}"; do lines "$h" "before ($before)" "$tmp/before/include"; done
fi
record kernel kernel include # again: the machine's drift over the run
python3 "$(dirname "$0")/summarize_compile_times.py" "$out"
