#!/usr/bin/python3
"""Tables of a bench_smooth result, beside the paper's published numbers.

Usage:
    /usr/bin/python3 plots/make_tables.py RESULT.json OUTDIR [--metric real_time]

Writes into OUTDIR (created if missing):
    tables.md     all tables in Markdown, headed by the device, host, precision and git SHA
    table3.csv    running time (ms), Form A: ours and the paper's Table 3
    table4.csv    running time (ms), Form B: ours and the paper's Table 4
    table5.csv    speedup over our serial CPU and over Threads, Form A; paper's Table 5
    table6.csv    the same for Form B; paper's Table 6
    quality.csv   mesh quality before/after per benchmark
    scaling.csv   per-sweep throughput of GPU runs and the ratio to the memory floor
    colours.csv   coloured GPU runs: time per colour class, summed over sweeps
    phases.csv    MultiBlock GPU runs: ms per sweep by kind of kernel
    runs.csv      every benchmark: time (ms) and how it was reduced over repetitions

Missing benchmarks (families not run, no GPU) are empty cells in CSV and "—"
in Markdown.  Times are the chosen metric (default real_time, which is the
CUDA-event time for GPU families) in ms: the median aggregate when the run has
repetitions, else the mean of the iterations.  Speedup = our serial CPU time
over the variant's time, as the paper defines it.  Exit status: 0 on success,
2 when the result file is missing, empty or not benchmark JSON, or OUTDIR
cannot be made.
"""

import argparse
import csv
import math
import os
import sys
from dataclasses import dataclass, field

import bench_json as bj
import paper_numbers as paper

STRATEGY_KEY = {"SingleBlock": "single", "MultiBlock": "multi", "Coloured": "coloured"}
PAPER_VARIANTS = (("AoS", "SingleBlock"), ("AoS", "MultiBlock"), ("SoA", "SingleBlock"), ("SoA", "MultiBlock"))
OUR_EXTRA_VARIANTS = (("AoS", "Coloured"), ("SoA", "Coloured"))
ALL_VARIANTS = PAPER_VARIANTS + OUR_EXTRA_VARIANTS
QUALITY_KEYS = ("sweeps", "accepted", "q_min_before", "q_min_after", "q_mean_before", "q_mean_after",
                "low_q_before", "low_q_after", "inverted_before", "inverted_after")
FORM_TITLE = {"FormA": "Form A", "FormB": "Form B"}
DASH = "—"


def variant_key(layout, strategy):
    """Column key of a GPU variant, e.g. aos_multi; matches paper_numbers' keys."""
    return f"{layout.lower()}_{STRATEGY_KEY[strategy]}"


def variant_header(layout, strategy):
    return f"{layout} {STRATEGY_KEY[strategy]}"


# ---------------------------------------------------------------- formatting

def fmt_sig(value, digits=4):
    """Significant digits without scientific notation: 36,592 / 12.35 / 0.08123."""
    if value is None or (isinstance(value, float) and math.isnan(value)):
        return DASH
    if value == 0:
        return "0"
    decimals = max(0, digits - 1 - int(math.floor(math.log10(abs(value)))))
    return f"{value:,.{decimals}f}"


def fmt_fixed(decimals):
    return lambda v: DASH if v is None else f"{v:,.{decimals}f}"


def fmt_general(digits):
    """Significant digits that keep tiny values visible: 4.611e-08 rather than 0.0000."""
    return lambda v: DASH if v is None else f"{v:.{digits}g}"


def fmt_int(value):
    return DASH if value is None else f"{int(round(value)):,}"


def fmt_giga(value):
    return DASH if value is None else fmt_sig(value / 1e9, 3)


def fmt_text(value):
    return DASH if value in (None, "") else str(value)


def csv_value(value):
    if value is None:
        return ""
    if isinstance(value, float):
        return str(int(value)) if value.is_integer() and abs(value) < 1e15 else format(value, ".10g")
    return str(value)


# ---------------------------------------------------------------- table model

@dataclass
class Column:
    key: str
    header: str
    fmt: object = fmt_sig


@dataclass
class Table:
    """Rows of dicts; csv_keys orders the CSV, markdown() renders a view."""
    title: str
    csv_keys: list
    rows: list
    notes: list = field(default_factory=list)


