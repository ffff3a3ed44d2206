"""End-to-end tests of the tetsmooth executable: every command, every output
format, the JSON reports, and the documented exit codes for bad input.

Runs the binary at $TETSMOOTH_BIN_DIR/tetsmooth (CTest sets it)."""
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import unittest

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
BIN = os.path.join(os.environ.get("TETSMOOTH_BIN_DIR", ""), "tetsmooth")


def missing(why):
    """A tool the tests need is not there. Under CTest, which sets
    TETSMOOTH_BIN_DIR (and runs after scripts/install_deps.sh), that fails
    the test: a skip would count as a pass. Run by hand without it, the
    tests that need the tool skip."""
    if "TETSMOOTH_BIN_DIR" in os.environ:
        raise RuntimeError(why)
    raise unittest.SkipTest(why)


def require_binary():
    if not os.access(BIN, os.X_OK):
        missing(f"no tetsmooth binary at {BIN!r}: set TETSMOOTH_BIN_DIR")

EXIT_USAGE, EXIT_INPUT, EXIT_OUTPUT, EXIT_DEVICE = 2, 3, 4, 5


def run(*args, check=True):
    """Runs tetsmooth; with check, a non-zero exit fails the test with stderr."""
    proc = subprocess.run([BIN, *args], capture_output=True, text=True, timeout=600)
    if check and proc.returncode != 0:
        raise AssertionError(f"tetsmooth {' '.join(args)} exited {proc.returncode}:\n{proc.stderr}")
    return proc


def quality_json(path, *extra):
    return json.loads(run("quality", path, "--json", *extra).stdout)


def kuhn_lattice(n, jitter=0.15, seed=3):
    """n^3 unit cubes, 6 positively oriented tets each, interior nodes jittered:
    built here, independently of tetsmooth's generator."""
    g = np.arange(n + 1, dtype=float)
    xyz = np.stack(np.meshgrid(g, g, g, indexing="ij"), axis=-1).reshape(-1, 3)

    def node(i, j, k):
        return (i * (n + 1) + j) * (n + 1) + k

    tets = []
    for i in range(n):
        for j in range(n):
            for k in range(n):
                for p in ([0, 1, 2], [0, 2, 1], [1, 0, 2], [1, 2, 0], [2, 0, 1], [2, 1, 0]):
                    c = [i, j, k]
                    path = [node(*c)]
                    for axis in p:
                        c[axis] += 1
                        path.append(node(*c))
                    tets.append(path)
    tets = np.array(tets)
    # Odd permutations of the axes give negatively oriented paths.
    flip = signed_volume6(xyz, tets) < 0
    tets[flip] = tets[flip][:, [0, 1, 3, 2]]
    interior = np.all((xyz > 0) & (xyz < n), axis=1)
    xyz[interior] += np.random.default_rng(seed).uniform(-jitter, jitter, size=(interior.sum(), 3))
    assert np.all(signed_volume6(xyz, tets) > 0), "jitter too large: a tet inverted"
    return xyz, tets


def signed_volume6(xyz, tets):
    a, b, c, d = (xyz[tets[:, k]] for k in range(4))
    return np.einsum("ij,ij->i", b - a, np.cross(c - a, d - a))


def radius_ratio(xyz, tets):
    """3 r_in / R from the inscribed radius 3V/S and the circumcentre found by
    solving a linear system: a different route from tetsmooth's formula."""
    p = xyz[tets]
    v = signed_volume6(xyz, tets) / 6
    area = sum(0.5 * np.linalg.norm(np.cross(p[:, f[1]] - p[:, f[0]], p[:, f[2]] - p[:, f[0]]), axis=1)
               for f in ([1, 2, 3], [0, 2, 3], [0, 1, 3], [0, 1, 2]))
    r_in = 3 * np.abs(v) / area
    m = 2 * (p[:, 1:] - p[:, :1])
    rhs = np.sum(p[:, 1:] ** 2, axis=2) - np.sum(p[:, :1] ** 2, axis=2)
    centre = np.linalg.solve(m, rhs[..., None])[..., 0]
    circum = np.linalg.norm(centre - p[:, 0], axis=1)
    return np.sign(v) * 3 * r_in / circum


