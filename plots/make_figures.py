#!/usr/bin/python3
"""Figures 9-13 of the paper, redrawn from a bench_smooth result.

Usage:
    /usr/bin/python3 plots/make_figures.py RESULT.json OUTDIR [--quality-model 109k] [--metric real_time]

Writes into OUTDIR (created if missing):
    fig09_layout.png     running time by data layout (AoS vs SoA), Form A and Form B panels
    fig10_form.png       running time by iteration form (A vs B), AoS and SoA panels
    fig11_cpu_gpu.png    CPU (serial, threads) vs GPU running times, and speedup over serial
    fig12_blocks.png     single block vs multiple blocks (and our Coloured strategy)
    fig13_quality.png    radius-ratio histograms of the input, the ordinary and the adaptive result
                         (Serial/FormB and Serial/Ordinary of --quality-model, default 109k)

Figures 9-12 have three rows: our times (top), the paper's published times
from Tables 3-4 (middle, same y axis so the two devices compare directly) and
a ratio row with both (ours solid, filled markers; paper dashed, hollow).
A row's y axis is logarithmic when its values, over all the figure's panels,
span more than a decade, so the panels of a row always share one scale; the
axis label says "log scale" then.  Titles name the GPU precision of the run
("float" or "double"; CPU runs are always double).  Models that were not run
leave gaps; a panel with nothing measured says so.
Exit status: 0 on success, 2 when the result file is missing, empty or not benchmark JSON,
or OUTDIR cannot be made.
"""

import argparse
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (the backend must be chosen first)
from matplotlib.ticker import FuncFormatter, LogLocator, NullFormatter  # noqa: E402

import bench_json as bj  # noqa: E402
import paper_numbers as paper  # noqa: E402

MODEL_TICKS = ["5k", "10k", "59k", "77k\n(slope)", "109k"]
STRATEGY_LABEL = {"SingleBlock": "single", "MultiBlock": "multi", "Coloured": "coloured"}
PAPER_STRATEGIES = ("SingleBlock", "MultiBlock")
FORM_LABEL = {"FormA": "Form A", "FormB": "Form B"}
LINESTYLE = {"SingleBlock": "-", "MultiBlock": "--", "Coloured": ":"}
MARKER = {"AoS": "o", "SoA": "s", "cpu": "D", "SingleBlock": "o", "MultiBlock": "s", "Coloured": "^"}
COLOUR = {"AoS": "tab:blue", "SoA": "tab:orange", "FormA": "tab:green", "FormB": "tab:purple",
          "SingleBlock": "tab:red", "MultiBlock": "tab:blue", "Coloured": "tab:olive",
          "serial": "black", "threads": "tab:gray", "gpu": "tab:blue"}
DPI = 110


# ---------------------------------------------------------------- data series

def nan_if_none(values):
    return [math.nan if v is None else float(v) for v in values]


def ours(result, name_of, metric):
    """Our values over the five models; name_of(model) -> benchmark name."""
    return nan_if_none(result.time_ms(name_of(model), metric) for model in bj.MODELS)


def paper_times(form, column):
    return nan_if_none(paper.time_ms(form, column, model) for model in bj.MODELS)


def paper_column(layout, strategy):
    return f"{layout.lower()}_{STRATEGY_LABEL[strategy]}"


def divide(numerators, denominators):
    return [a / b if b > 0 else math.nan for a, b in zip(numerators, denominators)]


def series(label, values, colour, linestyle="-", marker="o", source="ours"):
    return {"label": label, "values": values, "colour": colour, "linestyle": linestyle,
            "marker": marker, "source": source}


def has_data(values):
    return any(not math.isnan(v) for v in values)


# ---------------------------------------------------------------- drawing

def draw(ax, lines):
    """Plot the series with data; returns how many were drawn."""
    drawn = 0
    for line in lines:
        if not has_data(line["values"]):
            continue
        hollow = line["source"] == "paper"
        ax.plot(range(len(bj.MODELS)), line["values"], label=line["label"], color=line["colour"],
                linestyle=line["linestyle"], marker=line["marker"], markersize=5,
                markerfacecolor="white" if hollow else line["colour"])
        drawn += 1
    return drawn


def span_is_wide(values, decades=1.0):
    positive = [v for v in values if not math.isnan(v) and v > 0]
    return bool(positive) and math.log10(max(positive) / min(positive)) > decades