def write_csv(table, path):
    with open(path, "w", newline="", encoding="utf-8") as handle:
        writer = csv.writer(handle)
        writer.writerow(table.csv_keys)
        for row in table.rows:
            writer.writerow([csv_value(row.get(k)) for k in table.csv_keys])


def markdown_grid(headers, lines):
    """A Markdown table from header strings and rows of cell strings."""
    out = ["| " + " | ".join(headers) + " |", "|" + "|".join("---" for _ in headers) + "|"]
    out.extend("| " + " | ".join(cells) + " |" for cells in lines)
    return "\n".join(out)


def markdown_rows(columns, rows):
    return markdown_grid([c.header for c in columns], [[c.fmt(r.get(c.key)) for c in columns] for r in rows])


def markdown_paired(columns, rows, ours_label):
    """Two lines per model: ours, then the paper's (keys prefixed paper_)."""
    headers = ["Model", "Source"] + [c.header for c in columns]
    lines = []
    for row in rows:
        lines.append([row["model"], ours_label] + [c.fmt(row.get(c.key)) for c in columns])
        lines.append([row["model"], paper.DEVICE_LABEL] + [c.fmt(row.get("paper_" + c.key)) for c in columns])
    return markdown_grid(headers, lines)


def markdown_section(title, notes, body):
    parts = [f"## {title}", ""]
    if notes:
        parts.extend(f"- {n}" for n in notes)
        parts.append("")
    parts.extend([body, ""])
    return "\n".join(parts)


# ---------------------------------------------------------------- Tables 3-4

TIME_COLUMNS = ([Column("nodes", "Nodes", fmt_int), Column("tets", "Tets", fmt_int),
                 Column("cpu_serial_ms", "CPU serial")]
                + [Column(variant_key(*v) + "_ms", "GPU " + variant_header(*v)) for v in PAPER_VARIANTS]
                + [Column("cpu_threads_ms", "CPU threads")]
                + [Column(variant_key(*v) + "_ms", "GPU " + variant_header(*v)) for v in OUR_EXTRA_VARIANTS])


def time_row(result, form, model, metric):
    nodes, tets = result.mesh_size(model)
    row = {"model": model, "nodes": nodes, "tets": tets,
           "cpu_serial_ms": result.time_ms(f"Serial/{form}/{model}", metric),
           "cpu_threads_ms": result.time_ms(f"Threads/{form}/{model}", metric)}
    for layout, strategy in ALL_VARIANTS:
        row[variant_key(layout, strategy) + "_ms"] = result.time_ms(bj.gpu_name(form, layout, strategy, model), metric)
    row["paper_nodes"], row["paper_tets"] = paper.MODEL_SIZES[model]
    row["paper_cpu_serial_ms"] = paper.time_ms(form, "cpu", model)
    for layout, strategy in PAPER_VARIANTS:
        key = variant_key(layout, strategy)
        row[f"paper_{key}_ms"] = paper.time_ms(form, key, model)
    return row


def time_table(result, form, metric):
    number = paper.TABLE_NUMBER["time"][form]
    keys = (["model", "nodes", "tets", "cpu_serial_ms"]
            + [variant_key(*v) + "_ms" for v in PAPER_VARIANTS]
            + ["cpu_threads_ms"] + [variant_key(*v) + "_ms" for v in OUR_EXTRA_VARIANTS]
            + ["paper_nodes", "paper_tets", "paper_cpu_serial_ms"]
            + [f"paper_{variant_key(*v)}_ms" for v in PAPER_VARIANTS])
    rows = [time_row(result, form, model, metric) for model in bj.MODELS]
    notes = [f"Running time in ms ({metric}); paper rows: Table {number}, {paper.GPU_DETAIL}, CPU {paper.CPU}.",
             "single = one block, multi = multiple blocks, coloured = ours only (graph-coloured Gauss-Seidel).",
             "The paper used one serial CPU time per model for both forms; ours measures each form."]
    return Table(f"Table {number}: running time, {FORM_TITLE[form]} (ms)", keys, rows, notes)


# ---------------------------------------------------------------- Tables 5-6

SPEEDUP_COLUMNS = ([Column(variant_key(*v), "GPU " + variant_header(*v), fmt_fixed(3)) for v in PAPER_VARIANTS]
                   + [Column("max", "Max (paper's four)", fmt_fixed(3))]
                   + [Column(variant_key(*v), "GPU " + variant_header(*v), fmt_fixed(3)) for v in OUR_EXTRA_VARIANTS]
                   + [Column("threads_over_serial", "CPU threads", fmt_fixed(3))])

