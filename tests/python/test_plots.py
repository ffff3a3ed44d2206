#!/usr/bin/python3
"""Tests of plots/: the JSON loader, the paper's numbers, the tables and the figures.

Run: /usr/bin/python3 tests/python/test_plots.py   (CTest sets TETSMOOTH_SOURCE_DIR)
The fixture tests/data/bench_small.json is a hand-made google/benchmark 1.7.1
result with the quirks of real runs: /repeats:N, /iterations:N, /min_time:X
and /manual_time suffixes, repetitions with median/mean/stddev/cv aggregates,
a benchmark reported as an error, a time unit of "us", custom context values
as strings, two models (5k, 109k) and two lattices.  Other cases (the
slope-77k spelling, float runs, CUDA's integer version, tiny q, empty files)
are small synthetic results written by write_result().
"""

import csv
import json
import math
import os
import subprocess
import sys
import tempfile
import unittest
from unittest import mock

SOURCE_DIR = os.environ.get("TETSMOOTH_SOURCE_DIR") or os.path.dirname(
    os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
PLOTS = os.path.join(SOURCE_DIR, "plots")
FIXTURE = os.path.join(SOURCE_DIR, "tests", "data", "bench_small.json")
sys.path.insert(0, PLOTS)

import bench_json as bj  # noqa: E402
import paper_numbers as paper  # noqa: E402

FIGURES = ("fig09_layout.png", "fig10_form.png", "fig11_cpu_gpu.png", "fig12_blocks.png", "fig13_quality.png")
CSV_FILES = ("table3.csv", "table4.csv", "table5.csv", "table6.csv", "quality.csv", "scaling.csv", "colours.csv",
             "phases.csv", "runs.csv")


def run_script(script, *args):
    return subprocess.run([sys.executable, os.path.join(PLOTS, script), *args],
                          capture_output=True, text=True, timeout=300)


def read_csv(path):
    with open(path, newline="", encoding="utf-8") as handle:
        return list(csv.DictReader(handle))


def raw_fixture():
    with open(FIXTURE, encoding="utf-8") as handle:
        return json.load(handle)


def raw_entry(document, name, aggregate=None):
    """The fixture entry with this full Google Benchmark name (independent of the loader)."""
    for entry in document["benchmarks"]:
        if entry["name"] == name and entry.get("aggregate_name") == aggregate:
            return entry
    raise KeyError(name)


def entry(name, real_time, unit="ms", run_type="iteration", aggregate=None, run_name=None, **counters):
    item = {"name": name, "run_type": run_type, "real_time": real_time, "cpu_time": real_time,
            "time_unit": unit, "iterations": 1}
    if aggregate:
        item["aggregate_name"] = aggregate
    if run_name:
        item["run_name"] = run_name
    item.update(counters)
    return item


def write_result(folder, document, stem="result"):
    path = os.path.join(folder, stem + ".json")
    with open(path, "w", encoding="utf-8") as handle:
        json.dump(document, handle)
    return path


def histogram_counters(prefix, counts):
    return {f"{prefix}_{i}": c for i, c in enumerate(counts)}


# Bin counts within about one decade, as the paper models' are.
HIST_INPUT = [18288, 31000, 52000, 75000, 100000, 118000, 122000, 108000, 72000, 21000]
HIST_AFTER = [12448, 28000, 50000, 68000, 88000, 108000, 121000, 117000, 91000, 30000]


def float_document():
    """A float run of Form B on the 109k model only, with the context bench_smooth writes."""
    context = {"gpu_name": "NVIDIA H100 80GB HBM3", "gpu_precision": "float", "cuda_version": "13000",
               "sm_count": "132", "host_name": "vm", "num_cpus": 16, "git_sha": "abc123",
               "command_line": "bench_smooth --precision=float --models=109k --benchmark_repetitions=3"}
    quality = dict(q_min_before=4.611063343546083e-08, q_min_after=0.0, q_mean_before=0.55, q_mean_after=0.58)
    return {"context": context, "benchmarks": [
        entry("Serial/FormB/109k/manual_time", 4000.0, sweeps=8, **quality,
              **histogram_counters("hist_before", HIST_INPUT), **histogram_counters("hist_after", HIST_AFTER)),
        entry("Serial/Ordinary/109k/manual_time", 3000.0, sweeps=100, **quality,
              **histogram_counters("hist_before", HIST_INPUT), **histogram_counters("hist_after", HIST_AFTER)),
        entry("FormB/AoS/MultiBlock/109k/manual_time", 2.0, sweeps=8, **quality),
        entry("FormB/SoA/MultiBlock/109k/manual_time", 2.5, sweeps=8, **quality)]}


def figures_drawn(draw):
    """Run draw() with plt.close patched out; returns the figures it closed, still open, in order."""
    import make_figures
    from matplotlib.figure import Figure
    closed = []
    with mock.patch.object(make_figures.plt, "close", side_effect=closed.append):
        draw()
    # pyplot may close("all") when it first picks its backend; only figures count.
    return [f for f in closed if isinstance(f, Figure)]


class NameTests(unittest.TestCase):
    def test_suffixes_are_stripped(self):
        cases = {
            "FormB/AoS/MultiBlock/109k/repeats:5/manual_time": "FormB/AoS/MultiBlock/109k",
            "Serial/FormA/5k/iterations:1/real_time": "Serial/FormA/5k",
            "FormA/SoA/SingleBlock/5k/min_time:0.500/manual_time": "FormA/SoA/SingleBlock/5k",
            "Threads/FormB/77k/real_time/threads:8": "Threads/FormB/77k",
            "Memory/CopyBandwidth/manual_time": "Memory/CopyBandwidth",
            "FormB/SoA/Coloured/lattice-64/min_warmup_time:0.2/process_time": "FormB/SoA/Coloured/lattice-64",
            "FormB/AoS/MultiBlock/10k": "FormB/AoS/MultiBlock/10k",
        }
        for name, stripped in cases.items():
            self.assertEqual(bj.strip_name(name), stripped, name)

    def test_aggregate_name_without_run_name(self):
        item = entry("FormB/AoS/MultiBlock/5k/manual_time_median", 1.0, run_type="aggregate", aggregate="median")
        self.assertEqual(bj.entry_name(item), "FormB/AoS/MultiBlock/5k")

    def test_parse_name_kinds(self):
        self.assertEqual(bj.parse_name("FormB/SoA/Coloured/59k")["strategy"], "Coloured")
        self.assertEqual(bj.parse_name("FormA/AoS/MultiBlock/lattice-128")["lattice_n"], 128)
        self.assertEqual(bj.parse_name("Serial/Ordinary/109k")["kind"], "ordinary")
        self.assertEqual(bj.parse_name("FormA/SoA/SingleBlock/5k")["method"], "adaptive")
        gpu_ordinary = bj.parse_name("Ordinary/AoS/Coloured/lattice-215")
        self.assertEqual((gpu_ordinary["kind"], gpu_ordinary["method"], gpu_ordinary["form"]),
                         ("gpu", "ordinary", "FormB"))
        self.assertEqual(gpu_ordinary["lattice_n"], 215)
        self.assertEqual(bj.parse_name("Threads/FormA/5k")["kind"], "threads")
        self.assertEqual(bj.parse_name("Memory/CopyBandwidth")["kind"], "copy")
        self.assertEqual(bj.parse_name("FormC/AoS/MultiBlock/5k")["kind"], "other")

    def test_model_aliases(self):
        # bench_smooth --models=slope-77k puts the generator's name in the benchmark names and context.
        self.assertEqual(bj.canonical_model("slope-77k"), "77k")
        self.assertEqual(bj.canonical_model("lattice-64"), "lattice-64")
        self.assertEqual(bj.canonical_name("FormB/AoS/MultiBlock/slope-77k"), "FormB/AoS/MultiBlock/77k")
        self.assertEqual(bj.canonical_name("Memory/CopyBandwidth"), "Memory/CopyBandwidth")
        document = {"context": {"model_slope-77k_nodes": "76850", "model_slope-77k_tets": "389359"},
                    "benchmarks": [entry("Serial/FormB/slope-77k/manual_time", 1800.0),
                                   entry("FormB/AoS/MultiBlock/slope-77k/manual_time", 1.5),
                                   entry("Threads/FormB/slope-77k/manual_time", 1.0, error_occurred=True,
                                         error_message="failed")]}
        result = bj.parse_result(document)
        self.assertAlmostEqual(result.time_ms("Serial/FormB/77k"), 1800.0)
        self.assertAlmostEqual(result.time_ms("FormB/AoS/MultiBlock/77k"), 1.5)
        self.assertIn("Threads/FormB/77k", result.errors)
        self.assertEqual(result.mesh_size("77k"), (76850, 389359))

    def test_cuda_version_text(self):
        self.assertEqual(bj.cuda_version_text("13000"), "13.0")
        self.assertEqual(bj.cuda_version_text(12040), "12.4")
        self.assertEqual(bj.cuda_version_text("13.0"), "13.0")


class LoaderTests(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.result = bj.load_result(FIXTURE)

    def test_ratio_of_a_missing_or_non_positive_denominator_is_none(self):
        # A zero time (a run that did nothing measurable) must leave a blank cell, not stop the script.
        self.assertIsNone(bj.ratio(1.0, 0.0))
        self.assertIsNone(bj.ratio(1.0, -2.0))
        self.assertIsNone(bj.ratio(None, 2.0))
        self.assertEqual(bj.ratio(3.0, 2.0), 1.5)

    def test_not_skipped_is_a_result(self):
        # A "skipped" field of "NotSkipped" is the state of a run that was not skipped (the loader
        # accepts it beside false and ""): a result like any other, not an error.
        document = {"context": {}, "benchmarks": [entry("Serial/FormB/5k/manual_time", 7.0, skipped="NotSkipped")]}
        result = bj.parse_result(document)
        self.assertEqual(result.errors, {})
        self.assertAlmostEqual(result.time_ms("Serial/FormB/5k"), 7.0)

    def test_describe_names_cpus_and_copy_bandwidth_in_their_units(self):
        # 2.5e12 bytes/s is 2500.0 GB/s (1 GB = 1e9 bytes); the CPU line carries the core count.
        document = {"context": {"host_name": "vm", "num_cpus": 16},
                    "benchmarks": [entry("Memory/CopyBandwidth/manual_time", 1.0, bytes_per_s=2.5e12),
                                   entry("Serial/FormB/5k/manual_time", 7.0)]}
        lines = bj.parse_result(document).describe()
        self.assertIn("CPU: vm, 16 CPUs", lines)
        self.assertIn("measured device copy bandwidth: 2500.0 GB/s (Memory/CopyBandwidth)", lines)

    def test_context_keeps_the_first_spelling_of_a_model(self):
        # As for the benchmarks, the spelling met first wins when a context names one model twice.
        document = {"context": {"model_77k_nodes": "100", "model_77k_tets": "400",
                                "model_slope-77k_nodes": "200", "model_slope-77k_tets": "800"},
                    "benchmarks": [entry("Serial/FormB/77k/manual_time", 7.0)]}
        self.assertEqual(bj.parse_result(document).mesh_size("77k"), (100, 400))

    def test_median_aggregate_is_preferred(self):
        # Repetitions 4.10, 4.00, 4.90: median 4.10, mean 4.333.
        self.assertAlmostEqual(self.result.time_ms("FormB/AoS/MultiBlock/5k"), 4.10)
        self.assertEqual(self.result.run("FormB/AoS/MultiBlock/5k").statistic, "median of 3")

    def test_single_runs_and_time_unit(self):
        self.assertAlmostEqual(self.result.time_ms("FormA/AoS/MultiBlock/109k"), 38.0)
        self.assertAlmostEqual(self.result.time_ms("Memory/CopyBandwidth"), 96.2e-3)  # written in us

    def test_errors_are_left_out(self):
        self.assertNotIn("Threads/FormA/109k", self.result.runs)
        self.assertIn("Threads/FormA/109k", self.result.errors)

    def test_counters_and_context(self):
        self.assertEqual(self.result.counter("Serial/Ordinary/109k", "hist_after_0"), 2050)
        self.assertIsNone(self.result.counter("Serial/Ordinary/109k", "no_such_counter"))
        self.assertEqual(self.result.context_number("sm_count"), 132)
        self.assertEqual(self.result.mesh_size("109k"), (109260, 702315))
        self.assertEqual(self.result.mesh_size("lattice-16"), (4913, 24576))
        self.assertEqual(self.result.device_label(), "NVIDIA H100 80GB HBM3")

    def test_mean_of_iterations_without_aggregates(self):
        document = {"context": {}, "benchmarks": [
            entry("Serial/FormB/5k/real_time", 10.0, sweeps=40),
            entry("Serial/FormB/5k/real_time", 14.0, sweeps=44),
            entry("FormB/AoS/MultiBlock/5k/manual_time", 2000.0, unit="us", unknown_field="text"),
            entry("FormA/AoS/MultiBlock/5k/manual_time", 0.5, unit="s")]}
        result = bj.parse_result(document)
        self.assertAlmostEqual(result.time_ms("Serial/FormB/5k"), 12.0)
        self.assertAlmostEqual(result.counter("Serial/FormB/5k", "sweeps"), 42.0)
        self.assertEqual(result.run("Serial/FormB/5k").statistic, "mean of 2")
        self.assertAlmostEqual(result.time_ms("FormB/AoS/MultiBlock/5k"), 2.0)
        self.assertAlmostEqual(result.time_ms("FormA/AoS/MultiBlock/5k"), 500.0)
        self.assertIsNone(result.counter("FormB/AoS/MultiBlock/5k", "unknown_field"))

    def test_median_from_name_only_aggregates(self):
        document = {"benchmarks": [
            entry("X/manual_time_mean", 3.0, run_type="aggregate", aggregate="mean"),
            entry("X/manual_time_median", 2.0, run_type="aggregate", aggregate="median"),
            entry("X/manual_time_cv", 0.1, run_type="aggregate", aggregate="cv")]}
        self.assertAlmostEqual(bj.parse_result(document).time_ms("X"), 2.0)

    def test_bad_input(self):
        with tempfile.TemporaryDirectory() as folder:
            bad = os.path.join(folder, "bad.json")
            with open(bad, "w", encoding="utf-8") as handle:
                handle.write("{\"benchmarks\": [")
            not_gbench = os.path.join(folder, "other.json")
            with open(not_gbench, "w", encoding="utf-8") as handle:
                handle.write("[1, 2]")
            for path in (os.path.join(folder, "missing.json"), bad, not_gbench):
                with self.assertRaises(bj.BenchInputError) as caught:
                    bj.load_result(path)
                self.assertIn(path, str(caught.exception))

    def test_a_file_cut_off_by_a_stopped_run_says_so(self):
        # Google Benchmark writes one field a line as each result finishes: a
        # killed run ends after a result, or inside one.
        with open(FIXTURE, encoding="utf-8") as handle:
            text = handle.read()
        after_result = text.index("\n    },", text.index("\"benchmarks\"")) + len("\n    }")
        inside_name = text.index("\"name\": \"FormB/") + len("\"name\": \"For")
        with tempfile.TemporaryDirectory() as folder:
            for stem, cut in (("after_result", after_result), ("inside_name", inside_name)):
                path = os.path.join(folder, stem + ".json")
                with open(path, "w", encoding="utf-8") as handle:
                    handle.write(text[:cut] + "\n")
                message = str(self.load_error(path))
                self.assertIn(f"{path}: the JSON ends before it is complete", message)
                self.assertIn("stopped early", message)
            # A mistake inside the file is still bad JSON, where it is.
            broken = os.path.join(folder, "broken.json")
            with open(broken, "w", encoding="utf-8") as handle:
                handle.write(text.replace("\"benchmarks\"", "benchmarks", 1))
            self.assertIn("bad JSON at line", str(self.load_error(broken)))
            self.assertIn(f"{folder}: a folder, not a result file", str(self.load_error(folder)))

    def test_a_console_or_csv_report_is_not_taken_for_json(self):
        # bench_smooth > new.json keeps the console report, which starts with the date.
        with tempfile.TemporaryDirectory() as folder:
            path = os.path.join(folder, "console.json")
            with open(path, "w", encoding="utf-8") as handle:
                handle.write("2026-11-28T04:40:26+00:00\nRunning build/bench/bench_smooth\n")
            message = str(self.load_error(path))
            self.assertIn(f"{path}: not JSON (it starts '2026-11-28T04:40:26+00:00')", message)
            self.assertIn("--benchmark_out=FILE --benchmark_out_format=json", message)

    def test_empty_file_and_no_benchmarks(self):
        # bench_smooth writes a 0-byte file when nothing was selected.
        with tempfile.TemporaryDirectory() as folder:
            paths = [os.path.join(folder, "empty.json"), os.path.join(folder, "blank.json"),
                     write_result(folder, {"context": {}, "benchmarks": []}, "none")]
            open(paths[0], "w", encoding="utf-8").close()
            with open(paths[1], "w", encoding="utf-8") as handle:
                handle.write("\n  \n")
            for path in paths:
                with self.assertRaises(bj.BenchInputError) as caught:
                    bj.load_result(path)
                self.assertIn(path, str(caught.exception))
                self.assertIn("check --benchmark_filter/--models", str(caught.exception))
            self.assertIn("empty file", str(self.load_error(paths[0])))

    def test_every_benchmark_errored(self):
        # Tables of nothing but blanks would hide the failure: the file is refused.
        entry = {"name": "Serial/FormB/5k/real_time", "run_type": "iteration", "error_occurred": True,
                 "error_message": "mesh not found"}
        # The copy-bandwidth run beside it is nothing to render either; nor is
        # a file of aggregates alone, which has neither runs nor errors.
        copy = {"name": "Memory/CopyBandwidth/manual_time", "run_type": "iteration", "real_time": 0.7,
                "time_unit": "ms", "bytes_per_s": 2.9e12}
        aggregate = {"name": "Serial/FormB/5k/real_time_stddev", "run_type": "aggregate", "aggregate_name": "stddev",
                     "real_time": 1.0, "time_unit": "ms"}
        with tempfile.TemporaryDirectory() as folder:
            path = write_result(folder, {"context": {}, "benchmarks": [entry, copy]}, "errored")
            self.assertEqual(bj.load_result(path).errors, {"Serial/FormB/5k": "mesh not found"})
            self.assertIn("every smoothing benchmark reported an error (1; the first, Serial/FormB/5k: mesh not found)",
                          str(self.load_error(path, need_runs=True)))
            bare = write_result(folder, {"context": {}, "benchmarks": [aggregate]}, "aggregates")
            self.assertIsNone(self.load_error(bare))
            self.assertIn("no smoothing benchmark with a result", str(self.load_error(bare, need_runs=True)))

    @staticmethod
    def load_error(path, need_runs=False):
        try:
            bj.load_result(path, need_runs=need_runs)
        except bj.BenchInputError as error:
            return error
        return None


class PaperNumberTests(unittest.TestCase):
    def test_speedups_match_published_times(self):
        # Tables 5-6 were printed from Tables 3-4: speedup = CPU / GPU within rounding.
        for form in bj.FORMS:
            for model in paper.MODELS:
                cpu = paper.time_ms(form, "cpu", model)
                for column in paper.SPEEDUP_COLUMNS[:4]:
                    expected = cpu / paper.time_ms(form, column, model)
                    self.assertAlmostEqual(paper.speedup(form, column, model) / expected, 1.0, delta=2e-3,
                                           msg=f"{form} {model} {column}")
                four = [paper.speedup(form, c, model) for c in paper.SPEEDUP_COLUMNS[:4]]
                self.assertAlmostEqual(paper.speedup(form, "max", model), max(four), places=3)

    def test_table_2_model_sizes(self):
        # Typed from the paper's Table 2 (nodes, tetrahedra); the tables put these beside our meshes' sizes,
        # and nothing else in paper_numbers.py cross-checks them.
        table_2 = {"5k": (5000, 32978), "10k": (10000, 66542), "59k": (59261, 391220),
                   "77k": (76928, 388428), "109k": (109260, 727088)}
        self.assertEqual(paper.MODEL_SIZES, table_2)

    def test_serial_cpu_column(self):
        # Typed from the CPU column of Tables 3-4.  The speedup check above allows 0.2 %, so a CPU time
        # off by a digit in both forms (15,852 for 15,825) would pass it.
        cpu = {"5k": 1473, "10k": 3745, "59k": 8452, "77k": 15825, "109k": 36592}
        for form in bj.FORMS:
            self.assertEqual({model: paper.time_ms(form, "cpu", model) for model in paper.MODELS}, cpu, form)

    def test_table_numbers_by_form(self):
        # Running time: Table 3 is Form A, Table 4 Form B; speedup: Table 5 Form A, Table 6 Form B.
        # Headings and figure titles name the table by these numbers.
        self.assertEqual(paper.TABLE_NUMBER, {"time": {"FormA": 3, "FormB": 4}, "speedup": {"FormA": 5, "FormB": 6}})

    def test_spot_values(self):
        self.assertEqual(paper.time_ms("FormA", "soa_multi", "59k"), 1254)
        self.assertEqual(paper.time_ms("FormB", "aos_multi", "109k"), 1618)
        self.assertEqual(paper.SPEEDUP["FormB"]["77k"], (13.366, 22.447, 12.530, 13.411, 22.447))
        self.assertEqual(paper.SPEEDUP["FormB"]["109k"], (10.261, 22.620, 8.389, 16.409, 22.620))
        self.assertEqual(paper.MODEL_SIZES["77k"], (76928, 388428))
        self.assertIsNone(paper.time_ms("FormB", "aos_coloured", "5k"))
        for model in paper.MODELS:
            self.assertEqual(paper.time_ms("FormA", "cpu", model), paper.time_ms("FormB", "cpu", model))


class ReportTests(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.folder = tempfile.TemporaryDirectory()
        cls.out = cls.folder.name
        cls.completed = run_script("report.py", FIXTURE, cls.out)
        cls.document = raw_fixture()

    @classmethod
    def tearDownClass(cls):
        cls.folder.cleanup()

    def table(self, stem):
        return {row["model"]: row for row in read_csv(os.path.join(self.out, f"{stem}.csv"))}

    def median(self, full_name):
        return raw_entry(self.document, full_name + "_median", "median")["real_time"]

    def single(self, full_name):
        return raw_entry(self.document, full_name)["real_time"]

    def test_report_succeeds_and_writes_everything(self):
        self.assertEqual(self.completed.returncode, 0, self.completed.stderr)
        for name in CSV_FILES + FIGURES + ("tables.md",):
            self.assertTrue(os.path.isfile(os.path.join(self.out, name)), name)

    def test_report_lists_every_file_it_wrote(self):
        # publish_results.sh shows this list as what was filed: tables and figures alike.
        listed = [os.path.basename(line) for line in self.completed.stdout.splitlines()[1:]]
        self.assertEqual(sorted(listed), sorted(CSV_FILES + FIGURES + ("tables.md",)))

    def test_report_passes_metric_and_quality_model_on(self):
        # --metric picks the time of the tables as of the figures, and --quality-model the model of
        # Figure 13; here cpu_time is 1.5 times real_time, and 5k is not the default 109k.
        import report
        document = raw_fixture()
        for item in document["benchmarks"]:
            if item["name"].startswith("FormB/AoS/MultiBlock/5k"):
                item["cpu_time"] = item["real_time"] * 1.5
        with tempfile.TemporaryDirectory() as out:
            path = write_result(out, document)
            with mock.patch("sys.stdout"), mock.patch("sys.stderr"):
                figures = figures_drawn(lambda: report.main([path, out, "--metric", "cpu_time",
                                                             "--quality-model", "5k"]))
            try:
                self.assertIn("model 5k", figures[-1]._suptitle.get_text())
            finally:
                for figure in figures:
                    report.make_figures.plt.close(figure)
            row = {r["model"]: r for r in read_csv(os.path.join(out, "table4.csv"))}["5k"]
            loaded = bj.load_result(path)
        cpu = loaded.time_ms("FormB/AoS/MultiBlock/5k", "cpu_time")
        self.assertNotAlmostEqual(cpu, loaded.time_ms("FormB/AoS/MultiBlock/5k", "real_time"))
        self.assertAlmostEqual(float(row["aos_multi_ms"]), cpu, places=6)

    def test_report_says_how_many_benchmarks_failed(self):
        # The fixture has one benchmark that reported an error; a run without any says nothing of errors.
        self.assertIn("report: 1 benchmark(s) reported errors", self.completed.stderr)
        with tempfile.TemporaryDirectory() as out:
            clean = run_script("report.py", write_result(out, float_document()), out)
        self.assertEqual(clean.returncode, 0, clean.stderr)
        self.assertNotIn("reported errors", clean.stderr)

    def test_time_table_columns_and_values(self):
        rows = read_csv(os.path.join(self.out, "table4.csv"))
        self.assertEqual(list(rows[0].keys()), [
            "model", "nodes", "tets", "cpu_serial_ms", "aos_single_ms", "aos_multi_ms", "soa_single_ms",
            "soa_multi_ms", "cpu_threads_ms", "aos_coloured_ms", "soa_coloured_ms", "paper_nodes", "paper_tets",
            "paper_cpu_serial_ms", "paper_aos_single_ms", "paper_aos_multi_ms", "paper_soa_single_ms",
            "paper_soa_multi_ms"])
        self.assertEqual([r["model"] for r in rows], list(bj.MODELS))
        table = {r["model"]: r for r in rows}
        self.assertAlmostEqual(float(table["109k"]["aos_multi_ms"]),
                               self.median("FormB/AoS/MultiBlock/109k/repeats:3/manual_time"))
        self.assertAlmostEqual(float(table["5k"]["cpu_serial_ms"]), self.median("Serial/FormB/5k/real_time"))
        self.assertEqual(table["5k"]["soa_single_ms"], "")  # not run
        self.assertEqual(table["10k"]["cpu_serial_ms"], "")  # model not run
        self.assertEqual(float(table["109k"]["paper_aos_multi_ms"]), 1618)
        self.assertEqual(float(table["59k"]["paper_nodes"]), 59261)

    def test_speedup_equals_serial_over_gpu(self):
        table5, table6 = self.table("table5"), self.table("table6")
        serial_b = self.median("Serial/FormB/109k/real_time")
        gpu_b = self.median("FormB/SoA/MultiBlock/109k/repeats:3/manual_time")
        threads_b = self.median("Threads/FormB/109k/real_time")
        self.assertAlmostEqual(float(table6["109k"]["soa_multi"]), serial_b / gpu_b, places=6)
        self.assertAlmostEqual(float(table6["109k"]["soa_multi_vs_threads"]), threads_b / gpu_b, places=6)
        self.assertAlmostEqual(float(table6["109k"]["threads_over_serial"]), serial_b / threads_b, places=6)
        serial_a = self.single("Serial/FormA/5k/iterations:1/real_time")
        gpu_a = self.single("FormA/SoA/SingleBlock/5k/min_time:0.500/manual_time")
        self.assertAlmostEqual(float(table5["5k"]["soa_single"]), serial_a / gpu_a, places=6)
        four = [float(table6["5k"][k]) for k in ("aos_single", "aos_multi", "soa_multi")]
        self.assertAlmostEqual(float(table6["5k"]["max"]), max(four), places=6)
        self.assertEqual(float(table6["109k"]["paper_aos_multi"]), 22.620)
        self.assertEqual(float(table5["10k"]["paper_max"]), 11.31)
        self.assertEqual(table5["109k"]["cpu_threads_ms"], "")  # the error entry

    def test_quality_table(self):
        rows = {r["benchmark"]: r for r in read_csv(os.path.join(self.out, "quality.csv"))}
        ordinary = rows["Serial/Ordinary/109k"]
        self.assertEqual(int(float(ordinary["inverted_after"])), 17)
        self.assertEqual(int(float(ordinary["low_q_before"])), 1490)
        adaptive = rows["FormB/AoS/MultiBlock/109k"]
        self.assertGreater(float(adaptive["q_min_after"]), float(adaptive["q_min_before"]))
        self.assertNotIn("Memory/CopyBandwidth", rows)

    def test_scaling_table_memory_floor(self):
        rows = {r["benchmark"]: r for r in read_csv(os.path.join(self.out, "scaling.csv"))}
        copy_bw = raw_entry(self.document, "Memory/CopyBandwidth/manual_time")["bytes_per_s"]
        lattice = rows["FormB/AoS/MultiBlock/lattice-32"]
        self.assertEqual(lattice["lattice_n"], "32")
        raw = raw_entry(self.document, "FormB/AoS/MultiBlock/lattice-32/manual_time")
        bytes_per_sweep = raw["bytes_per_s"] * raw["ms_per_sweep"] / 1000
        floor_ms = bytes_per_sweep / copy_bw * 1000
        self.assertAlmostEqual(float(lattice["bytes_per_sweep"]) / bytes_per_sweep, 1.0, places=6)
        self.assertAlmostEqual(float(lattice["floor_ms_per_sweep"]) / floor_ms, 1.0, places=6)
        self.assertAlmostEqual(float(lattice["ratio_to_floor"]), raw["ms_per_sweep"] / floor_ms, places=4)
        names = list(rows)
        self.assertLess(names.index("FormB/AoS/MultiBlock/109k"), names.index("FormB/AoS/MultiBlock/lattice-16"))
        self.assertLess(names.index("FormB/AoS/MultiBlock/lattice-16"), names.index("FormB/AoS/MultiBlock/lattice-32"))
        # The ordinary Laplacian run follows the adaptive ones, its own floor beside it.
        ordinary = rows["Ordinary/AoS/MultiBlock/lattice-32"]
        self.assertEqual((ordinary["method"], ordinary["form"]), ("ordinary", "FormB"))
        self.assertEqual(lattice["method"], "adaptive")
        self.assertEqual(names[-1], "Ordinary/AoS/MultiBlock/lattice-32")
        raw = raw_entry(self.document, "Ordinary/AoS/MultiBlock/lattice-32/manual_time")
        floor_ms = raw["bytes_per_s"] * raw["ms_per_sweep"] / copy_bw
        self.assertAlmostEqual(float(ordinary["ratio_to_floor"]), raw["ms_per_sweep"] / floor_ms, places=4)

    def test_phase_table(self):
        rows = {r["benchmark"]: r for r in read_csv(os.path.join(self.out, "phases.csv"))}
        # Only the fixture's MultiBlock runs that carry a phase run have rows.
        self.assertEqual(sorted(rows), ["FormB/AoS/MultiBlock/lattice-32", "Ordinary/AoS/MultiBlock/lattice-32"])
        raw = raw_entry(self.document, "FormB/AoS/MultiBlock/lattice-32/manual_time")
        row = rows["FormB/AoS/MultiBlock/lattice-32"]
        self.assertAlmostEqual(float(row["ms_per_sweep"]), raw["ms_per_sweep"])
        self.assertAlmostEqual(float(row["phase_run_ms_per_sweep"]), raw["phase_run_ms_per_sweep"])
        kernels = 0.0
        for phase in ("tet_quality", "node_update", "stopping_rule"):
            self.assertAlmostEqual(float(row[phase]), raw[f"phase_ms_per_sweep_{phase}"])
            kernels += raw[f"phase_ms_per_sweep_{phase}"]
        self.assertEqual(row["repair"], "")  # a Form B run has no repair kernels
        # The run's own remainder where the benchmark wrote it, else the difference of the counters.
        self.assertAlmostEqual(float(row["rest"]), raw["phase_run_rest_ms_per_sweep"])
        self.assertNotAlmostEqual(float(row["rest"]), raw["phase_run_ms_per_sweep"] - kernels)
        self.assertAlmostEqual(float(row["node_update_share"]),
                               raw["phase_ms_per_sweep_node_update"] / raw["phase_run_ms_per_sweep"])
        ordinary = rows["Ordinary/AoS/MultiBlock/lattice-32"]
        self.assertEqual(ordinary["tet_quality"], "")  # ordinary smoothing keeps no quality cache
        raw = raw_entry(self.document, "Ordinary/AoS/MultiBlock/lattice-32/manual_time")
        self.assertAlmostEqual(float(ordinary["rest"]), raw["phase_run_ms_per_sweep"]
                               - raw["phase_ms_per_sweep_node_update"] - raw["phase_ms_per_sweep_stopping_rule"])
        with open(os.path.join(self.out, "tables.md"), encoding="utf-8") as handle:
            self.assertIn("kernel by kernel", handle.read())

    def test_colour_table(self):
        rows = read_csv(os.path.join(self.out, "colours.csv"))
        median = raw_entry(self.document, "FormB/AoS/Coloured/5k/repeats:3/manual_time_median", "median")
        mine = [r for r in rows if r["benchmark"] == "FormB/AoS/Coloured/5k"]
        self.assertEqual([int(r["colour"]) for r in mine], list(range(int(median["colours"]))))
        total = sum(median[f"colour_ms_{k}"] for k in range(int(median["colours"])))
        for k, row in enumerate(mine):
            ms, nodes = median[f"colour_ms_{k}"], median[f"colour_nodes_{k}"]
            self.assertAlmostEqual(float(row["ms"]), ms)
            self.assertEqual(int(float(row["nodes"])), nodes)
            self.assertAlmostEqual(float(row["share"]), ms / total)
            self.assertAlmostEqual(float(row["us_per_sweep"]), 1000 * ms / median["sweeps"])
            self.assertAlmostEqual(float(row["ns_per_node"]), 1e6 * ms / median["sweeps"] / nodes)
        # A coloured run without per-colour times (the fixture's 109k entries) has no rows.
        self.assertFalse([r for r in rows if r["benchmark"] == "FormB/AoS/Coloured/109k"])

    def test_markdown_names_device_and_paper(self):
        with open(os.path.join(self.out, "tables.md"), encoding="utf-8") as handle:
            text = handle.read()
        context = self.document["context"]
        for expected in (context["gpu_name"], context["git_sha"], "132 SMs", "CUDA 13.0",
                         "paper: NVIDIA Quadro P6000", "Table 3", "Table 6", "22.620", "—",
                         "Threads/FormA/109k: not measured"):
            self.assertIn(expected, text)
        # The fixture predates gpu_precision: the header says so rather than guess.
        self.assertIn("not recorded", text.splitlines()[0])

    def test_report_docstring_lists_every_file(self):
        import report
        for name in sorted(os.listdir(self.out)):
            self.assertIn(name, report.__doc__)

    def test_docstrings_cite_existing_results(self):
        import re
        citations = 0
        for script in sorted(os.listdir(PLOTS)):
            if script.endswith(".py"):
                with open(os.path.join(PLOTS, script), encoding="utf-8") as handle:
                    for cited in re.findall(r"results/[\w.-]+/[\w.]+\.json", handle.read()):
                        citations += 1
                        self.assertTrue(os.path.isfile(os.path.join(SOURCE_DIR, cited)), f"{script}: {cited}")
        self.assertGreater(citations, 0, "no docstring cites a result file: the pattern no longer matches")

    def test_figures_are_real_pngs(self):
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.image as mpimg
        for name in FIGURES:
            path = os.path.join(self.out, name)
            with open(path, "rb") as handle:
                self.assertEqual(handle.read(8), b"\x89PNG\r\n\x1a\n", name)
            self.assertGreater(os.path.getsize(path), 20000, name)
            pixels = mpimg.imread(path)
            self.assertGreater(pixels.shape[0], 300)
            self.assertGreater(float(pixels.std()), 0.01, f"{name} looks blank")


class PrecisionAndFormattingTests(unittest.TestCase):
    """A float run, CUDA's version integer and tiny q values, as bench_smooth writes them."""

    @classmethod
    def setUpClass(cls):
        cls.folder = tempfile.TemporaryDirectory()
        cls.path = write_result(cls.folder.name, float_document(), "bench_float")
        cls.result = bj.load_result(cls.path)
        cls.completed = run_script("report.py", cls.path, cls.folder.name)
        with open(os.path.join(cls.folder.name, "tables.md"), encoding="utf-8") as handle:
            cls.markdown = handle.read()

    @classmethod
    def tearDownClass(cls):
        cls.folder.cleanup()

    def test_tables_state_precision_and_cuda_version(self):
        self.assertEqual(self.completed.returncode, 0, self.completed.stderr)
        self.assertIn("float", self.markdown.splitlines()[0])
        self.assertIn("CUDA 13.0", self.markdown)
        self.assertNotIn("13000", self.markdown)

    def test_report_prints_precision(self):
        self.assertIn("precision: GPU runs in float", self.completed.stdout)

    def test_tables_give_the_command_that_made_the_result(self):
        self.assertIn("command: `bench_smooth --precision=float --models=109k --benchmark_repetitions=3`",
                      self.markdown)
        # A result from before bench_smooth recorded it says nothing of one.
        with open(FIXTURE, encoding="utf-8") as handle:
            self.assertNotIn("command_line", handle.read())
        self.assertFalse([line for line in bj.load_result(FIXTURE).describe() if line.startswith("command")])

    def test_figure_titles_state_precision(self):
        import make_figures
        with tempfile.TemporaryDirectory() as out:
            figures = figures_drawn(lambda: make_figures.write_figures(self.result, out))
        try:
            self.assertEqual(len(figures), 5)
            for figure in figures[:4]:
                self.assertIn("(float)", figure._suptitle.get_text())
                self.assertIn("(float)", figure.axes[0].get_title())
            self.assertIn("double", figures[4]._suptitle.get_text())  # serial CPU runs
        finally:
            for figure in figures:
                make_figures.plt.close(figure)

    def test_tiny_q_min_is_visible(self):
        line = next(l for l in self.markdown.splitlines() if l.startswith("| Serial/FormB/109k |"))
        self.assertIn("| 4.611e-08 | 0 |", line)
        self.assertNotIn("0.0000", line)

    def test_ratio_row_has_one_scale(self):
        # Form A has only the paper's ratios (narrow span), Form B ours too (serial / GPU ~2000):
        # both ratio panels must still share one scale.
        import make_figures
        with tempfile.TemporaryDirectory() as out:
            figures = figures_drawn(lambda: make_figures.fig11_cpu_gpu(self.result, out, "real_time"))
        try:
            axes = figures[0].axes
            self.assertEqual(len(axes), 6)
            self.assertEqual({ax.get_yscale() for ax in axes[4:]}, {"log"})
            self.assertEqual(len({ax.get_yscale() for ax in axes[:4]}), 1)
            self.assertIn("log scale", axes[4].get_ylabel())
        finally:
            make_figures.plt.close(figures[0])

    def test_histogram_axis_has_several_ticks(self):
        import make_figures
        with tempfile.TemporaryDirectory() as out:
            figures = figures_drawn(lambda: make_figures.fig13_quality(self.result, out, "109k"))
        try:
            figure = figures[0]
            figure.canvas.draw()
            ax = figure.axes[0]
            low, high = ax.get_ylim()
            labelled = [t for t in ax.yaxis.get_major_ticks()
                        if low <= t.get_loc() <= high and t.label1.get_visible() and t.label1.get_text()]
            self.assertGreaterEqual(len(labelled), 3, [t.label1.get_text() for t in labelled])
        finally:
            make_figures.plt.close(figures[0])


class FigureDataTests(unittest.TestCase):
    """What the figures plot, read back from their lines: each ratio is the quotient its label names,
    the paper's rows carry the paper's numbers, and the panels name the paper's table."""

    # Our GPU times on 5k: SoA 3x AoS, Form A 2x Form B, single 2x multi 4x coloured; distinct enough
    # that any swapped quotient gives another number.
    STRATEGY_MS = {"SingleBlock": 8.0, "MultiBlock": 4.0, "Coloured": 2.0}
    SERIAL_MS = {"FormA": 800.0, "FormB": 400.0}
    THREADS_MS = {"FormA": 100.0, "FormB": 80.0}

    @classmethod
    def gpu_ms(cls, form, layout, strategy):
        return cls.STRATEGY_MS[strategy] * (3.0 if layout == "SoA" else 1.0) * (2.0 if form == "FormA" else 1.0)

    @classmethod
    def setUpClass(cls):
        benchmarks = []
        for form in bj.FORMS:
            benchmarks.append(entry(f"Serial/{form}/5k/manual_time", cls.SERIAL_MS[form]))
            benchmarks.append(entry(f"Threads/{form}/5k/manual_time", cls.THREADS_MS[form]))
            for layout in bj.LAYOUTS:
                for strategy in bj.STRATEGIES:
                    benchmarks.append(entry(f"{form}/{layout}/{strategy}/5k/manual_time",
                                            cls.gpu_ms(form, layout, strategy)))
        cls.result = bj.parse_result({"context": {"gpu_name": "GPU X", "gpu_precision": "double"},
                                      "benchmarks": benchmarks})

    def draw(self, name):
        import make_figures
        with tempfile.TemporaryDirectory() as out:
            figures = figures_drawn(lambda: getattr(make_figures, name)(self.result, out, "real_time"))
        self.addCleanup(make_figures.plt.close, figures[0])
        return figures[0].axes  # row-major: 2 panels of ours, 2 of the paper's, 2 of ratios

    def first_value(self, ax, label):
        """y at the 5k tick of the line labelled `label`."""
        lines = [line for line in ax.lines if line.get_label() == label]
        self.assertEqual(len(lines), 1, f"{label} in {[line.get_label() for line in ax.lines]}")
        return float(lines[0].get_ydata()[0])

    def test_layout_ratio_is_soa_over_aos(self):
        axes = self.draw("fig09_layout")
        self.assertAlmostEqual(self.first_value(axes[4], "ours multi"), 3.0)  # Form A panel
        self.assertAlmostEqual(self.first_value(axes[4], "paper multi"), 139 / 467)  # Table 3, 5k
        # The middle row is the paper's own times for the layout its legend names (Table 3, 5k).
        self.assertEqual(self.first_value(axes[2], "SoA single"), 151)
        self.assertEqual(self.first_value(axes[2], "AoS multi"), 467)

    def test_time_panels_name_tables_3_and_4(self):
        for name in ("fig09_layout", "fig11_cpu_gpu", "fig12_blocks"):
            axes = self.draw(name)
            self.assertIn("(Table 3)", axes[2].get_title(), name)  # Form A
            self.assertIn("(Table 4)", axes[3].get_title(), name)  # Form B

    def test_form_ratio_is_form_a_over_form_b(self):
        axes = self.draw("fig10_form")
        self.assertAlmostEqual(self.first_value(axes[4], "ours single"), 2.0)  # AoS panel
        self.assertAlmostEqual(self.first_value(axes[4], "paper single"), 450 / 169)  # Tables 3-4, AoS single

    def test_speedups_are_serial_over_the_fastest(self):
        axes = self.draw("fig11_cpu_gpu")
        self.assertAlmostEqual(self.first_value(axes[4], "ours: best GPU over serial"), 800.0 / 4.0)  # coloured AoS
        self.assertAlmostEqual(self.first_value(axes[4], "ours: threads over serial"), 800.0 / 100.0)
        # The paper's best over serial is the Max column of its Table 5 (10.597 for 5k, Form A).
        self.assertAlmostEqual(self.first_value(axes[4], "paper: best GPU over serial"), 10.597, delta=0.01)
        self.assertAlmostEqual(self.first_value(axes[5], "paper: best GPU over serial"), 15.344, delta=0.01)
        self.assertEqual(self.first_value(axes[3], "CPU serial"), 1473)

    def test_block_ratios_are_single_over_the_other(self):
        axes = self.draw("fig12_blocks")
        self.assertAlmostEqual(self.first_value(axes[4], "ours AoS: single / multi"), 2.0)
        self.assertAlmostEqual(self.first_value(axes[4], "ours AoS: single / coloured"), 4.0)
        self.assertAlmostEqual(self.first_value(axes[4], "paper AoS: single / multi"), 450 / 467)

    def test_model_ticks_follow_the_models(self):
        # The values are plotted in bj.MODELS order; the tick under each must name that model.
        axes = self.draw("fig09_layout")
        labels = [tick.get_text().split("\n")[0] for tick in axes[0].get_xticklabels()]
        self.assertEqual(labels, list(bj.MODELS))

    def test_time_rows_share_limits_that_hold_every_value(self):
        # Ours (a few ms) and the paper's (hundreds to thousands of ms) share one y range, so the two
        # devices compare by eye; that range must hold every value of either row.
        axes = self.draw("fig09_layout")[:4]
        self.assertEqual(len({ax.get_ylim() for ax in axes}), 1)
        low, high = axes[0].get_ylim()
        for ax in axes:
            for line in ax.lines:
                for y in line.get_ydata():
                    if not math.isnan(y):
                        self.assertTrue(low <= y <= high, f"{line.get_label()}: {y} outside {low}..{high}")

    def test_quality_panels_show_their_own_histograms(self):
        import make_figures
        ordinary = [900, 800, 700, 600, 500, 400, 300, 200, 100, 50]
        adaptive = [5, 10, 20, 40, 80, 160, 320, 640, 1280, 2560]
        document = {"context": {}, "benchmarks": [
            entry("Serial/FormB/5k/manual_time", 1.0, **histogram_counters("hist_before", HIST_INPUT),
                  **histogram_counters("hist_after", adaptive)),
            entry("Serial/Ordinary/5k/manual_time", 1.0, **histogram_counters("hist_before", HIST_INPUT),
                  **histogram_counters("hist_after", ordinary))]}
        result = bj.parse_result(document)
        with tempfile.TemporaryDirectory() as out:
            figures = figures_drawn(lambda: make_figures.fig13_quality(result, out, "5k"))
        self.addCleanup(make_figures.plt.close, figures[0])
        axes = figures[0].axes
        self.assertIn("ordinary", axes[1].get_title())
        self.assertIn("adaptive", axes[2].get_title())
        self.assertEqual([p.get_height() for p in axes[0].patches], HIST_INPUT)
        self.assertEqual([p.get_height() for p in axes[1].patches], ordinary)
        self.assertEqual([p.get_height() for p in axes[2].patches], adaptive)


class OptionAndEdgeTests(unittest.TestCase):
    def test_missing_result_exits_2(self):
        with tempfile.TemporaryDirectory() as out:
            for script in ("report.py", "make_tables.py", "make_figures.py"):
                completed = run_script(script, os.path.join(out, "missing.json"), os.path.join(out, "x"))
                self.assertEqual(completed.returncode, 2, script)
                self.assertIn("no such file", completed.stderr)
            self.assertFalse(os.path.exists(os.path.join(out, "x")))

    def test_empty_result_exits_2(self):
        with tempfile.TemporaryDirectory() as out:
            empty = os.path.join(out, "empty.json")
            open(empty, "w", encoding="utf-8").close()
            errored = write_result(out, {"context": {}, "benchmarks": [
                {"name": "Serial/FormB/5k/real_time", "run_type": "iteration", "error_occurred": True,
                 "error_message": "mesh not found"}]}, "errored")
            bare = write_result(out, {"context": {}, "benchmarks": [
                {"name": "Serial/FormB/5k/real_time_stddev", "run_type": "aggregate", "aggregate_name": "stddev",
                 "real_time": 1.0, "time_unit": "ms"}]}, "aggregates")
            for script in ("report.py", "make_tables.py", "make_figures.py"):
                for path, why in ((empty, "empty file"), (errored, "every smoothing benchmark reported an error"),
                                  (bare, "no smoothing benchmark with a result")):
                    completed = run_script(script, path, os.path.join(out, "x"))
                    self.assertEqual(completed.returncode, 2, script)
                    self.assertIn(f"{path}: {why}", completed.stderr)
                    self.assertNotIn("Traceback", completed.stderr)
            self.assertFalse(os.path.exists(os.path.join(out, "x")))

    def test_an_output_folder_that_cannot_be_made_exits_2(self):
        with tempfile.TemporaryDirectory() as out:
            blocker = os.path.join(out, "a file")
            open(blocker, "w", encoding="utf-8").close()
            inside = os.path.join(blocker, "results")
            for script in ("report.py", "make_tables.py", "make_figures.py"):
                completed = run_script(script, FIXTURE, inside)
                self.assertEqual(completed.returncode, 2, script)
                self.assertIn(f"{script[:-3]}: cannot write into {inside}", completed.stderr)
                self.assertNotIn("Traceback", completed.stderr)

    def test_slope_77k_run_fills_the_tables(self):
        document = raw_fixture()
        for item in document["benchmarks"]:
            for key in ("name", "run_name"):
                if key in item:
                    item[key] = item[key].replace("/109k", "/slope-77k")
        context = document["context"]
        for suffix in ("nodes", "tets"):
            context[f"model_slope-77k_{suffix}"] = context.pop(f"model_109k_{suffix}")
        with tempfile.TemporaryDirectory() as out:
            path = write_result(out, document, "slope")
            completed = run_script("report.py", path, out, "--quality-model", "slope-77k")
            self.assertEqual(completed.returncode, 0, completed.stderr)
            rows = {r["model"]: r for r in read_csv(os.path.join(out, "table4.csv"))}
            self.assertNotEqual(rows["77k"]["aos_multi_ms"], "")
            self.assertNotEqual(rows["77k"]["cpu_serial_ms"], "")
            self.assertEqual(rows["77k"]["nodes"], "109260")
            self.assertNotIn("no histograms for 77k", completed.stderr)

    def test_cpu_only_result(self):
        document = raw_fixture()
        document["benchmarks"] = [e for e in document["benchmarks"]
                                  if bj.parse_name(bj.entry_name(e))["kind"] in ("serial", "threads", "ordinary")]
        for key in ("gpu_name", "sm_count", "cuda_version"):
            del document["context"][key]
        with tempfile.TemporaryDirectory() as out:
            path = os.path.join(out, "cpu.json")
            with open(path, "w", encoding="utf-8") as handle:
                json.dump(document, handle)
            completed = run_script("report.py", path, out)
            self.assertEqual(completed.returncode, 0, completed.stderr)
            with open(os.path.join(out, "tables.md"), encoding="utf-8") as handle:
                self.assertIn("GPU: none in this run", handle.read())
            rows = {r["model"]: r for r in read_csv(os.path.join(out, "table6.csv"))}
            self.assertEqual(rows["109k"]["aos_multi"], "")
            self.assertNotEqual(rows["109k"]["threads_over_serial"], "")
            self.assertEqual(read_csv(os.path.join(out, "scaling.csv")), [])
            for name in FIGURES:
                self.assertTrue(os.path.isfile(os.path.join(out, name)), name)

    def test_quality_model_option_and_fallback(self):
        import make_figures
        result = bj.load_result(FIXTURE)
        self.assertEqual(make_figures.pick_quality_model(result, "5k"), "5k")
        self.assertEqual(make_figures.pick_quality_model(result, "59k"), "109k")
        before, ordinary, adaptive = make_figures.quality_histograms(result, "5k")
        self.assertEqual(sum(before), 31874)
        self.assertEqual(ordinary[0], 331)
        self.assertEqual(adaptive[0], 118)
        with tempfile.TemporaryDirectory() as out:
            completed = run_script("make_figures.py", FIXTURE, out, "--quality-model", "5k")
            self.assertEqual(completed.returncode, 0, completed.stderr)
            self.assertTrue(os.path.isfile(os.path.join(out, "fig13_quality.png")))

    def test_max_speedup_is_over_the_papers_four_only(self):
        # The paper's Max compares its four GPU variants; our coloured
        # variant, fastest here (50x against 10x), has its own column and
        # must not become the Max that stands beside the paper's.
        context = {"gpu_name": "NVIDIA H100 80GB HBM3", "gpu_precision": "double", "model_5k_nodes": "5000",
                   "model_5k_tets": "32978"}
        document = {"context": context, "benchmarks": [
            entry("Serial/FormB/5k/real_time", 100.0),
            entry("FormB/AoS/MultiBlock/5k/manual_time", 10.0),
            entry("FormB/SoA/SingleBlock/5k/manual_time", 20.0),
            entry("FormB/AoS/Coloured/5k/manual_time", 2.0)]}
        with tempfile.TemporaryDirectory() as out:
            completed = run_script("make_tables.py", write_result(out, document), out)
            self.assertEqual(completed.returncode, 0, completed.stderr)
            row = {r["model"]: r for r in read_csv(os.path.join(out, "table6.csv"))}["5k"]
            self.assertAlmostEqual(float(row["aos_coloured"]), 50.0)
            self.assertAlmostEqual(float(row["max"]), 10.0)
            with open(os.path.join(out, "tables.md"), encoding="utf-8") as handle:
                lines = handle.read().splitlines()
        # The Markdown table shows the same Max in its column on our 5k line.
        start = lines.index("## Table 6: speedup over serial CPU, Form B")
        header = next(line for line in lines[start:] if line.startswith("| Model"))
        ours = next(line for line in lines[start:] if line.startswith("| 5k | ours"))
        cells = [cell.strip() for cell in ours.strip("|").split("|")]
        column = [cell.strip() for cell in header.strip("|").split("|")].index("Max (paper's four)")
        self.assertEqual(cells[column], "10.000")

    def test_number_formatting(self):
        import make_tables
        self.assertEqual(make_tables.fmt_sig(36592.0), "36,592")
        self.assertEqual(make_tables.fmt_sig(12.345), "12.35")
        self.assertEqual(make_tables.fmt_sig(0.081234), "0.08123")
        self.assertEqual(make_tables.fmt_sig(None), "—")
        self.assertTrue(math.isclose(float(make_tables.csv_value(1 / 3)), 1 / 3, rel_tol=1e-9))
        self.assertEqual(make_tables.csv_value(None), "")


if __name__ == "__main__":
    unittest.main()