class CliTestCase(unittest.TestCase):
    """Tests that need the tetsmooth binary and a scratch folder (cls.tmp,
    named after SCRATCH_PREFIX and removed after; path() names a file in
    it)."""

    SCRATCH_PREFIX = "tetsmooth_test_cli_"

    @classmethod
    def setUpClass(cls):
        require_binary()
        cls.tmp = tempfile.mkdtemp(prefix=cls.SCRATCH_PREFIX)

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp, ignore_errors=True)

    @classmethod
    def path(cls, name):
        return os.path.join(cls.tmp, name)

    def assert_one_error_line(self, proc, code, *fragments):
        self.assertEqual(proc.returncode, code, proc.stderr)
        lines = proc.stderr.splitlines()
        self.assertEqual(len(lines), 1, proc.stderr)
        self.assertTrue(lines[0].startswith("tetsmooth: error: "), proc.stderr)
        for fragment in fragments:
            self.assertIn(fragment, lines[0])

    def assert_refused_output_kept(self, args, out, older):
        """A run of `args` that is refused (EXIT_INPUT) leaves the output
        `out`, written with `older` first, as it was; `out` is removed after.
        Returns the run."""
        with open(out, "w") as f:
            f.write(older)
        proc = run(*args, check=False)
        self.assertEqual(proc.returncode, EXIT_INPUT, proc.stderr)
        with open(out) as f:
            self.assertEqual(f.read(), older, "a refused run touched the output")
        os.remove(out)
        return proc


class RefusedDecks:
    """The refusals of a deck format, for a CliTestCase whose class sets
    `lines` (a good deck, a list of lines), SUFFIX (its extension) and
    `cases()`: {name: (lines, 1-based line the message must name, fragments
    it must hold)}. Each bad deck exits EXIT_INPUT with one error line
    naming the file and line, writes no output and leaves an existing one
    as it was."""

    SUFFIX = None

    def edited(self, index, new):
        """The deck with line `index` replaced by the lines `new`."""
        return self.lines[:index] + list(new) + self.lines[index + 1:]

    def test_the_deck_itself_is_read(self):
        # So that each refusal below is of the line a case changed.
        src = self.write("good" + self.SUFFIX, self.lines)
        self.assertEqual(quality_json(src)["input"]["tets"], len(self.tets))

    def test_bad_decks_are_refused_and_leave_the_output_alone(self):
        for name, (lines, line, fragments) in self.cases().items():
            with self.subTest(deck=name):
                src = self.write(name + self.SUFFIX, lines)
                out = self.path("never" + self.SUFFIX)
                proc = run("smooth", src, "-o", out, "--device", "cpu", check=False)
                self.assert_one_error_line(proc, EXIT_INPUT, f"{src}:{line}:", *fragments)
                self.assertFalse(os.path.exists(out))
                self.assert_refused_output_kept(("smooth", src, "-o", out, "--device", "cpu"), out, "an older deck\n")
        self.assertEqual(sorted(f for f in os.listdir(self.tmp) if f.startswith("never")), [])


