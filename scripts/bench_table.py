#!/usr/bin/env python3
"""Keeps docs/BENCHMARKS.md and bench/ in step.

    python3 scripts/bench_table.py RESULTS.json   # rows from `scripts/bench.sh` output
    scripts/bench.sh | python3 scripts/bench_table.py -
    python3 scripts/bench_table.py --check        # every benchmark has a current row, no stale name

RESULTS.json is what scripts/bench.sh prints: a JSON list with one Google Benchmark document
per benchmark program. The rows give each benchmark's time per iteration (CPU and wall), its
counters, and the load average the program saw, ready to be placed in the area tables of the
"Current figures" part of docs/BENCHMARKS.md.
"""
import json
import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
DOC = ROOT / "docs" / "BENCHMARKS.md"

# BENCHMARK(BM_Name) up to the end of its statement, where ->Name("...") may rename it.
REGISTRATION = re.compile(r"BENCHMARK\((BM_\w+)\)([^;]*);", re.S)
RENAME = re.compile(r'->Name\("([^"]+)"\)')


def registered_benchmarks():
    """(function name, reported name) of every benchmark registered in bench/*.cpp."""
    found = []
    for source in sorted((ROOT / "bench").glob("*.cpp")):
        for match in REGISTRATION.finditer(source.read_text()):
            rename = RENAME.search(match.group(2))
            found.append((match.group(1), rename.group(1) if rename else match.group(1),
                          source.name))
    return found


def check():
    """Exit status 1 when the current tables miss a benchmark or name one that is gone."""
    text = DOC.read_text()
    if "## Current figures" not in text or "## History" not in text:
        print(f"{DOC.name}: expected the parts '## Current figures' and '## History'")
        return 1
    current = text[text.index("## Current figures"):text.index("## History")]
    benchmarks = registered_benchmarks()
    named = set(re.findall(r"\w+", current)) | set(re.findall(r"[\w/]+", current))
    problems = []
    for function, reported, source in benchmarks:
        if function not in named and reported not in named:
            problems.append(f"{function} ({source}) has no row under 'Current figures'")
    known = {function for function, _, _ in benchmarks}
    for name in sorted(set(re.findall(r"\bBM_\w+", text)) - known):
        problems.append(f"{name} is named in {DOC.name} but registered nowhere in bench/")
    for problem in problems:
        print(f"docs/BENCHMARKS.md: {problem}")
    if not problems:
        print(f"docs/BENCHMARKS.md: all {len(benchmarks)} benchmarks of bench/ have a current row")
    return 1 if problems else 0


def format_time(value, unit):
    return f"{value:.3g} {unit}"


def rows(documents):
    """Markdown rows: benchmark, CPU and wall time per iteration, counters, load average."""
    yield "| benchmark | CPU time | wall time | counters | load average |"
    yield "|---|---|---|---|---|"
    for document in documents:
        load = document.get("context", {}).get("load_avg", [])
        load_text = ", ".join(f"{x:.1f}" for x in load) if load else "—"
        for b in document.get("benchmarks", []):
            if b.get("run_type") == "aggregate" and b.get("aggregate_name") != "median":
                continue
            unit = b.get("time_unit", "ns")
            skip = {"name", "run_name", "run_type", "repetitions", "repetition_index",
                    "threads", "iterations", "real_time", "cpu_time", "time_unit", "family_index",
                    "per_family_instance_index", "aggregate_name", "aggregate_unit", "label"}
            counters = ", ".join(f"{k} {v:.4g}" for k, v in b.items()
                                 if k not in skip and isinstance(v, (int, float)))
            yield (f"| `{b['name']}` | {format_time(b['cpu_time'], unit)} | "
                   f"{format_time(b['real_time'], unit)} | {counters or '—'} | {load_text} |")


def main(argv):
    if argv == ["--check"]:
        return check()
    if len(argv) != 1:
        print(__doc__.strip())
        return 2
    try:
        stream = sys.stdin if argv[0] == "-" else open(argv[0], encoding="utf-8")
        with stream:
            documents = json.load(stream)
    except (OSError, json.JSONDecodeError) as error:
        print(f"{argv[0]}: {error}", file=sys.stderr)
        return 1
    if isinstance(documents, dict):
        documents = [documents]
    for row in rows(documents):
        print(row)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
