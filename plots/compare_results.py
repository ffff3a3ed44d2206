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
    --filter REGEX               compare only benchmarks whose name matches (re.search); applies to the
                                 missing and errored benchmarks too
    --allow-missing              a benchmark of OLD that NEW lacks, or the metric's counter
                                 NEW lacks, is a warning, not a failure
    --allow-precision-mismatch   compare although OLD and NEW ran the GPU families in different
                                 precisions (context gpu_precision, float vs double)
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

Besides the timings it checks what the files are:
  * benchmarks that reported an error (error_occurred / skipped) are listed
    with their messages; one that errored in NEW is a failure, one that
    errored only in OLD is a note (there is no baseline for it).
  * a benchmark of OLD that NEW lacks is a failure: a benchmark that
    disappeared is a regression for tracking (a family no longer registered,
    a model dropped).  --allow-missing makes it a warning.  Benchmarks only
    in NEW are listed for information.
  * so is a benchmark that OLD measured and NEW ran without the metric's
    counter (a run of no sweeps writes no ms_per_sweep): it can no longer
    be tracked either; --allow-missing makes it a warning too.  A value
    that fell to 0 (a count such as inverted_after) is listed, not compared.
  * GPU families run in float and in double are not comparable: when both
    contexts name a gpu_precision and they differ, the check stops with exit
    2 unless --allow-precision-mismatch (CPU families always run in double,
    so a --filter that keeps only CPU and copy benchmarks is not stopped,
    nor is a file without GPU runs, whose GPU benchmarks are missing).
  * a different GPU (gpu_name), host (host_name) or CPU count (num_cpus) is a
    warning: the ratios then compare machines, not code.

The default threshold of 10 % is kept, but it is not a noise bound: on the
study's shared GPU machines run-to-run noise above 10 % has been seen for the
small (5k) model's GPU runs, which take only hundreds of microseconds, and
for the CPU baselines (Serial/, Threads/), whose host is shared: the serial
109k run of unchanged code has taken from 2.9 to 5.7 s.  Leave those out
(--filter '^(?!Serial/|Threads/)(?!.*/5k$)') or check them in a separate
call with a larger threshold (--filter '^(Serial|Threads)/|/5k$' --threshold
0.5).

Exit status: 0 = within thresholds (warnings allowed), 1 = a regression: a
benchmark or the geomean beyond a threshold, a benchmark that errored in NEW,
or one missing from NEW or without the metric there (without --allow-missing),
2 = bad input (missing,
empty or bad JSON, no benchmark in common, a metric neither file has, different
precisions, a --csv file that cannot be written, bad option).

Examples:
    compare_results.py results/h100-80gb-hbm3/bench_smooth.json new.json               # 10 % on each and on the geomean
    compare_results.py old.json new.json --per-benchmark-threshold off --geomean-threshold 0.05
    compare_results.py old.json new.json --filter '^Form[AB]/' --metric ms_per_sweep
    compare_results.py old.json new.json --filter '^(?!.*/5k$)' --allow-missing   # without the noisy 5k runs
"""

import argparse
import csv
import math
import os
import re
import subprocess
import sys
from dataclasses import dataclass, field

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
    """What compare() found; the name lists and error dicts keep --filter's selection only."""
    rows: list
    only_old: list
    only_new: list
    no_value: list
    errored_old: dict = field(default_factory=dict)
    errored_new: dict = field(default_factory=dict)
    lost: list = field(default_factory=list)  # a usable value in OLD, none in NEW

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
    parser.add_argument("--allow-missing", action="store_true",
                        help="a benchmark of OLD missing from NEW, or its metric missing there, is a warning, "
                        "not a failure")
    parser.add_argument("--allow-precision-mismatch", action="store_true",
                        help="compare although the GPU precisions (context gpu_precision) differ")
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
    # Said before the comparison is printed, not after, with the verdict lost.
    if args.csv is not None and not os.path.isdir(os.path.dirname(os.path.abspath(args.csv))):
        raise UsageError(f"--csv {args.csv}: no folder {os.path.dirname(os.path.abspath(args.csv))} to write it in")
    return args


def check_metric(old, new, metric):
    """A metric that no benchmark of either file has is a misspelling, not a regression."""
    if metric in ("real_time", "cpu_time"):
        return
    runs = list(old.runs.values()) + list(new.runs.values())
    if any(metric in run.counters for run in runs):
        return
    # Numbered families (hist_before_0..9, colour_ms_0..) are named once.
    counters = sorted({re.sub(r"_\d+$", "_N", key) for run in runs for key in run.counters})
    shown = ", ".join(counters)
    raise bj.BenchInputError(f"--metric {metric}: no benchmark of {old.path} or {new.path} has it; "
                             f"real_time, cpu_time or a counter: {shown or 'none in these files'}")


