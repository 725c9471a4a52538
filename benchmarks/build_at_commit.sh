#!/usr/bin/env bash
# Builds pdd-mesh (or another driver) as it was at another commit, for the old-versus-new pairs
# in benchmarks/results/ (issue 37 item 5: a pair is regenerated from a build, not quoted).
#   bash benchmarks/build_at_commit.sh COMMIT [WORK_DIR] [TARGET]
# Makes a detached git worktree of COMMIT under WORK_DIR (default /var/tmp/pdd-at), configures
# it with that commit's own release preset (GCC, CMAKE_BUILD_TYPE=Release) and builds only its
# TARGET (default pdd-mesh; e.g. pdd-decompose, or bench_kernel from benchmarks/). Prints the
# path of that program on the last line of standard output. A worktree that already holds it
# built is reused (no rebuild).
set -euo pipefail
commit=${1:?usage: build_at_commit.sh COMMIT [WORK_DIR] [TARGET]}
work=${2:-/var/tmp/pdd-at}
target=${3:-pdd-mesh}
repo=$(git -C "$(dirname "${BASH_SOURCE[0]}")" rev-parse --show-toplevel)
full=$(git -C "$repo" rev-parse --verify "$commit^{commit}")
tree="$work/${full:0:10}"
exe="$tree/build/release/examples/drivers/$target"
[ -d "$tree/build/release/benchmarks" ] && [[ $target == bench_* ]] &&
  exe="$tree/build/release/benchmarks/$target"
if [ ! -x "$exe" ]; then
  mkdir -p "$work"
  [ -d "$tree" ] || git -C "$repo" worktree add --detach "$tree" "$full" >&2
  (cd "$tree" && cmake --preset release >&2 && cmake --build build/release --target "$target" >&2)
  [[ $target == bench_* ]] && exe="$tree/build/release/benchmarks/$target"
fi
echo "$exe"