THREADS_COLUMNS = ([Column("model", "Model", fmt_text), Column("cpu_threads_ms", "CPU threads (ms)")]
                   + [Column(variant_key(*v) + "_vs_threads", "GPU " + variant_header(*v), fmt_fixed(3))
                      for v in ALL_VARIANTS])


def speedup_row(result, form, model, metric):
    serial = result.time_ms(f"Serial/{form}/{model}", metric)
    threads = result.time_ms(f"Threads/{form}/{model}", metric)
    row = {"model": model, "nodes": result.mesh_size(model)[0],
           "cpu_serial_ms": serial, "cpu_threads_ms": threads,
           "threads_over_serial": bj.ratio(serial, threads)}
    for layout, strategy in ALL_VARIANTS:
        key = variant_key(layout, strategy)
        gpu = result.time_ms(bj.gpu_name(form, layout, strategy, model), metric)
        row[key] = bj.ratio(serial, gpu)
        row[key + "_vs_threads"] = bj.ratio(threads, gpu)
    paper_four = [row[variant_key(*v)] for v in PAPER_VARIANTS if row[variant_key(*v)] is not None]
    row["max"] = max(paper_four) if paper_four else None
    for column in paper.SPEEDUP_COLUMNS:
        row["paper_" + column] = paper.speedup(form, column, model)
    return row


def speedup_table(result, form, metric):
    number = paper.TABLE_NUMBER["speedup"][form]
    keys = (["model", "nodes", "cpu_serial_ms", "cpu_threads_ms"]
            + [variant_key(*v) for v in ALL_VARIANTS] + ["max", "threads_over_serial"]
            + [variant_key(*v) + "_vs_threads" for v in ALL_VARIANTS]
            + ["paper_" + c for c in paper.SPEEDUP_COLUMNS])
    rows = [speedup_row(result, form, model, metric) for model in bj.MODELS]
    notes = [f"Speedup = our serial CPU time / the variant's time ({metric}); paper rows: Table {number} "
             f"(over their serial CPU code, {paper.CPU}).",
             "Max is over the paper's four GPU columns; CPU threads = serial / threaded CPU time."]
    return Table(f"Table {number}: speedup over serial CPU, {FORM_TITLE[form]}", keys, rows, notes)


# ---------------------------------------------------------------- quality, scaling, runs

QUALITY_COLUMNS = ([Column("benchmark", "Benchmark", fmt_text), Column("sweeps", "Sweeps", fmt_int),
                    Column("accepted", "Accepted", fmt_int)]
                   # q min of the paper models' inputs is about 5e-8, which fixed decimals show as 0.0000.
                   + [Column(k, k.replace("_", " "), fmt_general(4)) for k in QUALITY_KEYS[2:4]]
                   + [Column(k, k.replace("_", " "), fmt_fixed(4)) for k in QUALITY_KEYS[4:6]]
                   + [Column(k, k.replace("_", " "), fmt_int) for k in QUALITY_KEYS[6:]])

SCALING_COLUMNS = [Column("benchmark", "Benchmark", fmt_text), Column("nodes", "Nodes", fmt_int),
                   Column("tets", "Tets", fmt_int), Column("sweeps", "Sweeps", fmt_int),
                   Column("ms_per_sweep", "ms/sweep"), Column("node_updates_per_s", "G node updates/s", fmt_giga),
                   Column("bytes_per_s", "GB/s counted", fmt_giga), Column("bytes_per_sweep", "MB/sweep",
                                                                           lambda v: fmt_sig(v and v / 1e6)),
                   Column("floor_ms_per_sweep", "floor ms/sweep"),
                   Column("ratio_to_floor", "time / floor", fmt_fixed(2))]

KIND_ORDER = {"serial": 0, "ordinary": 1, "threads": 2, "gpu": 3, "copy": 4, "other": 5}


def mesh_order(mesh):
    """Paper models in their order, then lattices by size, then anything else."""
    if mesh in bj.MODELS:
        return (0, bj.MODELS.index(mesh), "")
    size = bj.lattice_size(mesh)
    if size is not None:
        return (1, size, "")
    return (2, 0, mesh or "")