def finish(ax, title, ylabel, drawn, empty_text):
    ax.set_title(title, fontsize=9)
    ax.set_xlim(-0.4, len(bj.MODELS) - 0.6)
    ax.set_xticks(range(len(bj.MODELS)))
    ax.set_xticklabels(MODEL_TICKS, fontsize=8)
    ax.set_ylabel(ylabel, fontsize=8)
    ax.tick_params(axis="y", labelsize=8)
    ax.grid(True, which="both", alpha=0.3)
    if drawn:
        ax.legend(fontsize=7, loc="best")
    else:
        ax.text(0.5, 0.5, empty_text, ha="center", va="center", transform=ax.transAxes, fontsize=9, color="gray")


def row_scales(panels):
    """(time rows, ratio row) y scales, each decided once over every panel.

    Per-panel choices gave a figure with one ratio panel linear and its
    neighbour logarithmic (a run with Form B only), which reads as if the
    two were on the same scale.
    """
    time_values = [v for p in panels for s in p["ours"] + p["paper"] for v in s["values"]]
    ratio_values = [v for p in panels for s in p["ratio"] for v in s["values"]]
    return ("log" if span_is_wide(time_values) else "linear", "log" if span_is_wide(ratio_values) else "linear")


def scale_label(label, scale):
    return f"{label}, log scale" if scale == "log" else label


def ours_label(result):
    """Our device with the GPU precision, for titles: "NVIDIA H100 80GB HBM3 (float)"."""
    return f"{result.device_label()} ({result.precision_tag()})"


def comparison_figure(path, title, result, panels, ratio_label):
    """Three rows x len(panels) columns: our times, the paper's times, ratios.

    panels: list of dicts with "title", "ours", "paper", "ratio" (lists of series)
    and "table" (the paper's table number the middle row comes from).
    """
    fig, axes = plt.subplots(3, len(panels), figsize=(6.2 * len(panels), 12), squeeze=False)
    time_scale, ratio_scale = row_scales(panels)
    device = ours_label(result)
    for column, panel in enumerate(panels):
        top, middle, bottom = axes[0][column], axes[1][column], axes[2][column]
        finish(top, f"{panel['title']} - ours: {device}", scale_label("time (ms)", time_scale),
               draw(top, panel["ours"]), "not measured in this run")
        finish(middle, f"{panel['title']} - paper: {paper.GPU} (Table {panel['table']})",
               scale_label("time (ms)", time_scale), draw(middle, panel["paper"]), "no published numbers")
        drawn = draw(bottom, panel["ratio"])
        bottom.axhline(1.0, color="black", linewidth=0.8, alpha=0.6)
        finish(bottom, f"{panel['title']} - {ratio_label}", scale_label("ratio", ratio_scale), drawn,
               "nothing to compare")
        for ax in (top, middle):
            ax.set_yscale(time_scale)
        bottom.set_yscale(ratio_scale)
        if ratio_scale == "log":
            bottom.yaxis.set_major_formatter(FuncFormatter(lambda value, _: f"{value:g}"))
    share_y(list(axes[0]) + list(axes[1]))
    fig.suptitle(f"{title}\nours: {device}, git {result.context_text('git_sha', 'unknown')}; "
                 f"paper: {paper.GPU_DETAIL} (ratio row: ours solid, paper dashed)", fontsize=10)
    fig.tight_layout(rect=(0, 0, 1, 0.96))
    fig.savefig(path, dpi=DPI)
    plt.close(fig)
    return path


def share_y(axes):
    """Same y limits on every time panel, so ours and the paper's compare by eye."""
    limits = [ax.get_ylim() for ax in axes if ax.lines]
    if not limits:
        return
    low, high = min(l[0] for l in limits), max(l[1] for l in limits)
    for ax in axes:
        if ax.lines:
            ax.set_ylim(low, high)


# ---------------------------------------------------------------- figures 9-12

