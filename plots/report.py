#!/usr/bin/python3
"""Tables and figures of one bench_smooth result, in one command.

Usage:
    /usr/bin/python3 plots/report.py RESULT.json OUTDIR [--quality-model 109k] [--metric real_time]

Runs make_tables.py (tables.md, table3.csv, table4.csv, table5.csv,
table6.csv, quality.csv, scaling.csv, colours.csv, phases.csv, runs.csv) and
make_figures.py (fig09_layout.png, fig10_form.png, fig11_cpu_gpu.png,
fig12_blocks.png, fig13_quality.png) on RESULT.json, writing into OUTDIR.
It prints the precision of the run first (float and double runs of
bench_smooth give files of the same names), then the files written.  This is the step the study script calls after
bench_smooth, e.g.

    /usr/bin/python3 plots/report.py results/h100-80gb-hbm3/bench_smooth.json results/h100-80gb-hbm3

Exit status: 0 on success, 2 when the result file is missing, empty or not
benchmark JSON, or OUTDIR cannot be made (nothing is written then).
"""

import argparse
import sys

import bench_json as bj
import make_figures
import make_tables


def parse_args(argv):
    parser = argparse.ArgumentParser(description="Tables and figures of a bench_smooth result.")
    bj.add_render_arguments(parser, "folder for the tables and figures", "report", quality_model=True)
    return parser.parse_args(argv)


def main(argv=None):
    args = parse_args(argv)
    result = bj.load_for_rendering(args.result, "report")
    if result is None or not bj.make_outdir(args.outdir, "report"):
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
