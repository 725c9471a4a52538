"""Prints the markdown tables of benchmarks/results/uniform.md from run_uniform.sh's JSON lines."""
import json
import sys

rows = [json.loads(line) for line in open(sys.argv[1]) if line.strip()]
for domain in sorted({r['domain'] for r in rows}):
    rs = [r for r in rows if r['domain'] == domain]
    mono = next(r for r in rs if r['label'] == 'monolithic')
    print(f"\n### {domain}: monolithic {mono['triangles']:,} triangles, "
          f"{mono['timings']['total']:.2f} s, peak RSS {mono['peak_rss_mib']:.0f} MiB\n")
    print('| run | N | threads | triangles | over-refinement % | decompose s | decouple s | mesh s '
          '| merge s | total s | speed-up vs monolithic | peak RSS MiB | min angle |')
    print('|---|---|---|---|---|---|---|---|---|---|---|---|---|')
    for r in rs:
        t = r['timings']
        over = 100.0 * (r['triangles'] / mono['triangles'] - 1.0)
        angle = f"{r['min_angle_deg']:.2f}" if 'min_angle_deg' in r else 'n/a'
        print(f"| {r['label']} | {r['subdomains']} | {r['threads']} | {r['triangles']:,} | {over:+.3f} | "
              f"{t['decompose']:.3f} | {t['decouple']:.3f} | {t['mesh']:.2f} | {t['merge']:.2f} | "
              f"{t['total']:.2f} | {mono['timings']['total'] / t['total']:.2f}x | "
              f"{r['peak_rss_mib']:.0f} ({100 * r['peak_rss_mib'] / mono['peak_rss_mib']:.0f}%) | {angle} |")
    # angle histograms (5-degree buckets, % of all angles): monolithic vs the largest N, 2 threads
    dec = [r for r in rs if r['label'] == 'decoupled']
    if dec and 'angle_histogram_deg' in mono:
        d = max(dec, key=lambda r: (r['threads'], r['subdomains']))
        print(f"\nAngle histogram (% of angles per 5-degree bucket), monolithic vs N = "
              f"{d['subdomains']}:\n")
        print('| angle | ' + ' | '.join(f'{b}-{b + 5}' for b in range(20, 125, 5)) + ' |')
        print('|---|' + '---|' * 21)
        for name, r in (('monolithic', mono), (f"N = {d['subdomains']}", d)):
            h = r['angle_histogram_deg']
            tot = sum(h)
            print(f'| {name} | ' + ' | '.join(
                f'{100.0 * sum(h[b:b + 5]) / tot:.2f}' for b in range(20, 125, 5)) + ' |')
