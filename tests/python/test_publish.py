#!/usr/bin/python3
"""Tests of scripts/publish_results.sh, which files a result under results/.

Run: /usr/bin/python3 tests/python/test_publish.py   (CTest sets TETSMOOTH_SOURCE_DIR)
Uses tests/data/bench_small.json (a small bench_smooth result) and writes
only into temporary folders given with --dest.
"""

import json
import os
import shutil
import subprocess
import tempfile
import unittest

SOURCE_DIR = os.environ.get("TETSMOOTH_SOURCE_DIR") or os.path.dirname(
    os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SCRIPT = os.path.join(SOURCE_DIR, "scripts", "publish_results.sh")
SMALL = os.path.join(SOURCE_DIR, "tests", "data", "bench_small.json")


def publish(*args):
    return subprocess.run(["bash", SCRIPT, *args], capture_output=True, text=True, timeout=300)


class PublishResults(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.mkdtemp(prefix="publish-")
        self.dest = os.path.join(self.tmp, "dest")

    def tearDown(self):
        shutil.rmtree(self.tmp)

    def write(self, name, text):
        path = os.path.join(self.tmp, name)
        with open(path, "w", encoding="utf-8") as handle:
            handle.write(text)
        return path

    def test_files_the_result_with_its_tables_and_logs(self):
        logs = os.path.join(self.tmp, "out")
        os.mkdir(logs)
        for name in ("gpu_tests.log", "sanitizers.log", "device.txt", "run.txt"):
            self.write(os.path.join("out", name), name)
        done = publish("--dest", self.dest, "--logs", logs, SMALL, SMALL)
        self.assertEqual(done.returncode, 0, done.stderr)
        present = set(os.listdir(self.dest))
        for name in ("bench_smooth.json", "bench_float.json", "tables.md", "table3.csv", "gpu_tests.log",
                     "sanitizers.log", "device.txt", "run.txt"):
            self.assertIn(name, present)
        self.assertTrue(any(name.startswith("fig") for name in present), present)

    def test_logs_stay_until_a_run_brings_its_own(self):
        # A re-run without --logs keeps the earlier run's logs; --logs replaces them, missing ones too.
        logs = os.path.join(self.tmp, "out")
        os.mkdir(logs)
        for name in ("gpu_tests.log", "device.txt"):
            self.write(os.path.join("out", name), "first")
        self.assertEqual(publish("--dest", self.dest, "--logs", logs, SMALL).returncode, 0)
        done = publish("--dest", self.dest, SMALL)
        self.assertEqual(done.returncode, 0, done.stderr)
        self.assertTrue({"gpu_tests.log", "device.txt"} <= set(os.listdir(self.dest)))
        os.remove(os.path.join(logs, "device.txt"))
        self.write(os.path.join("out", "gpu_tests.log"), "second")
        self.assertEqual(publish("--dest", self.dest, "--logs", logs, SMALL).returncode, 0)
        self.assertNotIn("device.txt", os.listdir(self.dest))
        with open(os.path.join(self.dest, "gpu_tests.log"), encoding="utf-8") as handle:
            self.assertEqual(handle.read(), "second")

    def test_float_result_is_filed_as_given(self):
        # FLOAT.json is filed as bench_float.json byte for byte, beside BENCH.json, not a copy of it.
        with open(SMALL, encoding="utf-8") as handle:
            document = json.load(handle)
        document["context"]["gpu_precision"] = "float"
        float_path = self.write("float.json", json.dumps(document))
        self.assertEqual(publish("--dest", self.dest, SMALL, float_path).returncode, 0)
        for name, source in (("bench_float.json", float_path), ("bench_smooth.json", SMALL)):
            with open(os.path.join(self.dest, name), "rb") as filed, open(source, "rb") as given:
                self.assertEqual(filed.read(), given.read(), name)

    def test_a_new_run_replaces_the_old_files_and_keeps_notes(self):
        self.assertEqual(publish("--dest", self.dest, SMALL, SMALL).returncode, 0)
        for name in ("fig99_old.png", "ncu_notes.txt"):
            self.write(os.path.join("dest", name), "earlier run")
        done = publish("--dest", self.dest, SMALL)
        self.assertEqual(done.returncode, 0, done.stderr)
        self.assertIn("replacing the results", done.stdout)
        present = set(os.listdir(self.dest))
        self.assertNotIn("bench_float.json", present, "a float file of the earlier run must not linger")
        self.assertNotIn("fig99_old.png", present)
        self.assertIn("ncu_notes.txt", present)

    def test_bad_input_leaves_the_old_results_whole(self):
        self.assertEqual(publish("--dest", self.dest, SMALL).returncode, 0)
        before = sorted(os.listdir(self.dest))
        for bad in (self.write("empty.json", ""), self.write("broken.json", "{not json"),
                    os.path.join(self.tmp, "missing.json")):
            done = publish("--dest", self.dest, bad)
            self.assertNotEqual(done.returncode, 0, bad)
            self.assertTrue(done.stderr.strip(), f"{bad}: no message")
            self.assertEqual(sorted(os.listdir(self.dest)), before, bad)
        with open(os.path.join(self.dest, "bench_smooth.json"), encoding="utf-8") as kept, \
                open(SMALL, encoding="utf-8") as original:
            self.assertEqual(json.load(kept), json.load(original))

    def test_a_result_cut_off_or_not_benchmark_json_is_named_and_not_filed(self):
        # FLOAT.json is filed, not rendered: it is read all the same. A bad
        # BENCH.json is named as the caller gave it, not as its staged copy.
        self.assertEqual(publish("--dest", self.dest, SMALL).returncode, 0)
        before = sorted(os.listdir(self.dest))
        with open(SMALL, encoding="utf-8") as handle:
            text = handle.read()
        cut = self.write("cut.json", text[:text.index("\n    },", text.index("\"benchmarks\"")) + 6] + "\n")
        other = self.write("other.json", json.dumps({"context": {}}))
        for args, named, why in (([SMALL, cut], cut, "the JSON ends before it is complete"),
                                 ([SMALL, other], other, "not Google Benchmark JSON"),
                                 ([cut], cut, "the JSON ends before it is complete")):
            done = publish("--dest", self.dest, *args)
            self.assertEqual(done.returncode, 2, args)
            self.assertIn(f"publish_results: {named}: {why}", done.stderr)
            self.assertNotIn("/tmp/tmp.", done.stderr, "names the staging folder instead of the caller's file")
            self.assertEqual(sorted(os.listdir(self.dest)), before, args)

    def test_bad_arguments_change_nothing(self):
        logs = os.path.join(self.tmp, "out")
        os.mkdir(logs)
        self.write(os.path.join("out", "gpu_tests.log"), "tests")
        self.assertEqual(publish("--dest", self.dest, "--logs", logs, SMALL, SMALL).returncode, 0)
        before = sorted(os.listdir(self.dest))
        for args in (["--logs", os.path.join(self.tmp, "no-such-folder"), SMALL],  # no log to take
                     ["--logs", self.tmp, SMALL],                                 # a folder without logs
                     [SMALL, ""],                                                  # an empty FLOAT
                     [SMALL, os.path.join(self.tmp, "missing float.json")],
                     [SMALL, SMALL, SMALL]):                                      # a third result, not filed
            done = publish("--dest", self.dest, *args)
            self.assertEqual(done.returncode, 2, args)
            self.assertEqual(sorted(os.listdir(self.dest)), before, args)

    def test_paths_are_the_callers_and_may_hold_spaces(self):
        spaced = os.path.join(self.tmp, "a b")
        os.mkdir(spaced)
        shutil.copy(SMALL, os.path.join(spaced, "float run.json"))
        done = subprocess.run(["bash", SCRIPT, "--dest", "rel dest", SMALL, os.path.join("a b", "float run.json")],
                              capture_output=True, text=True, timeout=300, cwd=self.tmp)
        self.assertEqual(done.returncode, 0, done.stderr)
        self.assertTrue(os.path.isfile(os.path.join(self.tmp, "rel dest", "bench_float.json")))
        self.assertNotIn("/tmp/tmp.", done.stdout, "names the staging folder instead of the destination")

    def test_device_folder_names_the_whole_board(self):
        with open(SMALL, encoding="utf-8") as handle:
            result = json.load(handle)
        # Without --dest the script writes under results/ of its own tree:
        # run a copy of scripts/ and plots/, so the checkout's is never touched.
        repo = os.path.join(self.tmp, "repo")
        shutil.copytree(os.path.join(SOURCE_DIR, "scripts"), os.path.join(repo, "scripts"))
        shutil.copytree(os.path.join(SOURCE_DIR, "plots"), os.path.join(repo, "plots"))
        for gpu, folder in (("NVIDIA H100 80GB HBM3", "h100-80gb-hbm3"), ("NVIDIA H100 PCIe", "h100-pcie"),
                            ("NVIDIA H200", "h200")):
            result["context"]["gpu_name"] = gpu
            path = self.write("named.json", json.dumps(result))
            done = subprocess.run(["bash", os.path.join(repo, "scripts", "publish_results.sh"), path],
                                  capture_output=True, text=True, timeout=300)
            self.assertEqual(done.returncode, 0, done.stderr)
            self.assertTrue(os.path.isfile(os.path.join(repo, "results", folder, "tables.md")), gpu)
        # Naming the folder reads the JSON: a broken one is bad input (2).
        done = subprocess.run(["bash", os.path.join(repo, "scripts", "publish_results.sh"), self.write("bad.json", "{x")],
                              capture_output=True, text=True, timeout=300)
        self.assertEqual(done.returncode, 2, done.stderr)
        self.assertIn("bad.json: bad JSON", done.stderr)


if __name__ == "__main__":
    unittest.main()
