"""Shared loader for the Google Benchmark JSON that bench_smooth writes.

Used by make_tables.py, make_figures.py, report.py and compare_results.py;
it is a module, not a script:

    from bench_json import load_result
    result = load_result("results/h100-80gb-hbm3/bench_smooth.json")
    result.time_ms("FormB/AoS/MultiBlock/109k")      # -> float or None
    result.counter("Serial/FormB/109k", "q_min_after")

What it does with the file (google/benchmark 1.7.x JSON, --benchmark_out):
  * names: `run_name` when present, else `name` without its aggregate
    suffix; then trailing segments that Google Benchmark appends
    (manual_time, real_time, process_time, repeats:N, iterations:N,
    min_time:X, min_warmup_time:X, threads:N) are stripped, so
    "FormB/AoS/MultiBlock/109k/repeats:5/manual_time" is
    "FormB/AoS/MultiBlock/109k".
  * repetitions: the "median" aggregate when present, else the mean of the
    per-repetition ("iteration") entries, else a "mean" aggregate.  The same
    choice applies to the counters.
  * model labels: bench_smooth --models takes the paper's labels (5k, 10k,
    59k, 77k, 109k) and also the generator names (slope-77k), and uses the
    label as given in the benchmark names and the model_<label>_* context
    keys.  Both spellings are mapped to the label in MODELS here, in one
    place (canonical_model), so "Serial/FormB/slope-77k" is
    "Serial/FormB/77k" for every script.  (A run that lists one model under
    both spellings keeps the entries of the spelling met first.)
  * times are converted to milliseconds from the entry's time_unit.
  * entries that report an error (error_occurred / skipped) are left out and
    listed in `errors`; unknown fields are ignored; custom context values
    (written as strings by AddCustomContext) are parsed as numbers on request.
  * an empty file (bench_smooth writes one when no benchmark was selected),
    a file with an empty "benchmarks" list and a file cut off by a run that
    stopped early raise BenchInputError, so every script exits 2 with a
    message instead of a traceback or empty tables; so does a file whose
    every benchmark reported an error, for the scripts that render it
    (load_result's need_runs).
"""

import json
import math
import os
import re
import sys
from dataclasses import dataclass, field

MODELS = ("5k", "10k", "59k", "77k", "109k")
# Generator names that bench_smooth --models also accepts, by the label in
# MODELS they stand for (generators/models.cpp: "slope-77k" is the 77k model).
MODEL_ALIASES = {"slope-77k": "77k"}
FORMS = ("FormA", "FormB")
LAYOUTS = ("AoS", "SoA")
STRATEGIES = ("SingleBlock", "MultiBlock", "Coloured")
# GPU runs are adaptive smoothing, named Form/Layout/Strategy/mesh; ordinary
# Laplacian GPU runs (Form B, on the scaling meshes) are named
# Ordinary/Layout/Strategy/mesh.
METHODS = ("adaptive", "ordinary")
ORDINARY_GPU = "Ordinary"
COPY_BANDWIDTH = "Memory/CopyBandwidth"

TIME_UNIT_TO_MS = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}

# CPU families smooth in double whatever --precision says; gpu_precision in
# the context is the GPU families' precision.
CPU_PRECISION = "double"
NO_BENCHMARK_HINT = "no benchmark ran? check --benchmark_filter/--models"
CUT_SHORT_HINT = "the run that wrote it stopped early (killed, or bench_smooth failed); run it again"

_SUFFIX_SEGMENT = re.compile(
    r"^(manual_time|real_time|process_time|repeats:\d+|iterations:\d+|"
    r"min_time:[0-9.eE+-]+s?|min_warmup_time:[0-9.eE+-]+s?|threads:\d+)$")

# Fields of a benchmark entry that are not user counters.
_STANDARD_FIELDS = {
    "name", "family_index", "per_family_instance_index", "run_name",
    "run_type", "repetitions", "repetition_index", "threads", "iterations",
    "real_time", "cpu_time", "time_unit", "aggregate_name", "aggregate_unit",
    "error_occurred", "error_message", "skipped", "skip_message", "label",
    "big_o", "rms", "complexity",
}