def compare(old, new, metric, name_filter=None):
    """Match the two results by name and collect old/new values of the metric.

    A benchmark that errored in NEW is listed as errored, not as missing from
    NEW, so that it is reported once, with its message.
    """
    def selected(names):
        return [n for n in names if name_filter is None or name_filter.search(n)]

    old_names, new_names = selected(old.names()), selected(new.names())
    errored_old = {n: old.errors[n] for n in selected(old.errors)}
    errored_new = {n: new.errors[n] for n in selected(new.errors)}
    rows, no_value, lost = [], [], []
    for name in old_names:
        if name not in new.runs:
            continue
        before, after = old.value(name, metric), new.value(name, metric)
        if before is None or before <= 0:
            no_value.append(name)
            continue
        if after is None:  # the counter is gone: a run of no sweeps writes no ms_per_sweep
            lost.append(name)
            continue
        if after <= 0:  # a count that fell to 0 (inverted_after) has no ratio, but is no loss
            no_value.append(name)
            continue
        statistic = old.runs[name].statistic
        if new.runs[name].statistic != statistic:
            statistic = f"{statistic} / {new.runs[name].statistic}"
        rows.append(Row(name, before, after, statistic))
    only_old = [n for n in old_names if n not in new.runs and n not in errored_new]
    only_new = [n for n in new_names if n not in old.runs and n not in errored_old]
    return Comparison(rows, only_old, only_new, no_value, errored_old, errored_new, lost)


def fmt_value(value):
    return f"{value:.6g}"


def describe(result):
    return (f"{result.path} (git {result.context_text('git_sha', '?')}, {result.device_label()}, "
            f"{result.precision_tag()}, {result.context_text('date', '?')})")


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
    geomean_text = "—" if geomean is None else f"{geomean:.3f}"
    print(f"{'geometric mean':<{width}}  {'':>12}  {'':>12}  {geomean_text:>8}  ({len(comparison.rows)} benchmarks)")
    missing_label = "only in OLD, missing from NEW" + (", allowed" if args.allow_missing else "")
    lost_label = f"no usable {args.metric} in NEW, measured in OLD" + (", allowed" if args.allow_missing else "")
    for label, names in ((missing_label, comparison.only_old), ("only in NEW", comparison.only_new),
                         (lost_label, comparison.lost), (f"no usable {args.metric} in OLD", comparison.no_value)):
        if names:
            print(f"{label} (not compared): {', '.join(names)}")
    for label, errors in (("errored in OLD", comparison.errored_old), ("errored in NEW", comparison.errored_new)):
        for name, message in errors.items():
            print(f"{label} (not compared): {name}: {message}")


def error_list(errors):
    return "; ".join(f"{name} ({message})" for name, message in errors.items())


def verdict(comparison, args):
    """List of failure messages; empty when within thresholds.

    Besides the timings, a benchmark that errored in NEW and (unless
    --allow-missing) one that NEW lacks are failures: either way the
    benchmark can no longer be tracked, which a timing check must not pass.
    """
    failures = []
    if comparison.errored_new:
        failures.append(f"{len(comparison.errored_new)} benchmark(s) errored in NEW: "
                        f"{error_list(comparison.errored_new)}")
    if comparison.only_old and not args.allow_missing:
        failures.append(f"{len(comparison.only_old)} benchmark(s) of OLD missing from NEW "
                        f"(--allow-missing to accept): {', '.join(comparison.only_old)}")
    if comparison.lost and not args.allow_missing:
        failures.append(f"{len(comparison.lost)} benchmark(s) without a usable {args.metric} in NEW "
                        f"(--allow-missing to accept): {', '.join(comparison.lost)}")
    limit = args.per_benchmark_threshold
    if limit is not None:
        slow = [r for r in comparison.rows if r.slowdown(args.higher_is_better) > 1 + limit]
        if slow:
            listed = ", ".join(f"{r.name} ({r.ratio:.3f})" for r in slow)
            failures.append(f"{len(slow)} benchmark(s) slower than {1 + limit:.3f}x: {listed}")
    limit = args.geomean_threshold
    if limit is not None and comparison.rows:
        geomean = comparison.geomean()
        slowdown = 1 / geomean if args.higher_is_better else geomean
        if slowdown > 1 + limit:
            failures.append(f"geometric mean of ratios {geomean:.3f} beyond {1 + limit:.3f}x")
    return failures


def missing_warnings(comparison, args):
    """Messages about what is worth a look but passes (with --allow-missing: benchmarks, or values of the
    metric, that only OLD had)."""
    warnings = []
    if comparison.only_old and args.allow_missing:
        warnings.append(f"{len(comparison.only_old)} benchmark(s) of OLD missing from NEW (allowed): "
                        f"{', '.join(comparison.only_old)}")
    if comparison.lost and args.allow_missing:
        warnings.append(f"{len(comparison.lost)} benchmark(s) without a usable {args.metric} in NEW (allowed): "
                        f"{', '.join(comparison.lost)}")
    return warnings