def fig09_layout(result, outdir, metric):
    panels = []
    for form in bj.FORMS:
        our_lines, paper_lines, ratio_lines = [], [], []
        for layout in bj.LAYOUTS:
            for strategy in bj.STRATEGIES:
                label = f"{layout} {STRATEGY_LABEL[strategy]}"
                our_lines.append(series(label, ours(result, lambda m: bj.gpu_name(form, layout, strategy, m), metric),
                                        COLOUR[layout], LINESTYLE[strategy], MARKER[strategy]))
                if strategy in PAPER_STRATEGIES:
                    paper_lines.append(series(label, paper_times(form, paper_column(layout, strategy)),
                                              COLOUR[layout], LINESTYLE[strategy], MARKER[strategy], "paper"))
        for strategy in bj.STRATEGIES:
            aos = ours(result, lambda m: bj.gpu_name(form, "AoS", strategy, m), metric)
            soa = ours(result, lambda m: bj.gpu_name(form, "SoA", strategy, m), metric)
            ratio_lines.append(series(f"ours {STRATEGY_LABEL[strategy]}", divide(soa, aos), COLOUR[strategy]))
            if strategy in PAPER_STRATEGIES:
                ratio_lines.append(series(
                    f"paper {STRATEGY_LABEL[strategy]}",
                    divide(paper_times(form, paper_column("SoA", strategy)),
                           paper_times(form, paper_column("AoS", strategy))),
                    COLOUR[strategy], "--", "o", "paper"))
        panels.append({"title": FORM_LABEL[form], "ours": our_lines, "paper": paper_lines, "ratio": ratio_lines,
                       "table": paper.TABLE_NUMBER["time"][form]})
    return comparison_figure(os.path.join(outdir, "fig09_layout.png"),
                             "Figure 9: running time by data layout (AoS vs SoA)", result, panels,
                             "SoA time / AoS time (> 1: AoS faster)")


def fig10_form(result, outdir, metric):
    panels = []
    for layout in bj.LAYOUTS:
        our_lines, paper_lines, ratio_lines = [], [], []
        for form in bj.FORMS:
            for strategy in bj.STRATEGIES:
                label = f"{FORM_LABEL[form]} {STRATEGY_LABEL[strategy]}"
                our_lines.append(series(label, ours(result, lambda m: bj.gpu_name(form, layout, strategy, m), metric),
                                        COLOUR[form], LINESTYLE[strategy], MARKER[strategy]))
                if strategy in PAPER_STRATEGIES:
                    paper_lines.append(series(label, paper_times(form, paper_column(layout, strategy)),
                                              COLOUR[form], LINESTYLE[strategy], MARKER[strategy], "paper"))
        for strategy in bj.STRATEGIES:
            form_a = ours(result, lambda m: bj.gpu_name("FormA", layout, strategy, m), metric)
            form_b = ours(result, lambda m: bj.gpu_name("FormB", layout, strategy, m), metric)
            ratio_lines.append(series(f"ours {STRATEGY_LABEL[strategy]}", divide(form_a, form_b), COLOUR[strategy]))
            if strategy in PAPER_STRATEGIES:
                column = paper_column(layout, strategy)
                ratio_lines.append(series(f"paper {STRATEGY_LABEL[strategy]}",
                                          divide(paper_times("FormA", column), paper_times("FormB", column)),
                                          COLOUR[strategy], "--", "o", "paper"))
        panels.append({"title": f"{layout} layout", "ours": our_lines, "paper": paper_lines, "ratio": ratio_lines,
                       "table": "3-4"})
    return comparison_figure(os.path.join(outdir, "fig10_form.png"),
                             "Figure 10: running time by iteration form (Form A vs Form B)", result, panels,
                             "Form A time / Form B time (speedup of Form B)")


def best_speedup(serial, variant_lists):
    """Per model, serial time over the fastest available variant."""
    best = []
    for index, base in enumerate(serial):
        times = [v[index] for v in variant_lists if not math.isnan(v[index])]
        best.append(base / min(times) if times and not math.isnan(base) and min(times) > 0 else math.nan)
    return best


def fig11_cpu_gpu(result, outdir, metric):
    panels = []
    variants = [(layout, strategy) for layout in bj.LAYOUTS for strategy in bj.STRATEGIES]
    for form in bj.FORMS:
        serial = ours(result, lambda m: f"Serial/{form}/{m}", metric)
        threads = ours(result, lambda m: f"Threads/{form}/{m}", metric)
        gpu = {v: ours(result, lambda m: bj.gpu_name(form, v[0], v[1], m), metric) for v in variants}
        our_lines = [series("CPU serial", serial, COLOUR["serial"], "-", MARKER["cpu"]),
                     series("CPU threads", threads, COLOUR["threads"], "-", MARKER["cpu"])]
        our_lines += [series(f"GPU {l} {STRATEGY_LABEL[s]}", gpu[(l, s)], COLOUR[l], LINESTYLE[s], MARKER[s])
                      for l, s in variants]
        paper_serial = paper_times(form, "cpu")
        paper_gpu = {(l, s): paper_times(form, paper_column(l, s)) for l in bj.LAYOUTS for s in PAPER_STRATEGIES}
        paper_lines = [series("CPU serial", paper_serial, COLOUR["serial"], "-", MARKER["cpu"], "paper")]
        paper_lines += [series(f"GPU {l} {STRATEGY_LABEL[s]}", t, COLOUR[l], LINESTYLE[s], MARKER[s], "paper")
                        for (l, s), t in paper_gpu.items()]
        ratio_lines = [series("ours: best GPU over serial", best_speedup(serial, list(gpu.values())), COLOUR["gpu"]),
                       series("ours: threads over serial", divide(serial, threads), COLOUR["threads"]),
                       series("paper: best GPU over serial", best_speedup(paper_serial, list(paper_gpu.values())),
                              COLOUR["gpu"], "--", "o", "paper")]
        panels.append({"title": FORM_LABEL[form], "ours": our_lines, "paper": paper_lines, "ratio": ratio_lines,
                       "table": paper.TABLE_NUMBER["time"][form]})
    return comparison_figure(os.path.join(outdir, "fig11_cpu_gpu.png"),
                             "Figure 11: serial CPU vs parallel running time", result, panels,
                             "speedup over serial CPU (Tables 5-6)")