class BenchInputError(Exception):
    """The result file is missing, unreadable or not benchmark JSON."""


def strip_name(name):
    """Remove Google Benchmark's trailing option segments from a name."""
    parts = name.split("/")
    while len(parts) > 1 and _SUFFIX_SEGMENT.match(parts[-1]):
        parts.pop()
    return "/".join(parts)


def entry_name(entry):
    """The stripped benchmark name of one JSON entry."""
    name = entry.get("run_name")
    if not name:
        name = entry.get("name", "")
        aggregate = entry.get("aggregate_name")
        if entry.get("run_type") == "aggregate" and aggregate and name.endswith("_" + aggregate):
            name = name[: -len(aggregate) - 1]
    return strip_name(name)


def canonical_model(label):
    """The MODELS label of a model, whichever spelling bench_smooth was given."""
    return MODEL_ALIASES.get(label, label)


def canonical_name(name):
    """A stripped benchmark name with its mesh segment (the last) as in MODELS."""
    head, _, mesh = name.rpartition("/")
    return f"{head}/{canonical_model(mesh)}" if head else name


def _canonical_context(context):
    """The context with model_<alias>_* keys renamed to the MODELS label (first spelling wins)."""
    renamed = {}
    for key, value in context.items():
        match = re.fullmatch(r"model_(.+)_(nodes|tets)", key)
        if match:
            key = f"model_{canonical_model(match.group(1))}_{match.group(2)}"
        renamed.setdefault(key, value)
    return renamed


def cuda_version_text(value):
    """CUDA's version integer (major*1000 + minor*10, e.g. 13000) as "13.0"; other text unchanged."""
    text = str(value).strip()
    if not text.isdigit() or int(text) < 1000:
        return text
    number = int(text)
    return f"{number // 1000}.{(number % 1000) // 10}"


def gpu_name(form, layout, strategy, mesh):
    """Benchmark name of a GPU family, e.g. FormB/AoS/MultiBlock/109k."""
    return f"{form}/{layout}/{strategy}/{mesh}"


def parse_name(name):
    """Split a stripped name into its parts.

    Returns a dict with key "kind" ("gpu", "serial", "threads", "ordinary",
    "copy" or "other") and, where they apply, "form", "layout", "strategy",
    "method" (GPU runs: "adaptive" or "ordinary"), "mesh" and "lattice_n"
    (int, for lattice-N meshes). "ordinary" as a kind is the serial CPU
    ordinary run; an ordinary GPU run is of kind "gpu".
    """
    parts = name.split("/")
    info = {"kind": "other", "name": name}
    if name == COPY_BANDWIDTH:
        info["kind"] = "copy"
    elif len(parts) == 4 and parts[0] in FORMS + (ORDINARY_GPU,) and parts[1] in LAYOUTS and parts[2] in STRATEGIES:
        ordinary = parts[0] == ORDINARY_GPU
        info.update(kind="gpu", form="FormB" if ordinary else parts[0], layout=parts[1], strategy=parts[2],
                    method="ordinary" if ordinary else "adaptive", mesh=parts[3])
    elif len(parts) == 3 and parts[0] == "Serial" and parts[1] in FORMS:
        info.update(kind="serial", form=parts[1], mesh=parts[2])
    elif len(parts) == 3 and parts[0] == "Threads" and parts[1] in FORMS:
        info.update(kind="threads", form=parts[1], mesh=parts[2])
    elif len(parts) == 3 and parts[0] == "Serial" and parts[1] == "Ordinary":
        info.update(kind="ordinary", mesh=parts[2])
    size = lattice_size(info.get("mesh"))
    if size is not None:
        info["lattice_n"] = size
    return info


def lattice_size(mesh):
    """N of a "lattice-N" mesh label, else None."""
    match = re.fullmatch(r"lattice-(\d+)", mesh or "")
    return int(match.group(1)) if match else None


def _is_number(value):
    return isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value)


def _to_number(value):
    """A context value as a float, or None (custom context values are strings)."""
    if _is_number(value):
        return float(value)
    try:
        number = float(str(value).strip())
    except (TypeError, ValueError):
        return None
    return number if math.isfinite(number) else None


