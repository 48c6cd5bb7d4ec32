#!/usr/bin/env python3
"""Checks the numbers an HTML report shows against the experiment's own files.

    check_numbers.py DIR TABLES.json

DIR is the output directory of `fspm run` (results.sqlite, ttests.csv); TABLES.json the page's
tables as check_report.mjs read them from the browser. The expected values are computed here,
from the database rows and the CSV, with Python's statistics module: the per-point means and
sample standard deviations of every metric, and every t-test's t, df, p and group means.
"""
import csv
import json
import math
import re
import sqlite3
import statistics
import sys
from pathlib import Path


def g4(v):
    """A number as the report's tables print it, as fspm::format_significant(v, 4) does: four
    significant digits without trailing zeros, integer parts whole, an exponent below 1e-4 and
    from 1e15, magnitudes below 1e-12 as 0."""
    if math.isnan(v):
        return "nan"
    if math.isinf(v):
        return "inf" if v > 0 else "-inf"
    if abs(v) < 1e-12:
        return "0"
    if abs(v) < 1e-4 or abs(v) >= 1e15:
        mantissa, exponent = ("%.3e" % v).split("e")
        if "." in mantissa:
            mantissa = mantissa.rstrip("0").rstrip(".")
        return mantissa + "e" + exponent
    decimals = max(0, 3 - math.floor(math.log10(abs(v))))
    text = "%.*f" % (decimals, v)
    if "." in text:
        text = text.rstrip("0").rstrip(".")
    return "0" if text == "-0" else text


def moments_text(values):
    if not values:
        return "-"
    if len(values) == 1:
        return g4(values[0])
    return g4(statistics.fmean(values)) + " ± " + g4(statistics.stdev(values))


def same_to_shown_digits(shown, value):
    """True when `value` rounded to as many significant digits as `shown` has equals it."""
    digits = len(re.sub(r"^[-0.]+", "", shown.split("e")[0]).replace(".", "")) or 1
    return math.isclose(float("%.*g" % (digits, value)), float(shown), rel_tol=1e-12, abs_tol=0)


def check_point_tables(db, tables, failures):
    runs = db.execute("SELECT point, status, metrics, parameters FROM runs").fetchall()
    recorded = set()
    for r in runs:
        recorded.update(json.loads(r[2] or "{}"))
    checked = 0
    for table in tables:
        if table["heading"] not in ("Metrics per parameter point", "Timings per parameter point"):
            continue
        metrics = [h.split(" (")[0] for h in table["headers"]]
        for row in table["rows"]:
            point = int(row[0])
            at_point = [r for r in runs if r[0] == point]
            if int(row[1]) != len(at_point):
                failures.append(f"point {point}: {row[1]} runs on the page, {len(at_point)} in the database")
            for column, cell in enumerate(row):
                name = metrics[column]
                if column < 2:
                    continue
                if name not in recorded:  # a swept parameter
                    value = json.loads(at_point[0][3])[name]
                    same = cell == value if isinstance(value, str) else float(cell) == value
                    if not same:
                        failures.append(f"point {point}, {name}: page {cell!r}, database {value!r}")
                    continue
                values = [json.loads(m).get(name) for p, s, m, _ in at_point if s == "ok"]
                values = [v for v in values if isinstance(v, (int, float)) and math.isfinite(v)]
                expected = moments_text(values)
                checked += 1
                if cell != expected:
                    failures.append(f"{table['heading']}, point {point}, {name}: page {cell!r}, database {expected!r}")
    return checked


def check_ttests(directory, tables, failures):
    path = directory / "ttests.csv"
    if not path.exists():
        return 0
    tests = {(r["group"], r["a"], r["b"]): r for r in csv.DictReader(path.open())}
    checked = 0
    for table in tables:
        if table["heading"] == "t-tests":
            for row in table["rows"]:
                cells = dict(zip(table["headers"], row))
                t = tests.get((cells["group"], cells["a"], cells["b"]))
                if t is None:
                    failures.append(f"t-test {cells['group']} {cells['a']} vs {cells['b']} is not in ttests.csv")
                    continue
                for key in ("t", "df"):
                    checked += 1
                    if cells[key] != g4(float(t[key])):
                        failures.append(f"t-test {cells['group']}: {key} page {cells[key]}, ttests.csv {t[key]}")
                p = cells["p"]
                checked += 1
                ok = float(t["p"]) < float(p.split("<")[1]) if "<" in p else same_to_shown_digits(p.split("=")[1].strip(), float(t["p"]))
                if not ok:
                    failures.append(f"t-test {cells['group']}: p page {p!r}, ttests.csv {t['p']}")
        if table["heading"] == "Comparisons":
            for row in table["rows"]:
                if row[1] != "mean":
                    continue
                for name, cell in zip(table["headers"][2:], row[2:]):
                    means = [float(t["mean_a"]) for (g, a, b), t in tests.items() if g == row[0] and a == name]
                    means += [float(t["mean_b"]) for (g, a, b), t in tests.items() if g == row[0] and b == name]
                    if not means:
                        continue
                    checked += 1
                    if not same_to_shown_digits(cell, means[0]):
                        failures.append(f"Comparisons {row[0]} {name}: mean page {cell}, ttests.csv {means[0]}")
    return checked


def main():
    directory, tables_path = Path(sys.argv[1]), sys.argv[2]
    tables = json.load(open(tables_path))
    db = sqlite3.connect(f"file:{directory / 'results.sqlite'}?mode=ro", uri=True)
    failures = []
    n_points = check_point_tables(db, tables, failures)
    n_tests = check_ttests(directory, tables, failures)
    for f in failures[:20]:
        print("FAIL:", f)
    if n_points == 0:
        failures.append("no per-point table on the page")
        print("FAIL: no per-point table on the page")
    if failures:
        sys.exit(1)
    print(f"numbers: {n_points} per-point cells equal results.sqlite, {n_tests} t-test values equal ttests.csv")


if __name__ == "__main__":
    main()