def fig12_blocks(result, outdir, metric):
    panels = []
    for form in bj.FORMS:
        our_lines, paper_lines, ratio_lines = [], [], []
        for layout in bj.LAYOUTS:
            times = {s: ours(result, lambda m: bj.gpu_name(form, layout, s, m), metric) for s in bj.STRATEGIES}
            for strategy in bj.STRATEGIES:
                label = f"{STRATEGY_LABEL[strategy]} {layout}"
                our_lines.append(series(label, times[strategy], COLOUR[strategy], LINESTYLE[strategy], MARKER[layout]))
            published = {s: paper_times(form, paper_column(layout, s)) for s in PAPER_STRATEGIES}
            for strategy in PAPER_STRATEGIES:
                paper_lines.append(series(f"{STRATEGY_LABEL[strategy]} {layout}", published[strategy],
                                          COLOUR[strategy], LINESTYLE[strategy], MARKER[layout], "paper"))
            ratio_lines.append(series(f"ours {layout}: single / multi",
                                      divide(times["SingleBlock"], times["MultiBlock"]),
                                      COLOUR[layout], "-", MARKER["MultiBlock"]))
            ratio_lines.append(series(f"ours {layout}: single / coloured",
                                      divide(times["SingleBlock"], times["Coloured"]),
                                      COLOUR[layout], ":", MARKER["Coloured"]))
            ratio_lines.append(series(f"paper {layout}: single / multi",
                                      divide(published["SingleBlock"], published["MultiBlock"]),
                                      COLOUR[layout], "--", MARKER["MultiBlock"], "paper"))
        panels.append({"title": FORM_LABEL[form], "ours": our_lines, "paper": paper_lines, "ratio": ratio_lines,
                       "table": paper.TABLE_NUMBER["time"][form]})
    return comparison_figure(os.path.join(outdir, "fig12_blocks.png"),
                             "Figure 12: single block vs multiple blocks (and graph colouring)", result, panels,
                             "single-block time / other (> 1: the other is faster)")


# ---------------------------------------------------------------- figure 13

HIST_BINS = 10
# §5.2 of the paper gives approximate counts of tets with q close to 0 (model not stated).
PAPER_NEAR_ZERO = {"input": "about 1500", "ordinary": "about 2000", "adaptive": "about 1000"}


def histogram(result, name, prefix):
    run = result.run(name)
    if run is None:
        return None
    counts = [run.counters.get(f"{prefix}_{i}") for i in range(HIST_BINS)]
    return None if any(c is None for c in counts) else counts


def quality_histograms(result, model):
    """(input, ordinary, adaptive) histograms of one model; missing ones are None."""
    adaptive_name, ordinary_name = f"Serial/FormB/{model}", f"Serial/Ordinary/{model}"
    before = histogram(result, adaptive_name, "hist_before") or histogram(result, ordinary_name, "hist_before")
    return before, histogram(result, ordinary_name, "hist_after"), histogram(result, adaptive_name, "hist_after")


def pick_quality_model(result, wanted):
    """The wanted model if it has histograms, else the largest one that has."""
    if any(quality_histograms(result, wanted)):
        return wanted
    for model in reversed(bj.MODELS):
        if any(quality_histograms(result, model)):
            print(f"make_figures: no histograms for {wanted}; Figure 13 uses {model}", file=sys.stderr)
            return model
    return None