@dataclass
class Run:
    """One benchmark, reduced over its repetitions.

    statistic says how: "median of N", "mean of N" or "single".
    """
    name: str
    real_time_ms: float
    cpu_time_ms: float
    counters: dict = field(default_factory=dict)
    statistic: str = "single"

    def value(self, metric):
        """real_time / cpu_time in ms, or any counter; None when absent."""
        if metric == "real_time":
            return self.real_time_ms
        if metric == "cpu_time":
            return self.cpu_time_ms
        return self.counters.get(metric)


def _entry_times_ms(entry):
    scale = TIME_UNIT_TO_MS.get(entry.get("time_unit", "ns"))
    if scale is None:
        raise BenchInputError(f"{entry.get('name')}: unknown time_unit {entry.get('time_unit')!r}")
    real, cpu = entry.get("real_time"), entry.get("cpu_time")
    return (real * scale if _is_number(real) else None,
            cpu * scale if _is_number(cpu) else None)


def _entry_counters(entry):
    return {k: float(v) for k, v in entry.items() if k not in _STANDARD_FIELDS and _is_number(v)}


def _run_from_entry(name, entry, statistic):
    real, cpu = _entry_times_ms(entry)
    return Run(name, real, cpu, _entry_counters(entry), statistic)


def _mean(values):
    values = [v for v in values if v is not None]
    return sum(values) / len(values) if values else None


def _run_from_iterations(name, entries):
    times = [_entry_times_ms(e) for e in entries]
    counter_dicts = [_entry_counters(e) for e in entries]
    keys = []
    for counters in counter_dicts:
        keys.extend(k for k in counters if k not in keys)
    counters = {k: _mean([c.get(k) for c in counter_dicts]) for k in keys}
    statistic = "single" if len(entries) == 1 else f"mean of {len(entries)}"
    return Run(name, _mean([t[0] for t in times]), _mean([t[1] for t in times]), counters, statistic)


def _reduce(name, entries):
    """Pick the median aggregate, else the mean of iterations, else a mean aggregate."""
    iterations = [e for e in entries if e.get("run_type", "iteration") != "aggregate"]
    aggregates = {e.get("aggregate_name"): e for e in entries if e.get("run_type") == "aggregate"}
    count = len(iterations) or int(entries[0].get("repetitions", 0) or 0)
    if "median" in aggregates:
        return _run_from_entry(name, aggregates["median"], f"median of {count}" if count else "median")
    if iterations:
        return _run_from_iterations(name, iterations)
    if "mean" in aggregates:
        return _run_from_entry(name, aggregates["mean"], f"mean of {count}" if count else "mean")
    return None


def _is_error(entry):
    skipped = entry.get("skipped")
    return bool(entry.get("error_occurred")) or (skipped not in (None, False, "", "NotSkipped"))