def run_order(name):
    info = bj.parse_name(name)
    return (mesh_order(info.get("mesh")), KIND_ORDER[info["kind"]], name)


def quality_table(result):
    rows = []
    for name in sorted(result.runs, key=run_order):
        counters = result.runs[name].counters
        if not any(k.startswith("q_") for k in counters):
            continue
        row = {"benchmark": name, "mesh": bj.parse_name(name).get("mesh")}
        row.update({k: counters.get(k) for k in QUALITY_KEYS})
        rows.append(row)
    notes = ["q = radius ratio scaled to [0, 1] (1 = regular tet); low q = tets with q < 0.1; "
             "inverted = tets with non-positive volume."]
    return Table("Mesh quality before and after smoothing", ["benchmark", "mesh"] + list(QUALITY_KEYS), rows, notes)


def scaling_row(result, name, copy_bw):
    run = result.runs[name]
    info = bj.parse_name(name)
    nodes, tets = run.counters.get("nodes"), run.counters.get("tets")
    if nodes is None or tets is None:
        mesh_nodes, mesh_tets = result.mesh_size(info["mesh"])
        nodes, tets = nodes if nodes is not None else mesh_nodes, tets if tets is not None else mesh_tets
    ms_per_sweep, bytes_per_s = run.counters.get("ms_per_sweep"), run.counters.get("bytes_per_s")
    bytes_per_sweep = bytes_per_s * ms_per_sweep / 1000 if None not in (bytes_per_s, ms_per_sweep) else None
    floor_ms = bytes_per_sweep / copy_bw * 1000 if None not in (bytes_per_sweep, copy_bw) and copy_bw > 0 else None
    return {"benchmark": name, "method": info["method"], "form": info["form"], "layout": info["layout"],
            "strategy": info["strategy"], "mesh": info["mesh"], "lattice_n": info.get("lattice_n"),
            "nodes": nodes, "tets": tets,
            "sweeps": run.counters.get("sweeps"), "ms_per_sweep": ms_per_sweep,
            "node_updates_per_s": run.counters.get("node_updates_per_s"), "bytes_per_s": bytes_per_s,
            "bytes_per_sweep": bytes_per_sweep, "copy_bytes_per_s": copy_bw, "floor_ms_per_sweep": floor_ms,
            "ratio_to_floor": bj.ratio(ms_per_sweep, floor_ms)}


def scaling_order(name):
    info = bj.parse_name(name)
    return (bj.METHODS.index(info["method"]), info["form"], info["layout"], bj.STRATEGIES.index(info["strategy"]),
            mesh_order(info["mesh"]))


def scaling_table(result):
    copy_bw = result.copy_bytes_per_s()
    names = [n for n in result.runs if bj.parse_name(n)["kind"] == "gpu"
             and result.runs[n].counters.get("ms_per_sweep") is not None]
    rows = [scaling_row(result, n, copy_bw) for n in sorted(names, key=scaling_order)]
    copy_text = f"{copy_bw / 1e9:.1f} GB/s" if copy_bw else "not measured in this run"
    notes = ["Bytes per sweep = bytes_per_s x ms_per_sweep (as counted by the benchmark of the run: "
             "bytes_per_sweep in bench/bench_counters.hpp); "
             f"floor = bytes per sweep / measured device copy bandwidth ({copy_text}); "
             "time / floor >= 1, and 1 would be copy speed.",
             "Adaptive runs first, then ordinary Laplacian ones (Ordinary/..., whose count has no star: "
             "they read none); within each, paper models first, then lattice-N meshes by size."]
    keys = ["benchmark", "method", "form", "layout", "strategy", "mesh", "lattice_n", "nodes", "tets", "sweeps",
            "ms_per_sweep", "node_updates_per_s", "bytes_per_s", "bytes_per_sweep", "copy_bytes_per_s",
            "floor_ms_per_sweep", "ratio_to_floor"]
    return Table("Throughput per sweep and the memory floor (GPU runs)", keys, rows, notes)


COLOUR_COLUMNS = [Column("benchmark", "Benchmark", fmt_text), Column("colour", "Colour", fmt_int),
                  Column("nodes", "Nodes", fmt_int), Column("ms", "ms (all sweeps)"),
                  Column("share", "Share of loop", lambda v: DASH if v is None else f"{100 * v:.1f}%"),
                  Column("us_per_sweep", "us/sweep"), Column("ns_per_node", "ns/node/sweep")]


