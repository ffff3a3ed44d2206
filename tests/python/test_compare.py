#!/usr/bin/python3
"""Tests of plots/compare_results.py, the regression check between two results.

Run: /usr/bin/python3 tests/python/test_compare.py   (CTest sets TETSMOOTH_SOURCE_DIR)
tests/data/bench_small_slower.json is bench_small.json with two benchmarks
slowed down: FormB/AoS/MultiBlock/5k by 1.5x and FormB/SoA/MultiBlock/109k by
1.2x (their rates divided by the same factors); everything else is identical.
Both fixtures hold one benchmark reported as an error (Threads/FormA/109k),
which fails the check; the timing tests use copies without it (CLEAN_BASE,
CLEAN_SLOWER) and the error tests use the fixtures as they are.  Other cases
(missing benchmarks, precisions, hosts, empty files) are small synthetic
results written by write_result().
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
ERRORED = "Threads/FormA/109k"
ERROR_MESSAGE = "skipped: --skip-slow-cpu was given"
sys.path.insert(0, PLOTS)

import bench_json as bj  # noqa: E402
import compare_results  # noqa: E402


FOLDER = tempfile.TemporaryDirectory()
CLEAN_BASE = os.path.join(FOLDER.name, "bench_small_clean.json")
CLEAN_SLOWER = os.path.join(FOLDER.name, "bench_small_slower_clean.json")


def copy_without_errors(source, target):
    """A fixture without its errored entry, so that only the timings decide the verdict."""
    with open(source, encoding="utf-8") as handle:
        document = json.load(handle)
    document["benchmarks"] = [e for e in document["benchmarks"] if not e.get("error_occurred")]
    with open(target, "w", encoding="utf-8") as handle:
        json.dump(document, handle)


def setUpModule():
    copy_without_errors(BASE, CLEAN_BASE)
    copy_without_errors(SLOWER, CLEAN_SLOWER)


def tearDownModule():
    FOLDER.cleanup()


def bench(name, time=None, error=None):
    """One iteration entry in ms, or an errored one when error is a message."""
    item = {"name": name + "/manual_time", "run_name": name + "/manual_time", "run_type": "iteration",
            "iterations": 1, "real_time": time or 0.0, "cpu_time": time or 0.0, "time_unit": "ms"}
    if error:
        item.update(error_occurred=True, error_message=error)
    return item


GPU_CONTEXT = {"gpu_name": "NVIDIA H100 80GB HBM3", "gpu_precision": "double", "host_name": "vm", "num_cpus": 16}


def write_result(folder, stem, benchmarks, **context):
    """A result file with GPU_CONTEXT updated by context (a value of None drops the key)."""
    merged = dict(GPU_CONTEXT, **context)
    path = os.path.join(folder, stem + ".json")
    with open(path, "w", encoding="utf-8") as handle:
        json.dump({"context": {k: v for k, v in merged.items() if v is not None}, "benchmarks": benchmarks}, handle)
    return path


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
        completed = compare(CLEAN_BASE, CLEAN_BASE)
        self.assertEqual(completed.returncode, 0, completed.stdout + completed.stderr)
        self.assertIn("OK: within thresholds", completed.stdout)
        self.assertEqual(printed_geomean(completed.stdout)[0], 1.0)

    def test_slower_file_fails(self):
        completed = compare(CLEAN_BASE, CLEAN_SLOWER)
        self.assertEqual(completed.returncode, 1, completed.stdout + completed.stderr)
        self.assertIn("REGRESSION", completed.stdout)
        for name in SLOWED:
            self.assertRegex(completed.stdout, re.escape(name) + r"\s.*SLOWER")
        self.assertNotRegex(completed.stdout, r"FormB/AoS/MultiBlock/109k\s.*SLOWER")

    def test_geomean_is_over_common_benchmarks(self):
        geomean, count = printed_geomean(compare(CLEAN_BASE, CLEAN_SLOWER).stdout)
        expected = math.exp(sum(math.log(f) for f in SLOWED.values()) / count)
        self.assertAlmostEqual(geomean, expected, places=3)
        self.assertEqual(count, len(bj.load_result(CLEAN_BASE).runs))

    def test_thresholds_are_separate_options(self):
        # Geomean ~1.026: within 10 % once the per-benchmark check is off ...
        self.assertEqual(compare(CLEAN_BASE, CLEAN_SLOWER, "--per-benchmark-threshold", "off").returncode, 0)
        # ... and beyond 2 %.
        completed = compare(CLEAN_BASE, CLEAN_SLOWER, "--per-benchmark-threshold", "off",
                            "--geomean-threshold", "0.02")
        self.assertEqual(completed.returncode, 1)
        self.assertIn("geometric mean of ratios", completed.stdout)
        # Per benchmark only: 1.5 is beyond 1.3, 1.2 is not.
        completed = compare(CLEAN_BASE, CLEAN_SLOWER, "--geomean-threshold", "off",
                            "--per-benchmark-threshold", "0.3")
        self.assertEqual(completed.returncode, 1)
        self.assertIn("1 benchmark(s) slower", completed.stdout)
        self.assertEqual(compare(CLEAN_BASE, CLEAN_SLOWER, "--threshold", "0.6").returncode, 0)
        self.assertEqual(compare(CLEAN_BASE, CLEAN_SLOWER, "--threshold", "off").returncode, 0)

    def test_faster_new_result_passes(self):
        self.assertEqual(compare(CLEAN_SLOWER, CLEAN_BASE).returncode, 0)

    def test_rate_metric_is_higher_is_better(self):
        completed = compare(CLEAN_BASE, CLEAN_SLOWER, "--metric", "bytes_per_s")
        self.assertEqual(completed.returncode, 1, completed.stdout + completed.stderr)
        self.assertIn("higher is better", completed.stdout)
        self.assertEqual(compare(CLEAN_SLOWER, CLEAN_BASE, "--metric", "bytes_per_s").returncode, 0)

    def test_rate_verdicts_count_a_fall_as_a_slowdown(self):
        # With the per-benchmark check off only the geometric mean decides:
        # the slowed fixture's rates fell, so new/old < 1 is the regression
        # for bytes_per_s (about 2.5 % here, beyond a 2 % limit), and the same
        # ratios the other way round are an improvement.
        only_geomean = ("--metric", "bytes_per_s", "--per-benchmark-threshold", "off", "--geomean-threshold", "0.02")
        completed = compare(CLEAN_BASE, CLEAN_SLOWER, *only_geomean)
        self.assertEqual(completed.returncode, 1, completed.stdout + completed.stderr)
        geomean, count = printed_geomean(completed.stdout)
        self.assertAlmostEqual(geomean, math.exp(-sum(math.log(f) for f in SLOWED.values()) / count), places=3)
        self.assertLess(geomean, 1 / 1.02)
        self.assertIn("REGRESSION: geometric mean of ratios", completed.stdout)
        completed = compare(CLEAN_SLOWER, CLEAN_BASE, *only_geomean)
        self.assertEqual(completed.returncode, 0, completed.stdout + completed.stderr)
        self.assertGreater(printed_geomean(completed.stdout)[0], 1.02)
        # Benchmark by benchmark likewise: only the 1.5x fall is beyond 1.3.
        only_each = ("--metric", "bytes_per_s", "--geomean-threshold", "off", "--per-benchmark-threshold", "0.3")
        completed = compare(CLEAN_BASE, CLEAN_SLOWER, *only_each)
        self.assertEqual(completed.returncode, 1, completed.stdout + completed.stderr)
        self.assertIn("REGRESSION: 1 benchmark(s) slower than 1.300x: FormB/AoS/MultiBlock/5k", completed.stdout)
        self.assertEqual(compare(CLEAN_SLOWER, CLEAN_BASE, *only_each).returncode, 0)

    def test_filter(self):
        completed = compare(CLEAN_BASE, CLEAN_SLOWER, "--filter", "^Serial/")
        self.assertEqual(completed.returncode, 0)
        self.assertNotIn("FormB/AoS/MultiBlock/5k", completed.stdout)


class ErrorAndMissingTests(unittest.TestCase):
    """Benchmarks that errored or disappeared cannot be tracked: they must not pass silently."""

    def setUp(self):
        self.folder = tempfile.TemporaryDirectory()
        self.addCleanup(self.folder.cleanup)

    def result(self, stem, benchmarks, **context):
        return write_result(self.folder.name, stem, benchmarks, **context)

    def test_error_in_new_fails_and_is_printed(self):
        completed = compare(BASE, BASE)  # the fixture's errored benchmark is in NEW too
        self.assertEqual(completed.returncode, 1, completed.stdout + completed.stderr)
        self.assertIn(f"errored in NEW (not compared): {ERRORED}: {ERROR_MESSAGE}", completed.stdout)
        self.assertRegex(completed.stdout, r"REGRESSION: 1 benchmark\(s\) errored in NEW: " + re.escape(ERRORED))
        self.assertNotIn("only in OLD", completed.stdout)  # reported once, as errored
        # --filter selects the errors too.
        completed = compare(BASE, BASE, "--filter", "^Form")
        self.assertEqual(completed.returncode, 0, completed.stdout + completed.stderr)
        self.assertNotIn(ERRORED, completed.stdout)

    def test_error_in_new_of_a_measured_benchmark(self):
        old = self.result("old", [bench("Serial/FormB/5k", 10.0), bench("Serial/FormA/5k", 20.0)])
        new = self.result("new", [bench("Serial/FormB/5k", 10.0), bench("Serial/FormA/5k", error="CUDA error")])
        completed = compare(old, new)
        self.assertEqual(completed.returncode, 1, completed.stdout + completed.stderr)
        self.assertIn("Serial/FormA/5k: CUDA error", completed.stdout)
        # Every benchmark of NEW errored: still a regression (1), not bad input (2).
        new = self.result("new", [bench("Serial/FormB/5k", error="out of memory")])
        completed = compare(old, new, "--filter", "FormB")
        self.assertEqual(completed.returncode, 1, completed.stdout + completed.stderr)
        self.assertIn("out of memory", completed.stdout)

    def test_error_only_in_old_is_a_note(self):
        completed = compare(BASE, CLEAN_BASE)
        self.assertEqual(completed.returncode, 0, completed.stdout + completed.stderr)
        self.assertIn(f"errored in OLD (not compared): {ERRORED}: {ERROR_MESSAGE}", completed.stdout)

    def test_missing_from_new_fails_unless_allowed(self):
        old = self.result("old", [bench("Serial/FormB/5k", 10.0), bench("FormB/AoS/MultiBlock/5k", 1.0)])
        new = self.result("new", [bench("Serial/FormB/5k", 10.0)])
        completed = compare(old, new)
        self.assertEqual(completed.returncode, 1, completed.stdout + completed.stderr)
        self.assertIn("missing from NEW", completed.stdout)
        self.assertIn("FormB/AoS/MultiBlock/5k", completed.stdout)
        completed = compare(old, new, "--allow-missing")
        self.assertEqual(completed.returncode, 0, completed.stdout + completed.stderr)
        self.assertRegex(completed.stdout, r"warning: 1 benchmark\(s\) of OLD missing from NEW \(allowed\)")
        self.assertEqual(compare(old, new, "--filter", "^Serial/").returncode, 0)
        # The other way round the extra benchmark is only listed.
        completed = compare(new, old)
        self.assertEqual(completed.returncode, 0, completed.stdout + completed.stderr)
        self.assertIn("only in NEW (not compared): FormB/AoS/MultiBlock/5k", completed.stdout)

    def test_a_value_lost_in_new_fails_unless_allowed(self):
        # A run of no sweeps writes no ms_per_sweep: a smoother that broke so
        # must not pass as "not compared".
        measured = dict(bench("FormB/AoS/Coloured/109k", 2.9), ms_per_sweep=0.16)
        unmeasured = dict(bench("FormB/AoS/Coloured/109k", 0.5), sweeps=0)
        steady = dict(bench("FormB/AoS/MultiBlock/109k", 1.5), ms_per_sweep=0.1)
        old = self.result("old", [measured, steady])
        new = self.result("new", [unmeasured, steady])
        completed = compare(old, new, "--metric", "ms_per_sweep")
        self.assertEqual(completed.returncode, 1, completed.stdout + completed.stderr)
        self.assertIn("without a usable ms_per_sweep in NEW", completed.stdout)
        completed = compare(old, new, "--metric", "ms_per_sweep", "--allow-missing")
        self.assertEqual(completed.returncode, 0, completed.stdout + completed.stderr)
        self.assertRegex(completed.stdout, r"warning: 1 benchmark\(s\) without a usable ms_per_sweep in NEW \(allowed\)")
        # With no value in OLD there is no baseline: listed, not a failure.
        completed = compare(new, old, "--metric", "ms_per_sweep")
        self.assertEqual(completed.returncode, 0, completed.stdout + completed.stderr)
        self.assertIn("no usable ms_per_sweep in OLD (not compared): FormB/AoS/Coloured/109k", completed.stdout)
        # A count that fell to 0 is an improvement without a ratio, not a loss.
        old = self.result("old", [dict(measured, inverted_after=25), dict(steady, inverted_after=3)])
        new = self.result("new", [dict(measured, inverted_after=0), dict(steady, inverted_after=3)])
        completed = compare(old, new, "--metric", "inverted_after")
        self.assertEqual(completed.returncode, 0, completed.stdout + completed.stderr)
        self.assertIn("FormB/AoS/Coloured/109k", completed.stdout)

    def test_a_zero_in_old_is_no_baseline_and_no_crash(self):
        # A ratio over OLD's value would divide by zero: a time of 0 (a run
        # too short to time) or a count of 0 is listed as having no baseline.
        old = self.result("old", [dict(bench("Serial/FormB/5k", 0.0), inverted_after=0),
                                  dict(bench("Serial/FormA/5k", 10.0), inverted_after=2)])
        new = self.result("new", [dict(bench("Serial/FormB/5k", 5.0), inverted_after=3),
                                  dict(bench("Serial/FormA/5k", 10.0), inverted_after=2)])
        for metric in ("real_time", "inverted_after"):
            completed = compare(old, new, "--metric", metric)
            self.assertEqual(completed.returncode, 0, completed.stdout + completed.stderr)
            self.assertNotIn("Traceback", completed.stderr)
            self.assertIn(f"no usable {metric} in OLD (not compared): Serial/FormB/5k", completed.stdout)
            self.assertEqual(printed_geomean(completed.stdout), (1.0, 1))
        # Nothing left to compare is bad input, said in a line, not a traceback.
        completed = compare(old, new, "--filter", "FormB")
        self.assertEqual(completed.returncode, 2, completed.stdout + completed.stderr)
        self.assertIn("no benchmark with a positive real_time", completed.stderr)
        self.assertNotIn("Traceback", completed.stderr)

    def test_a_value_lost_in_every_benchmark_fails(self):
        # NEW ran every benchmark of OLD but none wrote the metric (no sweep
        # anywhere): nothing is left to compare, and that is the regression
        # (exit 1), not a wrong file (exit 2).
        old = self.result("old", [dict(bench("FormB/AoS/Coloured/109k", 2.9), ms_per_sweep=0.16),
                                  dict(bench("FormB/AoS/MultiBlock/109k", 1.5), ms_per_sweep=0.1)])
        new = self.result("new", [dict(bench("FormB/AoS/Coloured/109k", 0.5), sweeps=0),
                                  dict(bench("FormB/AoS/MultiBlock/109k", 0.4), sweeps=0)])
        completed = compare(old, new, "--metric", "ms_per_sweep")
        self.assertEqual(completed.returncode, 1, completed.stdout + completed.stderr)
        self.assertRegex(completed.stdout, r"REGRESSION: 2 benchmark\(s\) without a usable ms_per_sweep in NEW")
        self.assertRegex(completed.stdout, r"geometric mean\s+—\s+\(0 benchmarks\)")

    def test_model_aliases_match(self):
        # bench_smooth --models=slope-77k names the 77k model by its generator name.
        old = self.result("old", [bench("FormB/AoS/MultiBlock/77k", 2.0)])
        new = self.result("new", [bench("FormB/AoS/MultiBlock/slope-77k", 3.0)])
        completed = compare(old, new, "--threshold", "off")
        self.assertEqual(completed.returncode, 0, completed.stdout + completed.stderr)
        self.assertEqual(printed_geomean(completed.stdout), (1.5, 1))


class ContextTests(unittest.TestCase):
    """What the two files are: GPU precision, host and CPU count."""

    def setUp(self):
        self.folder = tempfile.TemporaryDirectory()
        self.addCleanup(self.folder.cleanup)
        self.benchmarks = [bench("Serial/FormB/5k", 10.0), bench("FormB/AoS/MultiBlock/5k", 1.0)]
        self.old = write_result(self.folder.name, "old", self.benchmarks)

    def new(self, **context):
        return write_result(self.folder.name, "new", self.benchmarks, **context)

    def test_precision_mismatch_is_bad_input(self):
        new = self.new(gpu_precision="float")
        completed = compare(self.old, new)
        self.assertEqual(completed.returncode, 2, completed.stdout + completed.stderr)
        for expected in ("double", "float", "--allow-precision-mismatch"):
            self.assertIn(expected, completed.stderr)
        completed = compare(self.old, new, "--allow-precision-mismatch")
        self.assertEqual(completed.returncode, 0, completed.stdout + completed.stderr)
        self.assertIn("warning: OLD ran the GPU families in double, NEW in float", completed.stdout)
        # CPU families run in double in both files: nothing to stop.
        self.assertEqual(compare(self.old, new, "--filter", "^Serial/").returncode, 0)

    def test_copy_bandwidth_runs_in_no_gpu_precision(self):
        # The copy benchmark moves bytes, in no precision of the smoothing:
        # a filter that keeps it with the CPU runs compares across precisions.
        benchmarks = [bench("Serial/FormB/5k", 10.0), bench("Memory/CopyBandwidth", 96.0),
                      bench("FormB/AoS/MultiBlock/5k", 1.0)]
        old = write_result(self.folder.name, "old_copy", benchmarks)
        new = write_result(self.folder.name, "new_copy", benchmarks, gpu_precision="float")
        completed = compare(old, new, "--filter", "^(Serial|Memory)/")
        self.assertEqual(completed.returncode, 0, completed.stdout + completed.stderr)
        self.assertIn("Memory/CopyBandwidth", completed.stdout)
        self.assertNotIn("precision", completed.stdout + completed.stderr)
        self.assertEqual(compare(old, new, "--filter", "^Memory/").returncode, 0)
        # The GPU run does: with it the check stops.
        self.assertEqual(compare(old, new).returncode, 2)

    def test_a_run_without_gpu_families_is_missing_them_not_of_another_precision(self):
        # bench_smooth on a host without a GPU still records --precision
        # (double by default): against a float GPU run, its GPU benchmarks are
        # missing (exit 1, named), not a precision mismatch (exit 2).
        old = write_result(self.folder.name, "float", self.benchmarks, gpu_precision="float")
        new = write_result(self.folder.name, "cpu", [bench("Serial/FormB/5k", 10.0)], gpu_name=None)
        completed = compare(old, new)
        self.assertEqual(completed.returncode, 1, completed.stdout + completed.stderr)
        self.assertIn("1 benchmark(s) of OLD missing from NEW", completed.stdout)
        self.assertIn("FormB/AoS/MultiBlock/5k", completed.stdout)
        self.assertNotIn("precision", completed.stderr)

    def test_unrecorded_precision_is_a_warning(self):
        completed = compare(self.old, self.new(gpu_precision=None))
        self.assertEqual(completed.returncode, 0, completed.stdout + completed.stderr)
        self.assertIn("GPU precision not recorded", completed.stdout)

    def test_different_host_or_cpu_count_warns(self):
        for context in ({"host_name": "other"}, {"num_cpus": 64}):
            completed = compare(self.old, self.new(**context))
            self.assertEqual(completed.returncode, 0, completed.stdout + completed.stderr)
            self.assertIn("CPU baselines compare machines", completed.stdout, context)
        self.assertNotIn("warning", compare(self.old, self.new()).stdout)


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

    def test_empty_file_and_empty_benchmark_list(self):
        # bench_smooth writes a 0-byte file when --benchmark_filter/--models select nothing.
        with tempfile.TemporaryDirectory() as folder:
            empty = os.path.join(folder, "empty.json")
            open(empty, "w", encoding="utf-8").close()
            no_benchmarks = write_result(folder, "none", [])
            for path in (empty, no_benchmarks):
                for args in ((path, BASE), (BASE, path)):
                    completed = compare(*args)
                    self.assertEqual(completed.returncode, 2, completed.stdout + completed.stderr)
                    self.assertIn(path, completed.stderr)
                    self.assertIn("no benchmark ran?", completed.stderr)
                    self.assertNotIn("Traceback", completed.stderr)

    def test_nothing_in_common_and_bad_options(self):
        completed = compare(CLEAN_BASE, CLEAN_SLOWER, "--filter", "^NoSuchFamily")
        self.assertEqual(completed.returncode, 2)
        self.assertRegex(completed.stderr, r"that --filter '\^NoSuchFamily' keeps \(\d+ without it\)")
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

    def test_a_reader_that_stops_early_keeps_the_verdict(self):
        # "compare_results.py ... | head": with the pipe's read end closed
        # before the first line, every print fails; the status must still
        # say regression (1) or not (0), without a traceback.
        for new, verdict in ((CLEAN_SLOWER, 1), (CLEAN_BASE, 0)):
            process = subprocess.Popen([sys.executable, os.path.join(PLOTS, "compare_results.py"), CLEAN_BASE, new],
                                       stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
            process.stdout.close()
            stderr = process.stderr.read()
            process.stderr.close()
            self.assertEqual(process.wait(timeout=120), verdict, stderr)
            self.assertNotIn("Traceback", stderr)
            self.assertNotIn("BrokenPipeError", stderr)

    def test_times_are_said_to_be_in_ms(self):
        # The fixture's "us" entries are shown in ms like the rest.
        self.assertIn("metric: real_time (lower is better, in ms)", compare(CLEAN_BASE, CLEAN_BASE).stdout)
        self.assertIn("metric: bytes_per_s (higher is better);",
                      compare(CLEAN_BASE, CLEAN_BASE, "--metric", "bytes_per_s").stdout)

    def test_csv_that_cannot_be_written_is_bad_input(self):
        with tempfile.TemporaryDirectory() as folder:
            nowhere = os.path.join(folder, "no-such-folder", "cmp.csv")
            completed = compare(CLEAN_BASE, CLEAN_BASE, "--csv", nowhere)
            self.assertEqual(completed.returncode, 2, completed.stdout + completed.stderr)
            self.assertIn(f"--csv {nowhere}: no folder", completed.stderr)
            self.assertEqual(completed.stdout, "", "the comparison is printed only when its CSV can be written")
            completed = compare(CLEAN_BASE, CLEAN_BASE, "--csv", folder)  # a folder, not a file
            self.assertEqual(completed.returncode, 2, completed.stdout + completed.stderr)
            self.assertIn(f"--csv {folder}: cannot write", completed.stderr)
            self.assertNotIn("Traceback", completed.stderr)

    def test_a_metric_neither_file_has_is_bad_input(self):
        # A misspelt counter is not "no usable value" for every benchmark, and
        # an error in NEW must not turn it into a regression (exit 1).
        for new in (CLEAN_SLOWER, SLOWER):
            completed = compare(CLEAN_BASE, new, "--metric", "ms_per_swep")
            self.assertEqual(completed.returncode, 2, completed.stdout + completed.stderr)
            self.assertIn("--metric ms_per_swep: no benchmark of", completed.stderr)
            self.assertIn("ms_per_sweep", completed.stderr)
            self.assertIn("hist_before_N", completed.stderr)
            self.assertNotIn("hist_before_0", completed.stderr)

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