class BenchResult:
    """A loaded result file: context (dict), runs (name -> Run, file order), errors."""

    def __init__(self, path, context, runs, errors):
        self.path = path
        self.context = context
        self.runs = runs
        self.errors = errors

    def names(self):
        return list(self.runs)

    def run(self, name):
        return self.runs.get(name)

    def value(self, name, metric="real_time"):
        run = self.runs.get(name)
        return run.value(metric) if run else None

    def time_ms(self, name, metric="real_time"):
        return self.value(name, metric)

    def counter(self, name, key):
        return self.value(name, key)

    def context_number(self, key):
        return _to_number(self.context.get(key)) if key in self.context else None

    def context_text(self, key, default=None):
        value = self.context.get(key)
        return default if value in (None, "") else str(value)

    def has_gpu_runs(self):
        return any(parse_name(n)["kind"] == "gpu" for n in self.runs)

    def copy_bytes_per_s(self):
        return self.counter(COPY_BANDWIDTH, "bytes_per_s")

    def mesh_size(self, mesh):
        """(nodes, tets) of a mesh from the context, else from any run's counters."""
        nodes = self.context_number(f"model_{mesh}_nodes")
        tets = self.context_number(f"model_{mesh}_tets")
        for name, run in self.runs.items():
            if nodes is not None and tets is not None:
                break
            if parse_name(name).get("mesh") == mesh:
                nodes = nodes if nodes is not None else run.counters.get("nodes")
                tets = tets if tets is not None else run.counters.get("tets")
        return nodes, tets

    def gpu_precision(self):
        """"float" or "double" (the GPU families'), or None when the context does not say."""
        return self.context_text("gpu_precision")

    def precision_tag(self):
        """Short precision note for titles: "float", "double" or "precision not recorded"."""
        return self.gpu_precision() or "precision not recorded"

    def precision_text(self):
        """One line saying in which precision the GPU and the CPU runs smoothed."""
        precision = self.gpu_precision()
        if not self.has_gpu_runs():
            return f"{CPU_PRECISION} (CPU runs only)"
        if precision is None:
            return f"GPU runs: not recorded in the result's context (no gpu_precision); CPU runs {CPU_PRECISION}"
        return f"GPU runs in {precision}, CPU runs in {CPU_PRECISION}"

    def device_label(self):
        """Short GPU name for legends and titles."""
        return self.context_text("gpu_name") or ("no GPU" if not self.has_gpu_runs() else "GPU")

    def cpu_label(self):
        host = self.context_text("host_name", "host")
        cpus = self.context_number("num_cpus")
        return f"{host}, {int(cpus)} CPUs" if cpus else host

    def describe(self):
        """Lines naming the device, host, build and date of the run."""
        gpu = self.context_text("gpu_name")
        if gpu:
            extras = []
            sms = self.context_number("sm_count")
            if sms:
                extras.append(f"{int(sms)} SMs")
            if self.context_text("cuda_version"):
                extras.append(f"CUDA {cuda_version_text(self.context_text('cuda_version'))}")
            gpu_line = gpu + (f" ({', '.join(extras)})" if extras else "")
        else:
            gpu_line = "none in this run (CPU baselines only)"
        mhz = self.context_number("mhz_per_cpu")
        cpu_line = self.cpu_label() + (f" @ {mhz:.0f} MHz" if mhz else "")
        copy = self.copy_bytes_per_s()
        lines = [
            f"GPU: {gpu_line}",
            f"CPU: {cpu_line}",
            f"precision: {self.precision_text()}",
            f"git SHA: {self.context_text('git_sha', 'unknown')}",
            f"date: {self.context_text('date', 'unknown')}",
            # Google Benchmark's own build as its library reports it (Debian's
            # package says "debug"), not tetsmooth's, which is a Release build.
            f"Google Benchmark library build: {self.context_text('library_build_type', 'unknown')}",
        ]
        if copy:
            lines.append(f"measured device copy bandwidth: {copy / 1e9:.1f} GB/s (Memory/CopyBandwidth)")
        # Results from before bench_smooth recorded its command have none.
        command = self.context_text("command_line")
        if command:
            lines.append(f"command: `{command}`")
        return lines


def parse_result(document, path="<memory>"):
    """Build a BenchResult from an already parsed JSON document."""
    if not isinstance(document, dict) or not isinstance(document.get("benchmarks"), list):
        raise BenchInputError(f"{path}: not Google Benchmark JSON (no \"benchmarks\" list)")
    if not document["benchmarks"]:
        raise BenchInputError(f"{path}: the \"benchmarks\" list is empty: {NO_BENCHMARK_HINT}")
    context = document.get("context") if isinstance(document.get("context"), dict) else {}
    groups, errors, spelling = {}, {}, {}
    for index, entry in enumerate(document["benchmarks"]):
        if not isinstance(entry, dict) or "name" not in entry:
            raise BenchInputError(f"{path}: benchmarks[{index}] has no name")
        written = entry_name(entry)
        name = canonical_name(written)
        if spelling.setdefault(name, written) != written:
            continue  # the same model under its other spelling: the first one met is kept
        if _is_error(entry):
            errors[name] = str(entry.get("error_message") or entry.get("skip_message") or "error")
            continue
        groups.setdefault(name, []).append(entry)
    runs = {}
    for name, entries in groups.items():
        run = _reduce(name, entries)
        if run is not None:
            runs[name] = run
    return BenchResult(path, _canonical_context(context), runs, errors)