def colour_rows(name, run):
    """One row per colour class of a coloured GPU run that timed its colours."""
    counters = run.counters
    colours = int(counters.get("colours") or 0)
    times = [counters.get(f"colour_ms_{k}") for k in range(colours)]
    if colours == 0 or None in times:
        return []
    total, sweeps = sum(times), counters.get("sweeps") or 0
    rows = []
    for k, ms in enumerate(times):
        nodes = counters.get(f"colour_nodes_{k}")
        per_sweep = ms / sweeps if sweeps else None
        rows.append({"benchmark": name, "mesh": bj.parse_name(name)["mesh"], "colour": k, "nodes": nodes, "ms": ms,
                     "share": ms / total if total > 0 else None, "us_per_sweep": per_sweep and per_sweep * 1000,
                     "ns_per_node": per_sweep * 1e6 / nodes if per_sweep is not None and nodes else None})
    return rows


def colour_table(result):
    names = [n for n in result.runs if bj.parse_name(n)["kind"] == "gpu"
             and bj.parse_name(n)["strategy"] == "Coloured"]
    rows = [row for n in sorted(names, key=scaling_order) for row in colour_rows(n, result.runs[n])]
    notes = ["The coloured loop's time class by class: a colour's step runs from the grid barrier that ends the "
             "previous colour to the one that ends it (barrier waits included), read on the device's global "
             "timer and summed over the sweeps; share = of the summed steps, which make up the smoothing phase.",
             "ns/node/sweep = us/sweep over the class's nodes: what a node of that class costs per sweep."]
    keys = ["benchmark", "mesh", "colour", "nodes", "ms", "share", "us_per_sweep", "ns_per_node"]
    return Table("Where the coloured loop's time goes, colour by colour (GPU)", keys, rows, notes)


PHASES = ("tet_quality", "node_update", "repair", "stopping_rule")
PHASE_COLUMNS = ([Column("benchmark", "Benchmark", fmt_text), Column("ms_per_sweep", "timed ms/sweep"),
                  Column("phase_run_ms_per_sweep", "phase run ms/sweep")]
                 + [Column(k, k.replace("_", " ")) for k in PHASES]
                 + [Column("rest", "rest"),
                    Column("node_update_share", "node update share", lambda v: DASH if v is None else f"{100 * v:.1f}%")])


def phase_row(name, run):
    """A MultiBlock GPU run's ms per sweep by kernel, from its phase run; None if it has none."""
    counters = run.counters
    total = counters.get("phase_run_ms_per_sweep")
    if total is None:
        return None
    row = {"benchmark": name, "mesh": bj.parse_name(name)["mesh"], "ms_per_sweep": counters.get("ms_per_sweep"),
           "phase_run_ms_per_sweep": total}
    row.update({k: counters.get(f"phase_ms_per_sweep_{k}") for k in PHASES})
    # The run's own remainder where the benchmark wrote it: the medians of
    # separate counters may come from different repetitions.
    rest = counters.get("phase_run_rest_ms_per_sweep")
    row["rest"] = rest if rest is not None else total - sum(v for v in (row[k] for k in PHASES) if v is not None)
    row["node_update_share"] = row["node_update"] / total if row["node_update"] is not None and total > 0 else None
    return row


def phase_table(result):
    names = [n for n in result.runs if bj.parse_name(n)["kind"] == "gpu"]
    rows = [row for row in (phase_row(n, result.runs[n]) for n in sorted(names, key=scaling_order)) if row]
    notes = ["Where a MultiBlock sweep's time goes, in ms per sweep: each kind of kernel timed with CUDA events in a "
             "run of its own after the timed ones (the events add to it, so its ms/sweep is shown beside the timed "
             "run's). tet quality = the adaptive sweeps' quality cache; node update = the sweep kernel; repair = Form "
             "A's conflict repair and move count; stopping rule = the verdict kernel; rest = what the kernels leave "
             "of that run's ms/sweep: the host's checks of the stop flag and the loop's set-up. The first kernel "
             "after each check carries its launch latency (kernels/cuda/phase_timer.hpp).",
             "Each column is the median of its own counter over the repetitions, so the columns of a row need not "
             "add up."]
    keys = ["benchmark", "mesh", "ms_per_sweep", "phase_run_ms_per_sweep", *PHASES, "rest", "node_update_share"]
    return Table("Where a MultiBlock sweep's time goes, kernel by kernel (GPU)", keys, rows, notes)


