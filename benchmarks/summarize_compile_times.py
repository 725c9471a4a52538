#!/usr/bin/env python3
"""Prints benchmarks/results/compile-times.md's tables from the raw data of
run_compile_times.sh (compile-times.jsonl): the times against the kernel-only file (the mean of
its runs), and the preprocessed lines of the main headers."""
import json
import sys


def main(path):
    rows = [json.loads(line) for line in open(path)]
    provenance = rows[0]["provenance"]
    runs = [r for r in rows[1:] if "file" in r]
    kernel = [r["wall_s"] for r in runs if r["file"] == "kernel"]
    base = sum(kernel) / len(kernel)
    print(f"Command: `{provenance['command']}`, commit {provenance['commit']}, "
          f"{provenance['date']}, {provenance['machine']}.\n")
    print("| file | headers from | wall s | CPU s | peak MiB | / kernel-only file |")
    print("|---|---|--:|--:|--:|--:|")
    for r in runs:
        print(f"| {r['file']} | {r['mode']} | {r['wall_s']:.1f} | {r['cpu_s']:.1f} | "
              f"{r['peak_mib']} | {r['wall_s'] / base:.2f} |")
    print("\n| header | headers from | preprocessed lines |")
    print("|---|---|--:|")
    for r in rows[1:]:
        if "header" in r:
            print(f"| `{r['header']}` | {r['mode']} | {r['preprocessed_lines']:,} |")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "benchmarks/results/compile-times.jsonl")