CPU_KINDS = ("serial", "threads", "ordinary", "copy")


def precision_matters(comparison):
    """Whether a compared benchmark ran in the GPU precision (CPU and copy runs do not)."""
    names = ([r.name for r in comparison.rows] + comparison.no_value + list(comparison.errored_new)
             + comparison.only_old + comparison.lost)
    return any(bj.parse_name(n)["kind"] not in CPU_KINDS for n in names)


def check_precision(old, new, comparison, args):
    """Stop (bad input) when the GPU precisions differ; returns warning lines otherwise."""
    before, after = old.gpu_precision(), new.gpu_precision()
    if before == after or not precision_matters(comparison):
        return []
    # A run without GPU families (no GPU on its host) still records the
    # --precision it was given; its GPU benchmarks are missing, not of
    # another precision, and the check reports them as such.
    if not (old.has_gpu_runs() and new.has_gpu_runs()):
        return []
    if before is None or after is None:
        return [f"GPU precision not recorded in {old.path if before is None else new.path} "
                f"(the other is {before or after}): check both ran in the same precision"]
    message = (f"OLD ran the GPU families in {before}, NEW in {after}: comparing different precisions "
               "is meaningless")
    if not args.allow_precision_mismatch:
        raise bj.BenchInputError(f"{message} (--allow-precision-mismatch to compare anyway, "
                                 "or --filter to CPU benchmarks)")
    return [f"{message}; compared anyway (--allow-precision-mismatch)"]


def machine_warnings(old, new):
    """Warnings when the two runs were on different GPUs, hosts or CPU counts."""
    lines = []
    if old.context_text("gpu_name") != new.context_text("gpu_name"):
        lines.append(f"different GPUs ({old.device_label()} vs {new.device_label()}): "
                     "the ratios compare machines, not code")
    hosts = [(r.context_text("host_name"), r.context_number("num_cpus")) for r in (old, new)]
    if hosts[0] != hosts[1]:
        lines.append(f"different hosts ({old.cpu_label()} vs {new.cpu_label()}): "
                     "CPU baselines compare machines, not code")
    return lines


def write_csv(comparison, path):
    with open(path, "w", newline="", encoding="utf-8") as handle:
        writer = csv.writer(handle)
        writer.writerow(["benchmark", "old", "new", "ratio_new_over_old", "statistic"])
        for row in comparison.rows:
            writer.writerow([row.name, repr(row.old), repr(row.new), repr(row.ratio), row.statistic])
        geomean = comparison.geomean()
        writer.writerow(["geomean", "", "", "" if geomean is None else repr(geomean),
                         f"{len(comparison.rows)} benchmarks"])


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
    check_metric(old, new, args.metric)
    comparison = compare(old, new, args.metric, args.filter)
    if not comparison.rows and not comparison.errored_new and not comparison.lost:
        # Nothing measured in common and nothing broken in NEW: the wrong file, filter or metric.
        # Say when it is the filter that left nothing: on a host without a GPU, the noise filter of the
        # docstring keeps no benchmark at all.
        kept = "" if args.filter is None else (
            f" that --filter {args.filter.pattern!r} keeps ({len(compare(old, new, args.metric).rows)} without it)")
        raise bj.BenchInputError(f"no benchmark with a positive {args.metric} in both {args.old} and {args.new}{kept}")
    notes = check_precision(old, new, comparison, args) + machine_warnings(old, new)
    if args.gbench:
        gbench_report(args.old, args.new)
    direction = "higher is better" if args.higher_is_better else "lower is better"
    print(f"OLD: {describe(old)}")
    print(f"NEW: {describe(new)}")
    for note in notes:
        print(f"warning: {note}")
    # The loader turns every time_unit into ms; counters keep their own units.
    unit = ", in ms" if args.metric in ("real_time", "cpu_time") else ""
    print(f"metric: {args.metric} ({direction}{unit}); limits: per benchmark "
          f"{limit_text(args.per_benchmark_threshold)}, geomean {limit_text(args.geomean_threshold)}")
    print()
    print_table(comparison, args)
    if args.csv:
        try:
            write_csv(comparison, args.csv)
        except OSError as error:
            raise bj.BenchInputError(f"--csv {args.csv}: cannot write: {error.strerror}") from error
    failures = verdict(comparison, args)
    print()
    for warning in missing_warnings(comparison, args):
        print(f"warning: {warning}")
    if failures:
        for failure in failures:
            print(f"REGRESSION: {failure}")
        return 1
    print("OK: within thresholds")
    return 0


def main(argv=None):
    try:
        args = parse_args(argv)
        try:
            return run(args)
        except BrokenPipeError:
            # The reader stopped early (| head): finish the check unheard, so
            # that the exit status is still its verdict, not a traceback's 1.
            os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
            return run(args)
    except (bj.BenchInputError, UsageError) as error:
        print(f"compare_results: {error}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
