#!/usr/bin/python3
"""Regression check: compare two bench_smooth results benchmark by benchmark.

Usage:
    /usr/bin/python3 plots/compare_results.py OLD.json NEW.json [options]

Options:
    --metric M                   real_time (default), cpu_time, or any counter (ms_per_sweep, bytes_per_s, ...)
    --threshold T                default for both thresholds below (default 0.10 = 10 %)
    --per-benchmark-threshold T  fail if any single benchmark is slower by more than T (ratio > 1 + T);
                                 "off" disables this check
    --geomean-threshold T        fail if the geometric mean of the ratios is above 1 + T; "off" disables it
    --higher-is-better           the metric is a rate (automatic for counters ending in _per_s):
                                 "slower" then means new < old, and the verdict uses old/new
    --filter REGEX               compare only benchmarks whose name matches (re.search)
    --csv FILE                   also write the comparison as CSV
    --gbench                     first print the report of Google Benchmark's own compare.py
                                 (Debian's libbenchmark-tools, /usr/share/benchmark/compare.py,
                                 which needs scipy; it adds a Mann-Whitney U test over repetitions).
                                 When it is not available a note says so and the check goes on;
                                 the exit status is always this script's verdict.

Benchmarks are matched on their names with Google Benchmark's suffixes
(/manual_time, /repeats:N, ...) stripped; each is reduced to its median
aggregate when it has repetitions, else the mean of its iterations (see
bench_json.py).  The table shows old, new and new/old per benchmark, and the
geometric mean of the ratios over the benchmarks present in both files.

Exit status: 0 = within thresholds, 1 = a regression beyond a threshold,
2 = bad input (missing file, bad JSON, no benchmark in common, bad option).

Examples:
    compare_results.py results/h100/bench.json new.json                      # 10 % on each and on the geomean
    compare_results.py old.json new.json --per-benchmark-threshold off --geomean-threshold 0.05
    compare_results.py old.json new.json --filter '^Form[AB]/' --metric ms_per_sweep
"""

import argparse
import csv
import math
import os
import re
import subprocess
import sys
from dataclasses import dataclass

import bench_json as bj

GBENCH_COMPARE = "/usr/share/benchmark/compare.py"


class UsageError(Exception):
    pass


@dataclass
class Row:
    name: str
    old: float
    new: float
    statistic: str

    @property
    def ratio(self):
        return self.new / self.old

    def slowdown(self, higher_is_better):
        """> 1 means worse, whatever the metric's direction."""
        return self.old / self.new if higher_is_better else self.ratio


@dataclass
class Comparison:
    rows: list
    only_old: list
    only_new: list
    no_value: list

    def geomean(self):
        if not self.rows:
            return None
        return math.exp(sum(math.log(r.ratio) for r in self.rows) / len(self.rows))


OFF = "off"


def threshold_value(text):
    """A threshold as a float fraction, or OFF."""
    if str(text).lower() in ("off", "none", "no"):
        return OFF
    try:
        value = float(text)
    except ValueError as error:
        raise argparse.ArgumentTypeError(f"not a number or 'off': {text!r}") from error
    if value < 0 or not math.isfinite(value):
        raise argparse.ArgumentTypeError(f"threshold must be >= 0: {text!r}")
    return value


def parse_args(argv):
    parser = argparse.ArgumentParser(
        description="Compare two bench_smooth results; exit 1 on a regression beyond the thresholds.")
    parser.add_argument("old", help="baseline result JSON")
    parser.add_argument("new", help="result JSON to check")
    parser.add_argument("--metric", default="real_time", help="real_time (default), cpu_time or a counter name")
    parser.add_argument("--threshold", type=threshold_value, default=0.10,
                        help="default for both thresholds, as a fraction (default 0.10)")
    parser.add_argument("--per-benchmark-threshold", type=threshold_value, default=None,
                        help="fail if any benchmark's ratio > 1 + T ('off' to disable)")
    parser.add_argument("--geomean-threshold", type=threshold_value, default=None,
                        help="fail if the geometric mean of ratios > 1 + T ('off' to disable)")
    parser.add_argument("--higher-is-better", action="store_true",
                        help="the metric is a rate (automatic for *_per_s counters)")
    parser.add_argument("--filter", default=None, help="only benchmarks whose name matches this regex")
    parser.add_argument("--csv", default=None, help="also write the comparison to this CSV file")
    parser.add_argument("--gbench", action="store_true",
                        help=f"also print the report of Google Benchmark's {GBENCH_COMPARE} (needs scipy)")
    args = parser.parse_args(argv)
    for key in ("per_benchmark_threshold", "geomean_threshold"):
        value = getattr(args, key)
        value = args.threshold if value is None else value
        setattr(args, key, None if value == OFF else value)
    args.higher_is_better = args.higher_is_better or args.metric.endswith("_per_s")
    if args.filter is not None:
        try:
            args.filter = re.compile(args.filter)
        except re.error as error:
            raise UsageError(f"bad --filter regex {args.filter!r}: {error}") from error
    return args


def compare(old, new, metric, name_filter=None):
    """Match the two results by name and collect old/new values of the metric."""
    def selected(result):
        return [n for n in result.names() if name_filter is None or name_filter.search(n)]

    old_names, new_names = selected(old), selected(new)
    rows, no_value = [], []
    for name in old_names:
        if name not in new.runs:
            continue
        before, after = old.value(name, metric), new.value(name, metric)
        if before is None or after is None or before <= 0 or after <= 0:
            no_value.append(name)
            continue
        statistic = old.runs[name].statistic
        if new.runs[name].statistic != statistic:
            statistic = f"{statistic} / {new.runs[name].statistic}"
        rows.append(Row(name, before, after, statistic))
    return Comparison(rows, [n for n in old_names if n not in new.runs],
                      [n for n in new_names if n not in old.runs], no_value)