RUNS_COLUMNS = [Column("benchmark", "Benchmark", fmt_text), Column("time_ms", "Time (ms)"),
                Column("statistic", "Reduced as", fmt_text), Column("sweeps", "Sweeps", fmt_int)]


def runs_table(result, metric):
    rows = [{"benchmark": name, "time_ms": run.value(metric), "statistic": run.statistic,
             "sweeps": run.counters.get("sweeps")}
            for name, run in sorted(result.runs.items(), key=lambda item: run_order(item[0]))]
    notes = [f"Time: {metric} in ms."]
    notes += [f"{name}: not measured ({message})" for name, message in sorted(result.errors.items())]
    return Table("All benchmarks", ["benchmark", "time_ms", "statistic", "sweeps"], rows, notes)


# ---------------------------------------------------------------- output

def header_markdown(result, metric):
    # The precision is in the title line: float and double runs give different tables.
    lines = [f"# tetsmooth results beside the paper ({result.precision_text()})", ""]
    lines += [f"- {line}" for line in result.describe()]
    lines += [f"- result file: `{os.path.basename(result.path)}`; times: {metric}, median of repetitions "
              "where present, else the mean of iterations",
              f"- paper: {paper.SOURCE}; {paper.GPU_DETAIL}; CPU {paper.CPU}", ""]
    return "\n".join(lines)


def build_tables(result, metric="real_time"):
    """All tables, keyed by their CSV stem."""
    return {"table3": time_table(result, "FormA", metric), "table4": time_table(result, "FormB", metric),
            "table5": speedup_table(result, "FormA", metric), "table6": speedup_table(result, "FormB", metric),
            "quality": quality_table(result), "scaling": scaling_table(result), "colours": colour_table(result),
            "phases": phase_table(result), "runs": runs_table(result, metric)}


def tables_markdown(result, tables, metric):
    ours = f"ours: {result.device_label()}"
    parts = [header_markdown(result, metric)]
    for stem in ("table3", "table4"):
        table = tables[stem]
        parts.append(markdown_section(table.title, table.notes, markdown_paired(TIME_COLUMNS, table.rows, ours)))
    for stem in ("table5", "table6"):
        table = tables[stem]
        parts.append(markdown_section(table.title, table.notes, markdown_paired(SPEEDUP_COLUMNS, table.rows, ours)))
        parts.append(markdown_section(table.title.replace("serial CPU", "threaded CPU (ours only)"),
                                      ["Speedup = our threaded CPU time / the GPU variant's time."],
                                      markdown_rows(THREADS_COLUMNS, table.rows)))
    for stem, columns in (("quality", QUALITY_COLUMNS), ("scaling", SCALING_COLUMNS), ("colours", COLOUR_COLUMNS),
                          ("phases", PHASE_COLUMNS), ("runs", RUNS_COLUMNS)):
        table = tables[stem]
        body = markdown_rows(columns, table.rows) if table.rows else "_No benchmarks of this kind in the result._"
        parts.append(markdown_section(table.title, table.notes, body))
    return "\n".join(parts)


def write_tables(result, outdir, metric="real_time"):
    """Write tables.md and the CSV files; returns the paths written."""
    os.makedirs(outdir, exist_ok=True)
    tables = build_tables(result, metric)
    written = []
    for stem, table in tables.items():
        path = os.path.join(outdir, f"{stem}.csv")
        write_csv(table, path)
        written.append(path)
    path = os.path.join(outdir, "tables.md")
    with open(path, "w", encoding="utf-8") as handle:
        handle.write(tables_markdown(result, tables, metric))
    written.append(path)
    return written


def parse_args(argv):
    parser = argparse.ArgumentParser(description="Tables of a bench_smooth result beside the paper's Tables 3-6.")
    bj.add_render_arguments(parser, "folder for tables.md and the CSV files", "tabulate")
    return parser.parse_args(argv)


def main(argv=None):
    args = parse_args(argv)
    result = bj.load_for_rendering(args.result, "make_tables")
    if result is None or not bj.make_outdir(args.outdir, "make_tables"):
        return 2
    for path in write_tables(result, args.outdir, args.metric):
        print(path)
    return 0


if __name__ == "__main__":
    sys.exit(main())
