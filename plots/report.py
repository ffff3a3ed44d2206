#!/usr/bin/python3
"""Tables and figures of one bench_smooth result, in one command.

Usage:
    /usr/bin/python3 plots/report.py RESULT.json OUTDIR [--quality-model 109k] [--metric real_time]

Runs make_tables.py (tables.md, table3.csv, table4.csv, table5.csv,
table6.csv, quality.csv, scaling.csv, colours.csv, runs.csv) and
make_figures.py (fig09_layout.png, fig10_form.png, fig11_cpu_gpu.png,
fig12_blocks.png, fig13_quality.png) on RESULT.json, writing into OUTDIR.
It prints the precision of the run first (float and double runs of
bench_smooth give files of the same names), then the files written.  This is the step the study script calls after
bench_smooth, e.g.

    /usr/bin/python3 plots/report.py results/h100-80gb-hbm3/bench_smooth.json results/h100-80gb-hbm3

Exit status: 0 on success, 2 when the result file is missing, empty or not
benchmark JSON (nothing is written then).
"""

import argparse
import sys

import bench_json as bj
import make_figures
import make_tables


def parse_args(argv):
    parser = argparse.ArgumentParser(description="Tables and figures of a bench_smooth result.")
    parser.add_argument("result", help="bench_smooth --benchmark_out JSON")
    parser.add_argument("outdir", help="folder for the tables and figures")
    parser.add_argument("--quality-model", default="109k", choices=bj.MODELS, type=bj.canonical_model,
                        help="model whose histograms Figure 13 shows (default 109k)")
    parser.add_argument("--metric", default="real_time", choices=("real_time", "cpu_time"),
                        help="which time to report (default real_time)")
    return parser.parse_args(argv)


def main(argv=None):
    args = parse_args(argv)
    try:
        result = bj.load_result(args.result, need_runs=True)
    except bj.BenchInputError as error:
        print(f"report: {error}", file=sys.stderr)
        return 2
    print(f"report: {args.result}: precision: {result.precision_text()}")
    written = make_tables.write_tables(result, args.outdir, args.metric)
    written += make_figures.write_figures(result, args.outdir, args.metric, args.quality_model)
    for path in written:
        print(path)
    if result.errors:
        print(f"report: {len(result.errors)} benchmark(s) reported errors; see the last table of tables.md",
              file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
