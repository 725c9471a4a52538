#!/usr/bin/env bash
# Provenance of a benchmark run (issue 37 item 5): every figure in benchmarks/results/ names the
# command that made it, the commit it measured, the machine and the date. A run_*.sh script
# sources this file and calls
#   provenance_json "$0 $*"   -> one JSON line {"provenance": {...}} (the first line of its raw data)
#   provenance_markdown "$0 $*" -> the same as a Markdown paragraph for the results page
# The commit is `git describe --always --dirty`: "-dirty" when tracked files differ from it
# (benchmarks/results/ excluded: a run rewrites its own raw data there).

provenance_commit() {
  local root
  root=$(git -C "$(dirname "${BASH_SOURCE[0]}")" rev-parse --show-toplevel 2>/dev/null) || {
    echo unknown
    return
  }
  local commit
  commit=$(git -C "$root" rev-parse --short=10 HEAD)
  if ! git -C "$root" diff --quiet HEAD -- . ':(exclude)benchmarks/results'; then
    commit="$commit-dirty"
  fi
  echo "$commit"
}

provenance_machine() {
  local cpu memory
  cpu=$(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -1)
  memory=$(awk '/^MemTotal/ {printf "%.0f GiB", $2 / 1048576}' /proc/meminfo)
  echo "$(nproc) cores ($cpu), $memory, $(uname -sr)"
}

provenance_json() {
  python3 - "$1" "$(provenance_commit)" "$(provenance_machine)" \
    "$(date -u +%Y-%m-%dT%H:%M:%SZ)" "$(uptime | sed 's/.*load average: //')" <<'EOF'
import json, sys
command, commit, machine, date, load = sys.argv[1:]
print(json.dumps({"provenance": {"command": command, "commit": commit, "machine": machine,
                                 "date": date, "load_average_at_start": load}}))
EOF
}

provenance_markdown() {
  echo "Measured $(date -u +%Y-%m-%d) at commit \`$(provenance_commit)\` on $(provenance_machine)," \
    "load average at start $(uptime | sed 's/.*load average: //'); command: \`$1\`"
}
