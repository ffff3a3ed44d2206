#!/usr/bin/python3
"""Tests of plots/compare_results.py, the regression check between two results.

Run: /usr/bin/python3 tests/python/test_compare.py   (CTest sets TETSMOOTH_SOURCE_DIR)
tests/data/bench_small_slower.json is bench_small.json with two benchmarks
slowed down: FormB/AoS/MultiBlock/5k by 1.5x and FormB/SoA/MultiBlock/109k by
1.2x (their rates divided by the same factors); everything else is identical.
"""

import csv
import json
import math
import os
import re
import subprocess
import sys
import tempfile
import unittest

SOURCE_DIR = os.environ.get("TETSMOOTH_SOURCE_DIR") or os.path.dirname(
    os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
PLOTS = os.path.join(SOURCE_DIR, "plots")
DATA = os.path.join(SOURCE_DIR, "tests", "data")
BASE = os.path.join(DATA, "bench_small.json")
SLOWER = os.path.join(DATA, "bench_small_slower.json")
SLOWED = {"FormB/AoS/MultiBlock/5k": 1.5, "FormB/SoA/MultiBlock/109k": 1.2}
sys.path.insert(0, PLOTS)

import bench_json as bj  # noqa: E402
import compare_results  # noqa: E402


def compare(*args):
    return subprocess.run([sys.executable, os.path.join(PLOTS, "compare_results.py"), *args],
                          capture_output=True, text=True, timeout=120)


def printed_geomean(output):
    match = re.search(r"geometric mean\s+([0-9.]+)\s+\((\d+) benchmarks\)", output)
    return float(match.group(1)), int(match.group(2))


def gbench_available():
    return os.path.isfile(compare_results.GBENCH_COMPARE) and subprocess.run(
        [sys.executable, "-c", "import scipy, numpy"], capture_output=True).returncode == 0


class ExitStatusTests(unittest.TestCase):
    def test_identical_files_pass(self):
        completed = compare(BASE, BASE)
        self.assertEqual(completed.returncode, 0, completed.stdout + completed.stderr)
        self.assertIn("OK: within thresholds", completed.stdout)
        self.assertEqual(printed_geomean(completed.stdout)[0], 1.0)

    def test_slower_file_fails(self):
        completed = compare(BASE, SLOWER)
        self.assertEqual(completed.returncode, 1, completed.stdout + completed.stderr)
        self.assertIn("REGRESSION", completed.stdout)
        for name in SLOWED:
            self.assertRegex(completed.stdout, re.escape(name) + r"\s.*SLOWER")
        self.assertNotRegex(completed.stdout, r"FormB/AoS/MultiBlock/109k\s.*SLOWER")

    def test_geomean_is_over_common_benchmarks(self):
        geomean, count = printed_geomean(compare(BASE, SLOWER).stdout)
        expected = math.exp(sum(math.log(f) for f in SLOWED.values()) / count)
        self.assertAlmostEqual(geomean, expected, places=3)
        self.assertEqual(count, len(bj.load_result(BASE).runs))

    def test_thresholds_are_separate_options(self):
        # Geomean ~1.026: within 10 % once the per-benchmark check is off ...
        self.assertEqual(compare(BASE, SLOWER, "--per-benchmark-threshold", "off").returncode, 0)
        # ... and beyond 2 %.
        completed = compare(BASE, SLOWER, "--per-benchmark-threshold", "off", "--geomean-threshold", "0.02")
        self.assertEqual(completed.returncode, 1)
        self.assertIn("geometric mean of ratios", completed.stdout)
        # Per benchmark only: 1.5 is beyond 1.3, 1.2 is not.
        completed = compare(BASE, SLOWER, "--geomean-threshold", "off", "--per-benchmark-threshold", "0.3")
        self.assertEqual(completed.returncode, 1)
        self.assertIn("1 benchmark(s) slower", completed.stdout)
        self.assertEqual(compare(BASE, SLOWER, "--threshold", "0.6").returncode, 0)
        self.assertEqual(compare(BASE, SLOWER, "--threshold", "off").returncode, 0)

    def test_faster_new_result_passes(self):
        self.assertEqual(compare(SLOWER, BASE).returncode, 0)

    def test_rate_metric_is_higher_is_better(self):
        completed = compare(BASE, SLOWER, "--metric", "bytes_per_s")
        self.assertEqual(completed.returncode, 1, completed.stdout + completed.stderr)
        self.assertIn("higher is better", completed.stdout)
        self.assertEqual(compare(SLOWER, BASE, "--metric", "bytes_per_s").returncode, 0)

    def test_filter(self):
        completed = compare(BASE, SLOWER, "--filter", "^Serial/")
        self.assertEqual(completed.returncode, 0)
        self.assertNotIn("FormB/AoS/MultiBlock/5k", completed.stdout)


class BadInputTests(unittest.TestCase):
    def test_missing_file(self):
        completed = compare(BASE, os.path.join(DATA, "no_such_result.json"))
        self.assertEqual(completed.returncode, 2)
        self.assertIn("no such file", completed.stderr)

    def test_bad_json_and_not_benchmark_json(self):
        with tempfile.TemporaryDirectory() as folder:
            for text in ("{\"context\": {", "{\"context\": {}}"):
                path = os.path.join(folder, "bad.json")
                with open(path, "w", encoding="utf-8") as handle:
                    handle.write(text)
                completed = compare(path, BASE)
                self.assertEqual(completed.returncode, 2, text)
                self.assertIn("bad.json", completed.stderr)

    def test_nothing_in_common_and_bad_options(self):
        self.assertEqual(compare(BASE, SLOWER, "--filter", "^NoSuchFamily").returncode, 2)
        self.assertEqual(compare(BASE, SLOWER, "--filter", "(").returncode, 2)
        self.assertEqual(compare(BASE, SLOWER, "--threshold", "-1").returncode, 2)
        self.assertEqual(compare(BASE).returncode, 2)


class OutputTests(unittest.TestCase):
    def test_csv_output(self):
        with tempfile.TemporaryDirectory() as folder:
            path = os.path.join(folder, "cmp.csv")
            compare(BASE, SLOWER, "--csv", path)
            with open(path, newline="", encoding="utf-8") as handle:
                rows = list(csv.DictReader(handle))
        self.assertEqual(list(rows[0]), ["benchmark", "old", "new", "ratio_new_over_old", "statistic"])
        by_name = {r["benchmark"]: r for r in rows}
        for name, factor in SLOWED.items():
            self.assertAlmostEqual(float(by_name[name]["ratio_new_over_old"]), factor, places=6)
        self.assertIn("geomean", by_name)

    def test_gbench_delegation(self):
        completed = compare(BASE, SLOWER, "--gbench")
        self.assertEqual(completed.returncode, 1)  # the verdict stays ours
        if gbench_available():
            self.assertIn("Google Benchmark compare.py", completed.stdout)
            self.assertIn("FormB/AoS/MultiBlock/5k/repeats:3/manual_time", completed.stdout)
        else:
            self.assertIn("note: --gbench", completed.stdout)

    def test_names_match_across_suffixes(self):
        def document(suffix, time):
            return {"context": {}, "benchmarks": [
                {"name": "FormB/AoS/MultiBlock/5k" + suffix, "run_type": "iteration", "real_time": time,
                 "cpu_time": time, "time_unit": "ms", "iterations": 3}]}
        old = bj.parse_result(document("/manual_time", 2.0))
        new = bj.parse_result(document("/repeats:3/manual_time", 3.0))
        comparison = compare_results.compare(old, new, "real_time")
        self.assertEqual([r.name for r in comparison.rows], ["FormB/AoS/MultiBlock/5k"])
        self.assertAlmostEqual(comparison.geomean(), 1.5)

    def test_fixtures_differ_only_where_documented(self):
        with open(BASE, encoding="utf-8") as handle:
            base = json.load(handle)
        with open(SLOWER, encoding="utf-8") as handle:
            slower = json.load(handle)
        self.assertEqual(len(base["benchmarks"]), len(slower["benchmarks"]))
        for old, new in zip(base["benchmarks"], slower["benchmarks"]):
            name = bj.entry_name(old)
            if name not in SLOWED:
                self.assertEqual(old, new, name)


if __name__ == "__main__":
    unittest.main()
