"""The paper's published numbers, as data.

Source: "Designing Parallel Adaptive Laplacian Smoothing for Improving
Tetrahedral Mesh Quality on the GPU" (MDPI, 2021, CC BY 4.0), §4:
Table 1 (workstation), Table 2 (models), Tables 3-4 (running time, ms, Form A
and Form B) and Tables 5-6 (speedup over the serial CPU version, Form A and
Form B).  Text copy: /work/shared/paper/adaptive-laplacian-tet-gpu.txt.

Transcription notes:
  * The paper's CPU column is the same in Tables 3 and 4 (one serial time per
    model is used for both forms).
  * Table 6's rows for 77k and 109k are printed on one line in the text copy;
    they are split here as 77k = 13.366 22.447 12.530 13.411 22.447 and
    109k = 10.261 22.620 8.389 16.409 22.620.
  * The published speedups are kept as printed.  A few differ from the
    quotient of the published times in the third decimal (10k Form B AoS
    single block: 3745/542 = 6.910, printed 6.906); tests allow 0.2 %.
  * 77k is the slope model, the others are random-point Delaunay boxes.

Usage (as a module):
    import paper_numbers as paper
    paper.time_ms("FormB", "aos_multi", "109k")     # 1618
    paper.speedup("FormB", "aos_multi", "109k")     # 22.62
"""

SOURCE = ("Designing Parallel Adaptive Laplacian Smoothing for Improving Tetrahedral "
          "Mesh Quality on the GPU (MDPI, 2021), Tables 1-6")

GPU = "NVIDIA Quadro P6000"
GPU_DETAIL = "NVIDIA Quadro P6000 (3840 cores, 24 GB), CUDA 11.0"
CPU = "Intel Xeon Gold 2.30 GHz (serial code)"
DEVICE_LABEL = f"paper: {GPU}"

MODELS = ("5k", "10k", "59k", "77k", "109k")

# Table 2: (nodes, tetrahedra).
MODEL_SIZES = {
    "5k": (5000, 32978),
    "10k": (10000, 66542),
    "59k": (59261, 391220),
    "77k": (76928, 388428),
    "109k": (109260, 727088),
}

# Column keys: "cpu" is the serial CPU version; GPU columns are
# <layout>_<strategy> with single = one block, multi = multiple blocks.
TIME_COLUMNS = ("cpu", "aos_single", "aos_multi", "soa_single", "soa_multi")
SPEEDUP_COLUMNS = ("aos_single", "aos_multi", "soa_single", "soa_multi", "max")

# Table 3 (Form A) and Table 4 (Form B): running time in ms, TIME_COLUMNS order.
RUNNING_TIME_MS = {
    "FormA": {
        "5k": (1473, 450, 467, 151, 139),
        "10k": (3745, 537, 535, 775, 331),
        "59k": (8452, 799, 954, 986, 1254),
        "77k": (15825, 3252, 1675, 3505, 2231),
        "109k": (36592, 5811, 4866, 6718, 4140),
    },
    "FormB": {
        "5k": (1473, 169, 155, 130, 96),
        "10k": (3745, 542, 304, 287, 389),
        "59k": (8452, 763, 502, 726, 654),
        "77k": (15825, 1184, 705, 1263, 1180),
        "109k": (36592, 3566, 1618, 4362, 2230),
    },
}

# Table 5 (Form A) and Table 6 (Form B): speedup over serial, SPEEDUP_COLUMNS order.
SPEEDUP = {
    "FormA": {
        "5k": (3.273, 3.154, 9.755, 10.597, 10.597),
        "10k": (6.974, 7.004, 4.832, 11.310, 11.31),
        "59k": (10.576, 8.857, 8.570, 6.740, 10.576),
        "77k": (4.866, 9.448, 4.515, 7.093, 9.448),
        "109k": (6.297, 7.520, 5.447, 8.839, 8.839),
    },
    "FormB": {
        "5k": (8.716, 9.503, 11.331, 15.344, 15.344),
        "10k": (6.906, 12.319, 13.049, 9.627, 13.049),
        "59k": (11.075, 16.833, 11.639, 12.920, 16.833),
        "77k": (13.366, 22.447, 12.530, 13.411, 22.447),
        "109k": (10.261, 22.620, 8.389, 16.409, 22.620),
    },
}

TABLE_NUMBER = {"time": {"FormA": 3, "FormB": 4}, "speedup": {"FormA": 5, "FormB": 6}}


def time_ms(form, column, model):
    """Published running time in ms, or None where the paper has none."""
    if column not in TIME_COLUMNS or model not in RUNNING_TIME_MS.get(form, {}):
        return None
    return float(RUNNING_TIME_MS[form][model][TIME_COLUMNS.index(column)])


def speedup(form, column, model):
    """Published speedup over serial, or None where the paper has none."""
    if column not in SPEEDUP_COLUMNS or model not in SPEEDUP.get(form, {}):
        return None
    return float(SPEEDUP[form][model][SPEEDUP_COLUMNS.index(column)])