def fmt_value(value):
    return f"{value:.6g}"


def describe(result):
    return (f"{result.path} (git {result.context_text('git_sha', '?')}, {result.device_label()}, "
            f"{result.context_text('date', '?')})")


def limit_text(threshold):
    return "off" if threshold is None else f"{1 + threshold:.3f}"


def print_table(comparison, args):
    width = max([len("benchmark")] + [len(r.name) for r in comparison.rows])
    print(f"{'benchmark':<{width}}  {'old':>12}  {'new':>12}  {'new/old':>8}  {'':6}  statistic")
    limit = args.per_benchmark_threshold
    for row in comparison.rows:
        slowdown = row.slowdown(args.higher_is_better)
        flag = "SLOWER" if limit is not None and slowdown > 1 + limit else ""
        print(f"{row.name:<{width}}  {fmt_value(row.old):>12}  {fmt_value(row.new):>12}  "
              f"{row.ratio:>8.3f}  {flag:6}  {row.statistic}")
    geomean = comparison.geomean()
    print(f"{'geometric mean':<{width}}  {'':>12}  {'':>12}  {geomean:>8.3f}  ({len(comparison.rows)} benchmarks)")
    for label, names in (("only in OLD", comparison.only_old), ("only in NEW", comparison.only_new),
                         (f"no usable {args.metric}", comparison.no_value)):
        if names:
            print(f"{label} (not compared): {', '.join(names)}")


def verdict(comparison, args):
    """List of failure messages; empty when within thresholds."""
    failures = []
    limit = args.per_benchmark_threshold
    if limit is not None:
        slow = [r for r in comparison.rows if r.slowdown(args.higher_is_better) > 1 + limit]
        if slow:
            listed = ", ".join(f"{r.name} ({r.ratio:.3f})" for r in slow)
            failures.append(f"{len(slow)} benchmark(s) slower than {1 + limit:.3f}x: {listed}")
    limit = args.geomean_threshold
    if limit is not None:
        geomean = comparison.geomean()
        slowdown = 1 / geomean if args.higher_is_better else geomean
        if slowdown > 1 + limit:
            failures.append(f"geometric mean of ratios {geomean:.3f} beyond {1 + limit:.3f}x")
    return failures


def write_csv(comparison, path):
    with open(path, "w", newline="", encoding="utf-8") as handle:
        writer = csv.writer(handle)
        writer.writerow(["benchmark", "old", "new", "ratio_new_over_old", "statistic"])
        for row in comparison.rows:
            writer.writerow([row.name, repr(row.old), repr(row.new), repr(row.ratio), row.statistic])
        writer.writerow(["geomean", "", "", repr(comparison.geomean()), f"{len(comparison.rows)} benchmarks"])


def gbench_report(old_path, new_path):
    """Print Google Benchmark's compare.py report, or a note why it cannot run."""
    if not os.path.isfile(GBENCH_COMPARE):
        print(f"note: --gbench: {GBENCH_COMPARE} not found (Debian package libbenchmark-tools); skipped")
        return
    probe = subprocess.run([sys.executable, "-c", "import scipy, numpy"], capture_output=True, text=True)
    if probe.returncode != 0:
        print(f"note: --gbench: {GBENCH_COMPARE} needs scipy and numpy for {sys.executable} "
              "(Debian: python3-scipy); skipped")
        return
    print(f"--- Google Benchmark compare.py ({GBENCH_COMPARE}) ---", flush=True)
    completed = subprocess.run([sys.executable, GBENCH_COMPARE, "--no-color", "benchmarks", old_path, new_path],
                               capture_output=True, text=True)
    sys.stdout.write(completed.stdout)
    if completed.returncode != 0:
        print(f"note: --gbench: compare.py exited {completed.returncode}: {completed.stderr.strip()}")
    print("--- tetsmooth comparison ---")


def run(args):
    old, new = bj.load_result(args.old), bj.load_result(args.new)
    if args.gbench:
        gbench_report(args.old, args.new)
    comparison = compare(old, new, args.metric, args.filter)
    if not comparison.rows:
        raise bj.BenchInputError(f"no benchmark with a positive {args.metric} in both {args.old} and {args.new}")
    direction = "higher is better" if args.higher_is_better else "lower is better"
    print(f"OLD: {describe(old)}")
    print(f"NEW: {describe(new)}")
    if old.context_text("gpu_name") != new.context_text("gpu_name"):
        print(f"warning: different GPUs ({old.device_label()} vs {new.device_label()}): "
              "the ratios compare machines, not code")
    print(f"metric: {args.metric} ({direction}); limits: per benchmark {limit_text(args.per_benchmark_threshold)}, "
          f"geomean {limit_text(args.geomean_threshold)}")
    print()
    print_table(comparison, args)
    if args.csv:
        write_csv(comparison, args.csv)
    failures = verdict(comparison, args)
    print()
    if failures:
        for failure in failures:
            print(f"REGRESSION: {failure}")
        return 1
    print("OK: within thresholds")
    return 0


def main(argv=None):
    try:
        args = parse_args(argv)
        return run(args)
    except (bj.BenchInputError, UsageError) as error:
        print(f"compare_results: {error}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