class GenerateSmoothQuality(CliTestCase):
    @classmethod
    def setUpClass(cls):
        super().setUpClass()
        cls.lattice = os.path.join(cls.tmp, "lattice4.vtu")
        cls.model = os.path.join(cls.tmp, "5k.msh")
        run("generate", "lattice-4", "-o", cls.lattice, "-q")
        run("generate", "5k", "-o", cls.model, "--seed", "2", "-q")

    def test_generate_makes_the_promised_sizes(self):
        q = quality_json(self.lattice)
        self.assertEqual(q["input"]["nodes"], 5 ** 3)
        self.assertEqual(q["input"]["tets"], 6 * 4 ** 3)
        self.assertEqual(q["quality"]["inverted"], 0)
        five_k = quality_json(self.model)
        self.assertGreater(five_k["input"]["nodes"], 3000)
        self.assertLess(five_k["input"]["nodes"], 8000)

    def test_generate_is_deterministic_for_a_seed(self):
        a, b = self.path("a.tsm"), self.path("b.tsm")
        run("generate", "lattice-3", "-o", a, "--seed", "9", "-q")
        run("generate", "lattice-3", "-o", b, "--seed", "9", "-q")
        with open(a, "rb") as fa, open(b, "rb") as fb:
            self.assertEqual(fa.read(), fb.read())

    def test_smooth_writes_every_format_and_never_worsens(self):
        before = quality_json(self.model)["quality"]
        outputs = [("out.vtu", ()), ("out.vtk", ()), ("out.msh", ()), ("out_bin.msh", ("--output-format", "msh41-binary")),
                   ("out22.msh", ("--output-format", "msh22")), ("out.mesh", ()), ("out.node", ()), ("out.tsm", ())]
        for name, extra in outputs:
            with self.subTest(output=name):
                out = self.path(name)
                proc = run("smooth", self.model, "-o", out, "--device", "cpu", *extra)
                self.assertIn("before", proc.stderr)
                self.assertNotIn("\r", proc.stderr, "no progress redraws when stderr is not a terminal")
                after = quality_json(out)
                self.assertEqual(after["input"]["tets"], before["tets"])
                self.assertGreaterEqual(after["quality"]["min"], before["min"])
                self.assertGreater(after["quality"]["mean"], before["mean"])
                self.assertEqual(after["quality"]["inverted"], 0)

    def test_smooth_report_json(self):
        report = self.path("report.json")
        run("smooth", self.model, "-o", self.path("r.vtu"), "--device", "cpu", "--report", report, "-q")
        with open(report) as f:
            r = json.load(f)
        self.assertEqual(r["options"]["method"], "adaptive")
        self.assertEqual(r["options"]["form"], "B")
        self.assertEqual(r["options"]["max_iterations"], 100)
        self.assertEqual(r["options"]["tolerance"], 1e-4)
        self.assertEqual(r["device"], "cpu")
        self.assertTrue(r["backend"].startswith("cpu"))
        self.assertEqual(len(r["accepted_per_sweep"]), r["sweeps"])
        self.assertIn(r["stop_reason"], {"no-moves", "tolerance", "max-iterations"})
        self.assertGreater(r["accepted_per_sweep"][0], 0)
        for phase in ("read", "topology", "smoothing", "write", "total"):
            self.assertGreaterEqual(r["timings_ms"][phase], 0)
        before, after = r["quality"]["before"], r["quality"]["after"]
        self.assertEqual(sum(before["histogram"]["counts"]), r["input"]["tets"])
        self.assertEqual(sum(after["histogram"]["counts"]), r["input"]["tets"])
        self.assertGreaterEqual(after["min"], before["min"])
        self.assertGreater(after["mean"], before["mean"])
        # The report agrees with an independent look at the written mesh.
        written = quality_json(self.path("r.vtu"))["quality"]
        self.assertAlmostEqual(written["min"], after["min"], places=12)
        self.assertAlmostEqual(written["mean"], after["mean"], places=12)

    def test_ordinary_and_form_a_run(self):
        for extra in (("--method", "ordinary"), ("--form", "A"), ("--threads", "1"), ("--max-iter", "2")):
            with self.subTest(options=extra):
                report = self.path("variant.json")
                run("smooth", self.lattice, "-o", self.path("variant.vtu"), "--device", "cpu", "--report", report,
                    "-q", *extra)
                with open(report) as f:
                    r = json.load(f)
                self.assertGreaterEqual(r["sweeps"], 1)
                if extra == ("--max-iter", "2"):
                    self.assertLessEqual(r["sweeps"], 2)

    def test_quality_json_matches_an_independent_computation(self):
        import meshio

        xyz, tets = kuhn_lattice(3)
        path = self.path("kuhn.vtu")
        meshio.write(path, meshio.Mesh(xyz, [("tetra", tets)]), binary=False)
        q = quality_json(path, "--worst", "5")
        expected = radius_ratio(xyz, tets)
        self.assertEqual(q["input"]["nodes"], len(xyz))
        self.assertEqual(q["input"]["tets"], len(tets))
        self.assertEqual(q["input"]["movable_nodes"], 2 ** 3)
        self.assertAlmostEqual(q["quality"]["min"], expected.min(), places=10)
        self.assertAlmostEqual(q["quality"]["mean"], expected.mean(), places=10)
        self.assertAlmostEqual(q["quality"]["max"], expected.max(), places=10)
        hist = np.histogram(np.clip(expected, 0, 0.999999), bins=10, range=(0, 1))[0]
        self.assertEqual(q["quality"]["histogram"]["counts"], hist.tolist())
        self.assertEqual(q["quality"]["below_0_1"], int((expected < 0.1).sum()))
        self.assertEqual(q["index_base"], 0)
        worst = sorted(range(len(tets)), key=lambda t: (expected[t], t))[:5]
        for entry, t in zip(q["worst_tets"], worst):
            self.assertAlmostEqual(entry["quality"], expected[t], places=10)
            self.assertEqual(entry["nodes"], tets[entry["tet"]].tolist())

    def test_quality_text(self):
        proc = run("quality", self.lattice, "--worst", "3")
        self.assertIn("radius ratio histogram", proc.stdout)
        self.assertIn("3 worst tets (0-based tet and node indices)", proc.stdout)
        self.assertEqual(proc.stderr, "")

    def test_fields_for_paraview(self):
        import meshio

        out = self.path("fields.vtu")
        run("smooth", self.lattice, "-o", out, "--device", "cpu", "-q")
        m = meshio.read(out)
        quality = np.concatenate([np.asarray(a).ravel() for a in m.cell_data["quality"]])
        boundary = np.asarray(m.point_data["boundary"]).ravel()
        expected = radius_ratio(m.points, m.cells_dict["tetra"])
        np.testing.assert_allclose(quality, expected, rtol=0, atol=1e-9)
        self.assertEqual(set(np.unique(boundary).tolist()), {0.0, 1.0})
        self.assertEqual(int(boundary.sum()), 5 ** 3 - 3 ** 3)

    def test_inverted_input_warns_and_continues(self):
        import meshio

        xyz, tets = kuhn_lattice(3)
        # Push interior node 21 (lattice point 1,1,1) through the opposite face
        # of one of its tets, which inverts that tet at least.
        node = 21
        tet = next(tet for tet in tets if node in tet)
        face_centre = xyz[[n for n in tet if n != node]].mean(axis=0)
        xyz[node] = face_centre + 0.5 * (face_centre - xyz[node])
        inverted = int((signed_volume6(xyz, tets) < 0).sum())
        self.assertGreater(inverted, 0)
        src = self.path("inverted.mesh")
        meshio.write(src, meshio.Mesh(xyz, [("tetra", tets)]))
        proc = run("smooth", src, "-o", self.path("uninverted.mesh"), "--device", "cpu")
        self.assertIn(f"warning: {src}: {inverted} inverted tets", proc.stderr)
        after = quality_json(self.path("uninverted.mesh"))["quality"]
        self.assertLessEqual(after["inverted"], inverted)

    def test_quiet(self):
        proc = run("smooth", self.lattice, "-o", self.path("quiet.vtu"), "-q")
        self.assertEqual(proc.stderr, "")
        self.assertEqual(proc.stdout, "")

    PROGRESS = r"  sweep (\d+)/(\d+)  moved [\d,]+ up to \S+  q min (\S+)  mean (\S+) *"

    def progress_mesh(self):
        """A lattice whose serial smoothing lasts several seconds here (so that
        progress shows even on a much faster machine), and its quality."""
        src = self.path("progress.tsm")
        if not os.path.exists(src):
            run("generate", "lattice-36", "-o", src, "--seed", "4", "-q")
        return src, quality_json(src)["quality"]

    def smooth_on_a_terminal(self, src, *extra):
        """Smooths src serially with stderr on a pseudo-terminal (through the
        device run's scripts/run_on_pty.py); what the terminal got, each
        carriage return as a line break."""
        pty_run = os.path.join(os.environ.get("TETSMOOTH_SOURCE_DIR", os.path.join(HERE, "..", "..")), "scripts",
                               "run_on_pty.py")
        proc = subprocess.run([sys.executable, pty_run, BIN, "smooth", src, "-o", self.path("progress_out.tsm"),
                               "--device", "cpu", "--threads", "1", "--tol", "0", *extra],
                              capture_output=True, text=True, timeout=600)
        self.assertEqual(proc.returncode, 0, proc.stdout + proc.stderr)
        return proc.stdout

    def test_progress_line_on_a_terminal(self):
        """On a terminal a run longer than half a second redraws one progress
        line in place: the sweep, the moves, and the mesh's smallest and mean
        quality after it, which adaptive smoothing of this lattice lifts far
        above the input's (about 0.19 to 0.7). --progress never silences it."""
        src, before = self.progress_mesh()
        shown = self.smooth_on_a_terminal(src, "--max-iter", "100")
        lines = re.findall("^" + self.PROGRESS + "$", shown, re.MULTILINE)
        self.assertTrue(lines, f"no progress line in {shown!r}")
        sweeps = [int(sweep) for sweep, _, _, _ in lines]
        self.assertEqual(sweeps, sorted(set(sweeps)))
        for _, cap, q_min, q_mean in lines:
            self.assertEqual(cap, "100")
            self.assertGreater(float(q_min), before["min"] + 0.3)
            self.assertGreater(float(q_mean), before["mean"])
        self.assertIn("before", shown, "the report follows the progress line")
        silent = self.smooth_on_a_terminal(src, "--max-iter", "40", "--progress", "never")
        self.assertNotRegex(silent, self.PROGRESS)
        self.assertIn("before", silent)

    def test_progress_lines_for_a_log(self):
        """--progress always writes whole lines to a stderr that is not a
        terminal (a batch job's log), the first after half a second and the
        next no sooner than 10 s later; without it a log gets none."""
        src, _ = self.progress_mesh()
        out = self.path("progress_log.tsm")
        proc = run("smooth", src, "-o", out, "--device", "cpu", "--threads", "1", "--tol", "0", "--max-iter", "100",
                   "--progress", "always")
        self.assertNotIn("\r", proc.stderr)
        lines = re.findall("^" + self.PROGRESS + "$", proc.stderr, re.MULTILINE)
        self.assertTrue(lines, proc.stderr)
        self.assertLess(proc.stderr.index("  sweep "), proc.stderr.index("before"))
        quiet = run("smooth", src, "-o", out, "--device", "cpu", "--threads", "1", "--tol", "0", "--max-iter", "40")
        self.assertNotRegex(quiet.stderr, self.PROGRESS)

    def test_every_format_round_trips_exactly(self):
        # The .tsm cache stores raw doubles, so byte equality after a trip
        # through another format means coordinates and tets were kept bit
        # for bit (the lattice's jittered coordinates need all 17 digits).
        source = self.path("exact.tsm")
        run("generate", "lattice-5", "-o", source, "-q")
        with open(source, "rb") as f:
            original = f.read()
        for name, extra in (("rt.vtu", ()), ("rt.vtk", ()), ("rt.msh", ()), ("rt_bin.msh", ("--output-format", "msh41-binary")),
                            ("rt22.msh", ("--output-format", "msh22")), ("rt.mesh", ()), ("rt.node", ())):
            with self.subTest(format=name):
                middle, back = self.path(name), self.path(name + ".tsm")
                run("convert", source, middle, "-q", *extra)
                run("convert", middle, back, "-q")
                with open(back, "rb") as f:
                    self.assertEqual(f.read(), original)

    def test_convert_keeps_the_mesh(self):
        out = self.path("converted.mesh")
        run("convert", self.model, out, "-q")
        a, b = quality_json(self.model), quality_json(out)
        self.assertEqual(a["quality"], b["quality"])
        self.assertEqual(a["worst_tets"], b["worst_tets"])