def log_ticks(ax):
    """Label 1, 2 and 5 times each power of ten on a log y axis.

    Counts of the paper models' bins lie within about one decade, where the
    default locator labels a single power of ten and the axis cannot be read.
    """
    ax.yaxis.set_major_locator(LogLocator(base=10, subs=(1.0, 2.0, 5.0)))
    ax.yaxis.set_major_formatter(FuncFormatter(lambda value, _: f"{value:,.0f}"))
    ax.yaxis.set_minor_formatter(NullFormatter())
    ax.tick_params(axis="y", labelsize=8)


def draw_histogram(ax, counts, reference, title, paper_note):
    centres = [(i + 0.5) / HIST_BINS for i in range(HIST_BINS)]
    width = 0.9 / HIST_BINS
    if counts is None:
        ax.text(0.5, 0.5, "not measured in this run", ha="center", va="center", transform=ax.transAxes, color="gray")
    else:
        ax.bar(centres, [max(c, 0.0) for c in counts], width=width, color="tab:blue", label="tetrahedra")
        ax.text(centres[0], max(counts[0], 1.0), f"{int(round(counts[0])):,}", ha="center", va="bottom", fontsize=8)
    if reference is not None and counts is not None:
        ax.step([0.0] + [(i + 1) / HIST_BINS for i in range(HIST_BINS)], [reference[0]] + list(reference),
                where="pre", color="black", linewidth=1, label="input (outline)")
    if counts is not None:
        ax.set_yscale("log")
        log_ticks(ax)
        ax.legend(fontsize=7, loc="upper left")
    ax.set_xlim(0, 1)
    ax.set_xlabel("radius ratio q (1 = regular)", fontsize=8)
    ax.set_ylabel("tetrahedra (log scale)", fontsize=8)
    ax.set_title(f"{title}\npaper §5.2 (model not stated): {paper_note} tets near q = 0", fontsize=9)


def mean_q(result, name, key):
    value = result.counter(name, key)
    return "" if value is None else f", mean q {value:.3f}"


def fig13_quality(result, outdir, wanted_model):
    model = pick_quality_model(result, wanted_model)
    if model is None:
        print("make_figures: no quality histograms in the result; Figure 13 skipped", file=sys.stderr)
        return None
    before, ordinary, adaptive = quality_histograms(result, model)
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.6), sharey=True)
    draw_histogram(axes[0], before, None, f"(a) input{mean_q(result, f'Serial/FormB/{model}', 'q_mean_before')}",
                   PAPER_NEAR_ZERO["input"])
    draw_histogram(axes[1], ordinary, before,
                   f"(b) ordinary Laplacian{mean_q(result, f'Serial/Ordinary/{model}', 'q_mean_after')}",
                   PAPER_NEAR_ZERO["ordinary"])
    draw_histogram(axes[2], adaptive, before,
                   f"(c) adaptive Laplacian (Form B){mean_q(result, f'Serial/FormB/{model}', 'q_mean_after')}",
                   PAPER_NEAR_ZERO["adaptive"])
    fig.suptitle(f"Figure 13: quality distribution, model {model} (serial CPU runs, {bj.CPU_PRECISION}; "
                 f"{result.cpu_label()}, git {result.context_text('git_sha', 'unknown')})", fontsize=10)
    fig.tight_layout(rect=(0, 0, 1, 0.93))
    path = os.path.join(outdir, "fig13_quality.png")
    fig.savefig(path, dpi=DPI)
    plt.close(fig)
    return path


# ---------------------------------------------------------------- driver

def write_figures(result, outdir, metric="real_time", quality_model="109k"):
    """Draw every figure; returns the paths written."""
    os.makedirs(outdir, exist_ok=True)
    paths = [fig09_layout(result, outdir, metric), fig10_form(result, outdir, metric),
             fig11_cpu_gpu(result, outdir, metric), fig12_blocks(result, outdir, metric),
             fig13_quality(result, outdir, quality_model)]
    return [p for p in paths if p]


def parse_args(argv):
    parser = argparse.ArgumentParser(description="Figures 9-13 of the paper from a bench_smooth result.")
    bj.add_render_arguments(parser, "folder for the PNG files", "plot", quality_model=True)
    return parser.parse_args(argv)


def main(argv=None):
    args = parse_args(argv)
    result = bj.load_for_rendering(args.result, "make_figures")
    if result is None or not bj.make_outdir(args.outdir, "make_figures"):
        return 2
    for path in write_figures(result, args.outdir, args.metric, args.quality_model):
        print(path)
    return 0


if __name__ == "__main__":
    sys.exit(main())
