"""Reads a benchmark's raw data (issue 37 item 5), for the tables the run_*.sh scripts print.

The first line of a raw data file is {"provenance": {...}} (benchmarks/provenance.sh), every
other line one measured run. A script's table snippet runs with this folder on PYTHONPATH:

    from raw_data import read_raw_data
    lines = read_raw_data(sys.argv[1])   # prints the provenance line; lines[1:] are the runs
"""
import json


def read_raw_data(path, blank_line=True):
    """Every JSON line of `path`, after printing its provenance as the page's 'Measured ...'
    line (followed by an empty line unless blank_line is False)."""
    with open(path, encoding="utf-8") as f:
        lines = [json.loads(line) for line in f]
    p = lines[0]["provenance"]
    print("Measured %s at commit `%s` on %s (load average at start %s); command: `%s`%s" % (
        p["date"], p["commit"], p["machine"], p["load_average_at_start"], p["command"],
        "\n" if blank_line else ""))
    return lines