class ExitCodes(CliTestCase):
    @classmethod
    def setUpClass(cls):
        super().setUpClass()
        cls.good = os.path.join(cls.tmp, "good.mesh")
        run("generate", "lattice-3", "-o", cls.good, "-q")
        with open(cls.good) as f:
            cls.good_text = f.read()

    def write(self, name, text, mode="w"):
        path = self.path(name)
        with open(path, mode) as f:
            f.write(text)
        return path

    def test_help_and_version(self):
        for args in (["--help"], ["smooth", "--help"], ["help", "convert"], ["--version"]):
            proc = run(*args)
            self.assertEqual(proc.stderr, "")
            self.assertTrue(proc.stdout)
        self.assertIn("Exit status", run("--help").stdout)

    def test_usage_errors(self):
        cases = [(["smooth", self.good, "-o", self.path("x.vtu"), "--bogus"], "--bogus"),
                 (["smooth", self.good, "-o", self.path("x.vtu"), "--method", "magic"], "magic"),
                 (["smooth", self.good], "-o"),
                 (["frobnicate"], "frobnicate"),
                 ([], "no command"),
                 (["convert", self.good, self.path("x.stl")], "x.stl"),
                 (["generate", "no-such-model", "-o", self.path("x.vtu")], "no-such-model")]
        for args, fragment in cases:
            with self.subTest(args=args):
                self.assert_one_error_line(run(*args, check=False), EXIT_USAGE, fragment)

    def test_malformed_files(self):
        truncated = self.write("truncated.mesh", self.good_text[: len(self.good_text) // 2])
        garbage = self.write("garbage.mesh", "MeshVersionFormatted 2\nDimension 3\nVertices\nmany\n")
        not_xml = self.write("broken.vtu", "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\">\n<Piece")
        empty = self.write("empty.msh", "")
        for path in (truncated, garbage, not_xml, empty, self.path("does-not-exist.vtu")):
            with self.subTest(path=path):
                self.assert_one_error_line(run("quality", path, check=False), EXIT_INPUT, path)
                self.assert_one_error_line(run("smooth", path, "-o", self.path("never.vtu"), check=False),
                                           EXIT_INPUT, path)
                self.assertFalse(os.path.exists(self.path("never.vtu")))

    def test_truncated_binary_msh(self):
        full = self.path("full_bin.msh")
        run("convert", self.good, full, "--output-format", "msh41-binary", "-q")
        with open(full, "rb") as f:
            data = f.read()
        cut = self.write("cut_bin.msh", data[: int(len(data) * 0.7)], mode="wb")
        self.assert_one_error_line(run("quality", cut, check=False), EXIT_INPUT, cut)

    def test_truncated_binary_legacy_vtk(self):
        # meshio writes legacy VTK as BINARY; a cut one names the byte where
        # the data ran out, and nothing is written.
        import meshio

        full = self.path("full_bin.vtk")
        meshio.write(full, meshio.read(self.good), binary=True)
        self.assertEqual(run("quality", full, check=False).returncode, 0)
        with open(full, "rb") as f:
            data = f.read()
        cut = self.write("cut_bin.vtk", data[: int(len(data) * 0.7)], mode="wb")
        proc = run("smooth", cut, "-o", self.path("never_bin.vtu"), check=False)
        self.assert_one_error_line(proc, EXIT_INPUT, cut)
        self.assertIn(f"{cut}, byte {int(len(data) * 0.7)}: unexpected end of file", proc.stderr)
        self.assertFalse(os.path.exists(self.path("never_bin.vtu")))

    def test_nan_coordinate(self):
        lines = self.good_text.splitlines()
        at = next(i for i, l in enumerate(lines) if l.strip() == "Vertices") + 2
        lines[at] = "nan 0 0 1"
        bad = self.write("nan.mesh", "\n".join(lines) + "\n")
        self.assert_one_error_line(run("smooth", bad, "-o", self.path("nan_out.vtu"), check=False), EXIT_INPUT, bad)
        self.assertFalse(os.path.exists(self.path("nan_out.vtu")))

    def test_index_out_of_range(self):
        lines = self.good_text.splitlines()
        at = next(i for i, l in enumerate(lines) if l.strip() == "Tetrahedra") + 2
        lines[at] = "1 2 3 999 0"
        bad = self.write("range.mesh", "\n".join(lines) + "\n")
        proc = run("quality", bad, check=False)
        self.assert_one_error_line(proc, EXIT_INPUT, bad)
        self.assertIn("999", proc.stderr)

    def test_unwritable_output_leaves_nothing_behind(self):
        target_dir = self.path("outdir")
        os.mkdir(target_dir)
        os.mkdir(os.path.join(target_dir, "taken.vtu"))  # a directory where the file should go
        cases = [os.path.join(self.tmp, "missing", "out.vtu"), os.path.join(target_dir, "taken.vtu"),
                 os.path.join(self.good, "out.vtu")]
        if os.geteuid() != 0:  # root may write into a read-only directory
            readonly = self.path("readonly")
            os.mkdir(readonly, 0o555)
            cases.append(os.path.join(readonly, "out.vtu"))
        for out in cases:
            with self.subTest(output=out):
                before = sorted(os.listdir(self.tmp)), sorted(os.listdir(target_dir))
                for args in (["smooth", self.good, "-o", out], ["convert", self.good, out],
                             ["generate", "lattice-2", "-o", out],
                             ["smooth", self.good, "-o", self.path("fine.vtu"), "--report", out]):
                    self.assert_one_error_line(run(*args, check=False), EXIT_OUTPUT)
                self.assertEqual((sorted(os.listdir(self.tmp)), sorted(os.listdir(target_dir))), before)

    def test_read_only_target_is_not_replaced(self):
        """A file its user may not write stays as it is (exit 4), though the
        rename that replaces a file needs only the directory's permission.
        Root may write any file, so as root the run drops to nobody."""
        os.chmod(self.tmp, 0o755)  # mkdtemp's 0700 would keep the other user out
        folder = self.path("shared")
        os.mkdir(folder)
        os.chmod(folder, 0o777)
        target = os.path.join(folder, "kept.vtu")
        with open(target, "w") as handle:
            handle.write("old\n")
        os.chmod(target, 0o444)
        source = os.path.join(folder, "in.vtu")
        shutil.copy(self.good, source)
        os.chmod(source, 0o644)
        prefix = []
        if os.geteuid() == 0:
            setpriv = shutil.which("setpriv")
            if not setpriv:
                missing("setpriv (util-linux) is needed to run as a user other than root")
            prefix = [setpriv, "--reuid=65534", "--regid=65534", "--clear-groups"]
        # generate has no input to read, but its output is checked the same way.
        for args in (["smooth", source, "-o", target], ["convert", source, target],
                     ["generate", "lattice-2", "-o", target]):
            with self.subTest(command=args[0]):
                proc = subprocess.run([*prefix, BIN, *args], capture_output=True, text=True, timeout=600)
                self.assert_one_error_line(proc, EXIT_OUTPUT, "kept.vtu", "not writable")
                with open(target) as handle:
                    self.assertEqual(handle.read(), "old\n")
                self.assertEqual(sorted(os.listdir(folder)), ["in.vtu", "kept.vtu"])

    def run_with_stdout(self, stdout, *args):
        """Runs tetsmooth with its standard output on the open file `stdout`."""
        return subprocess.run([BIN, *args], stdout=stdout, stderr=subprocess.PIPE, text=True, timeout=600)

    def test_full_standard_output_exits_4(self):
        """Results on a standard output that cannot take them (a full disk,
        here /dev/full) are an output error, exit 4 as --help documents, not
        a success whose results were lost: every command that prints to it."""
        if not os.path.exists("/dev/full"):
            self.skipTest("no /dev/full to fail a write")
        out = self.path("full_out.vtu")
        cases = [(["quality", self.good], "cannot write to standard output"),
                 (["quality", self.good, "--json"], "cannot write to standard output"),
                 (["--help"], "cannot write to standard output"),
                 (["smooth", self.good, "-o", out, "-q", "--report", "-"], f"mesh was written to '{out}'"),
                 (["smooth", self.good, "-o", out, "-q", "--report", "/dev/stdout"], "No space left on device")]
        with open("/dev/full", "w") as full:
            for args, fragment in cases:
                with self.subTest(args=args):
                    self.assert_one_error_line(self.run_with_stdout(full, *args), EXIT_OUTPUT, fragment)

    def test_report_to_dev_stdout_appends_to_a_log(self):
        """`--report /dev/stdout >> log` adds the report after what the log
        held: the file behind /dev/stdout is opened to append, as the shell's
        descriptor is, not truncated (nor written from its start)."""
        log = self.write("run.log", "earlier run\n")
        with open(log, "a") as handle:
            proc = self.run_with_stdout(handle, "smooth", self.good, "-o", self.path("logged.vtu"), "-q",
                                        "--report", "/dev/stdout")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        with open(log) as handle:
            text = handle.read()
        self.assertTrue(text.startswith("earlier run\n{"), text[:200])
        self.assertEqual(json.loads(text[len("earlier run\n"):])["command"], "smooth")

    def test_cuda_without_a_gpu(self):
        out = self.path("cuda.vtu")
        proc = run("smooth", self.good, "-o", out, "--device", "cuda", check=False)
        if proc.returncode == 0:
            self.skipTest("a usable GPU is present")
        self.assert_one_error_line(proc, EXIT_DEVICE, "--device cuda")
        self.assertFalse(os.path.exists(out))


if __name__ == "__main__":
    unittest.main()
