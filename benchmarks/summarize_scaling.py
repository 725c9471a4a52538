#!/usr/bin/env python3
"""Markdown tables from a benchmarks/run_scaling.sh output folder.

Usage: python3 benchmarks/summarize_scaling.py OUT_DIR
OUT_DIR holds results.jsonl (one line per run: wall_s, cpu_s, peak_rss_mib of the process) and
pdd-mesh's --stats JSON of each run (triangles, subdomains, timings).
"""
import json
import pathlib
import sys

out = pathlib.Path(sys.argv[1])
runs = {}
for line in (out / "results.jsonl").read_text().splitlines():
    r = json.loads(line)
    if "provenance" in r:  # benchmarks/provenance.sh: command, commit, machine, date
        p = r["provenance"]
        print(f"Measured {p['date']} at commit `{p['commit']}` on {p['machine']} (load average "
              f"at start {p['load_average_at_start']}); command: `{p['command']}`\n")
        continue
    runs[r["run"]] = r


def stats(name):
    p = out / f"{name}.json"
    return json.loads(p.read_text()) if p.exists() else {}


def kernels_table(domain):
    tri = runs.get(f"{domain} triangle 1")
    print(f"\n### {domain}, about 16M triangles\n")
    print("| run | threads | triangles | subdomains | wall s | CPU s | mesh s | peak RSS MiB "
          "| bytes / triangle | Triangle's wall / this wall |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    if tri:
        print(f"| Triangle 1.6 | 1 | | 1 | {tri['wall_s']:.2f} | {tri['cpu_s']:.2f} | | "
              f"{tri['peak_rss_mib']:.0f} | | 1.00 |")
    for kernel in ("native", "cgal"):
        rows = [("monolithic", 1, f"{domain}-{kernel}-mono")]
        t = 1
        while f"{domain} {kernel} decoupled {t}" in runs:
            rows.append(("decoupled", t, f"{domain}-{kernel}-t{t}"))
            t *= 2
        for what, threads, name in rows:
            r = runs.get(f"{domain} {kernel} {what} {threads}")
            s = stats(name)
            if not r or not s:
                continue
            n = s["triangles"]
            ratio = tri["wall_s"] / r["wall_s"] if tri else float("nan")
            print(f"| {kernel} {what} | {threads} | {n:,} | {s['subdomains']} | {r['wall_s']:.2f} "
                  f"| {r['cpu_s']:.2f} | {s['timings']['mesh']:.2f} | {r['peak_rss_mib']:.0f} "
                  f"| {r['peak_rss_mib'] * 2**20 / n:.0f} | {ratio:.2f} |")


def mpi_table(kind):
    print(f"\n### MPI, {kind} size\n")
    gain = "speed-up wall(1) / wall(P)" if kind == "fixed" else "efficiency wall(1) / wall(P)"
    print(f"| ranks P | triangles | wall s | path s | mesh s | {gain} | T_e us (P * mesh / triangles) | imbalance max/mean busy |")
    print("|---|---|---|---|---|---|---|---|")
    base = None
    p = 1
    while f"pipe mpi {kind} {p}" in runs:
        r, s = runs[f"pipe mpi {kind} {p}"], stats(f"mpi-{kind}-{p}")
        n, t = s.get("triangles", 0), s.get("timings", {})
        base = base or r["wall_s"]
        speed = base / r["wall_s"]
        te = p * t.get("mesh", 0) / n * 1e6 if n else float("nan")
        print(f"| {p} | {n:,} | {r['wall_s']:.2f} | {t.get('path', 0):.2f} | {t.get('mesh', 0):.2f} "
              f"| {speed:.2f} | {te:.2f} | {s.get('imbalance', float('nan')):.3f} |")
        p *= 2


def versus_table():
    """The part "versus": Triangle against pdd-mesh's automatic plan, repetition by repetition."""
    print("\n### Against Triangle 1.6, one pinned thread against one\n")
    print("| domain | rep | kernel | triangles (pdd) | Triangle wall s | pdd 1 thread wall s "
          "| pdd 2 threads wall s | ratio, 1 thread | ratio, 2 threads | peak RSS MiB, Triangle / pdd |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for name, tri in runs.items():
        domain, what, _, rep = (name.split() + ["", "", "", ""])[:4]
        if what != "triangle" or not rep.startswith("rep"):
            continue
        for kernel in ("native", "cgal"):
            one, two = runs.get(f"{domain} {kernel} auto 1 {rep}"), runs.get(f"{domain} {kernel} auto 2 {rep}")
            if not one or not two:
                continue
            n = stats(f"{domain}-{kernel}-auto-t1-{rep}").get("triangles", 0)
            print(f"| {domain} | {rep[3:]} | {kernel} | {n:,} | {tri['wall_s']:.2f} | {one['wall_s']:.2f} "
                  f"| {two['wall_s']:.2f} | {tri['wall_s'] / one['wall_s']:.2f} "
                  f"| {tri['wall_s'] / two['wall_s']:.2f} "
                  f"| {tri['peak_rss_mib']:.0f} / {two['peak_rss_mib']:.0f} |")


if any(name.endswith("rep1") for name in runs):
    versus_table()
for d in ("pipe", "key"):
    if f"{d} triangle 1" in runs:
        kernels_table(d)
for kind in ("fixed", "scaled"):
    if "pipe mpi fixed 1" in runs:
        mpi_table(kind)
other = [r for name, r in runs.items()
         if (name.startswith("bahamas ") or name.endswith("000000")) and "rep" not in name]
if other:
    print("\n### Monolithic runs\n")
    print("| run | triangles | wall s | CPU s | peak RSS MiB |")
    print("|---|---|---|---|---|")
    for r in other:
        name = r["run"].replace(" ", "-").replace("-auto-1", "-t1")
        parts = r["run"].split()
        s = stats(f"{parts[0]}-{parts[1]}-{parts[2]}") if parts[1] == "native" and parts[2].isdigit() \
            else stats(f"bahamas-{parts[1]}-t1") if parts[0] == "bahamas" else {}
        n = s.get("triangles", "")
        print(f"| {r['run']} | {n:,} | {r['wall_s']:.2f} | {r['cpu_s']:.2f} | {r['peak_rss_mib']:.0f} |"
              if n != "" else f"| {r['run']} | | {r['wall_s']:.2f} | {r['cpu_s']:.2f} | {r['peak_rss_mib']:.0f} |")