def load_result(path, need_runs=False):
    """Read a bench_smooth JSON file; raises BenchInputError with a clear message.

    need_runs: refuse a file whose every benchmark reported an error, as the
    table and figure scripts do (they would render blanks); compare_results
    reads one as a regression instead. The copy-bandwidth run alone is
    nothing to render either.
    """
    if os.path.isdir(path):
        raise BenchInputError(f"{path}: a folder, not a result file")
    if not os.path.isfile(path):
        raise BenchInputError(f"{path}: no such file")
    try:
        with open(path, encoding="utf-8") as handle:
            text = handle.read()
        if not text.strip():
            raise BenchInputError(f"{path}: empty file: {NO_BENCHMARK_HINT}")
        if not text.lstrip().startswith(("{", "[")):
            # The console report (bench_smooth > file) or --benchmark_out_format=csv.
            raise BenchInputError(f"{path}: not JSON (it starts {text.lstrip().splitlines()[0][:40]!r}): a console "
                                  "or CSV report? bench_smooth writes JSON with --benchmark_out=FILE "
                                  "--benchmark_out_format=json")
        document = json.loads(text)
    except json.JSONDecodeError as error:
        # Google Benchmark writes each result as it finishes, one field a
        # line, so a run that was killed or threw leaves the file cut off:
        # the parser stops at its end or inside its last line.
        body = text.rstrip()
        if error.pos >= len(body) or ("\n" in body and "\n" not in body[error.pos:]):
            raise BenchInputError(f"{path}: the JSON ends before it is complete (line {error.lineno}): "
                                  f"{CUT_SHORT_HINT}") from error
        raise BenchInputError(f"{path}: bad JSON at line {error.lineno}, column {error.colno}: {error.msg}") from error
    except (OSError, UnicodeDecodeError) as error:
        raise BenchInputError(f"{path}: cannot read: {error}") from error
    result = parse_result(document, path)
    if need_runs and not any(parse_name(name)["kind"] != "copy" for name in result.runs):
        if result.errors:
            name, message = next(iter(result.errors.items()))
            raise BenchInputError(f"{path}: every smoothing benchmark reported an error ({len(result.errors)}; "
                                  f"the first, {name}: {message})")
        raise BenchInputError(f"{path}: no smoothing benchmark with a result: {NO_BENCHMARK_HINT}")
    return result


def add_render_arguments(parser, outdir_help, metric_use, quality_model=False):
    """The command line shared by the scripts that render a result: the JSON,
    the output folder, --quality-model where Figure 13 is drawn, and
    --metric ("which time to <metric_use>")."""
    parser.add_argument("result", help="bench_smooth --benchmark_out JSON")
    parser.add_argument("outdir", help=outdir_help)
    if quality_model:
        parser.add_argument("--quality-model", default="109k", choices=MODELS, type=canonical_model,
                            help="model whose histograms Figure 13 shows (default 109k)")
    parser.add_argument("--metric", default="real_time", choices=("real_time", "cpu_time"),
                        help=f"which time to {metric_use} (default real_time)")
    return parser


def load_for_rendering(path, program):
    """load_result(path, need_runs=True) for a rendering script, or None once
    the reason is printed on stderr as "program: reason" (the script then
    exits with status 2, having written nothing)."""
    try:
        return load_result(path, need_runs=True)
    except BenchInputError as error:
        print(f"{program}: {error}", file=sys.stderr)
        return None


def make_outdir(path, program):
    """Create a rendering script's output folder; False once the reason is
    printed on stderr as "program: reason" (the script then exits with
    status 2 instead of a traceback)."""
    try:
        os.makedirs(path, exist_ok=True)
    except OSError as error:
        print(f"{program}: cannot write into {path}: {error.strerror}", file=sys.stderr)
        return False
    if not os.access(path, os.W_OK):
        print(f"{program}: cannot write into {path}: permission denied", file=sys.stderr)
        return False
    return True


def ratio(numerator, denominator):
    """numerator / denominator, or None when either is missing or the denominator is not positive."""
    if numerator is None or denominator is None or denominator <= 0:
        return None
    return numerator / denominator
