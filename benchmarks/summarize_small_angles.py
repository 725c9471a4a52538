"""Prints the markdown table of benchmarks/results/small-angles.md from run_small_angles.sh's
JSON lines: per geometry, the monolithic run and the decoupled run side by side. The first line
is the provenance (printed as the page's 'Measured ...' line)."""
import sys

from raw_data import read_raw_data

rows = read_raw_data(sys.argv[1])[1:]
print('| geometry | run | N | threads | triangles | over-refinement % | k | split points '
      '| shielded triangles | min input angle | min unshielded angle | max ratio unshielded '
      '| interface / shield splits | verified | time s | speed-up | peak RSS MiB |')
print('|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|')


def seconds(r):
    """The run's wall time without the verification it was asked for."""
    return r['timings']['total'] - r['timings'].get('verify', 0.0)


def verified(r):
    if not r['verified']:
        return 'not run'
    return ('yes' if r['conforming'] else 'NO') + f", {r['delaunay_violations']} Delaunay violations"


for domain in dict.fromkeys(r['domain'] for r in rows):
    rs = [r for r in rows if r['domain'] == domain]
    mono = next(r for r in rs if r['label'] == 'monolithic')
    for r in rs:
        over = 100.0 * (r['triangles'] / mono['triangles'] - 1.0)
        k = f"{r['k']:.3g}" if r['k'] > 0 else '-'
        split = f"{r.get('split_points', 0):,}" if r['subdomains'] > 1 else '-'
        print(f"| {domain} | {r['label']} | {r['subdomains']} | {r['threads']} | {r['triangles']:,} | "
              f"{over:+.2f} | {k} | {split} | {r['shielded_triangles']} | "
              f"{r['min_input_angle_deg']:.2f} | {r['min_angle_unshielded_deg']:.2f} | "
              f"{r['max_ratio_unshielded']:.4f} | {r['interface_splits']} / {r['shield_splits']} | "
              f"{verified(r)} | {seconds(r):.2f} | {seconds(mono) / seconds(r):.2f}x | "
              f"{r['peak_rss_mib']:.0f} |")
