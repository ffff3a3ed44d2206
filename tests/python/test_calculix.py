"""Smoothed Abaqus decks solved by a real solver, CalculiX's ccx: the point of
smoothing a deck is that it still runs and gives a sound answer.

Gmsh meshes a 2 x 2 x 2 block of two materials (two layers, two element
sets) with 4- and with 10-node tets; the test appends an analysis to each
deck, solves it with ccx, smooths it with tetsmooth and solves the smoothed
deck. Both solves must finish cleanly (which they would not if a set the
analysis names had gone), and:
- a patch test: a load that gives a uniform stress in each material must be
  reproduced exactly by linear (and straight-sided quadratic) tets on any
  valid mesh, the smoothed one included;
- under gravity, the reactions equal the weight, and the smoothed mesh's
  displacements agree with the original mesh's within its discretisation
  error;
- the worst radius ratio of the smoothed mesh did not fall.

Runs the binary at $TETSMOOTH_BIN_DIR/tetsmooth (CTest sets it) and ccx
(Debian's calculix-ccx, which scripts/install_deps.sh installs) from PATH."""
import os
import re
import shutil
import subprocess
import unittest

import numpy as np

from test_abaqus import parse_deck
from test_cli import missing, radius_ratio, run
from test_independent_readers import GmshScratchCase, gmsh_session, two_layers

# Two materials whose ratio nu/E is the same, so that under a uniform stress
# szz both layers contract sideways alike and stay together without a shear:
# the exact field is then linear in each layer (uz has a kink at z = 1, a
# plane of mesh faces), which the finite elements must reproduce.
LOWER = dict(E=1000.0, nu=0.2, rho=2.0)
UPPER = dict(E=2000.0, nu=0.4, rho=1.5)
DELTA = 0.01  # the top's prescribed displacement
GRAVITY = 9.81
AREA, HEIGHT = 4.0, 1.0  # each layer's cross-section and height

# ccx prints its results with 7 significant digits (%13.6E), each off by at
# most 5e-7 of itself: values that should equal a nonzero number are
# checked to twice that; values that should be zero print with their full
# magnitude and are checked to the direct solver's (SPOOLES) precision.
PRINTED_RTOL = 1e-6
SOLVER_RTOL = 1e-9


def ccx_binary():
    return shutil.which("ccx")


def require_ccx():
    if ccx_binary() is None:
        missing("no ccx on PATH: scripts/install_deps.sh installs Debian's calculix-ccx")


def materials_and_sections():
    """The two materials and their sections, on the element sets LOWER and
    UPPER (Gmsh's *ELSET lists of the physical volumes)."""
    text = ""
    for name, m in (("LOWER", LOWER), ("UPPER", UPPER)):
        text += (f"*MATERIAL, NAME={name}_ROCK\n*ELASTIC\n{m['E']}, {m['nu']}\n*DENSITY\n{m['rho']}\n"
                 f"*SOLID SECTION, ELSET={name}, MATERIAL={name}_ROCK\n")
    return text


def exact_patch_field(xyz):
    """The exact displacements of the patch test at the points xyz, and the
    stress szz: the top pulled up by DELTA, the bottom and the planes x = 0,
    y = 0 on rollers, the other faces free."""
    szz = DELTA / (HEIGHT / LOWER["E"] + HEIGHT / UPPER["E"])
    lateral = -LOWER["nu"] / LOWER["E"] * szz  # the same strain in both layers
    z = xyz[:, 2]
    uz = np.where(z <= HEIGHT, szz / LOWER["E"] * z,
                  szz / LOWER["E"] * HEIGHT + szz / UPPER["E"] * (z - HEIGHT))
    return np.stack([lateral * xyz[:, 0], lateral * xyz[:, 1], uz], axis=1), szz


def read_dat(path):
    """{(what, set): rows} of a ccx .dat file: what is the first word of the
    block's heading (displacements, forces, total, stresses), rows its
    numbers, node or element number first (no number for totals)."""
    blocks, rows = {}, None
    heading = re.compile(r"^\s*(\w+) .*for set (\S+) and time")
    with open(path) as f:
        for line in f:
            m = heading.match(line)
            if m:
                rows = blocks.setdefault((m.group(1), m.group(2)), [])
            elif line.strip() and rows is not None:
                rows.append([float(v) for v in line.split()])
    return {k: np.array(v) for k, v in blocks.items()}


def parse_sets(path):
    """{(keyword, name): node or element numbers} of the *NSET and *ELSET
    lists of a deck, parsed here (plain lists, as Gmsh and this test write)."""
    sets, current = {}, None
    with open(path) as f:
        for line in f:
            if line.startswith("**"):
                continue
            if line.startswith("*"):
                fields = [x.strip().upper() for x in line.split(",")]
                current = None
                if fields[0] in ("*NSET", "*ELSET"):
                    name = next(x.split("=", 1)[1] for x in fields[1:] if x.startswith(fields[0][1:] + "="))
                    current = sets.setdefault((fields[0], name), [])
            elif current is not None:
                current += [int(v) for v in line.split(",") if v.strip()]
    return sets


def bottom_weight(nodes, elements, sets):
    """The gravity load on the nodes of the set Z0: each tet's weight goes
    to its nodes as the integrals of their shape functions, a quarter to
    each corner of a linear tet and, of a straight-sided quadratic one,
    -1/20 to each corner and 1/5 to each midside node (ccx's Gauss rules
    integrate both exactly)."""
    rho = {e: m["rho"] for name, m in (("LOWER", LOWER), ("UPPER", UPPER)) for e in sets[("*ELSET", name)]}
    bottom = set(sets[("*NSET", "Z0")])
    total = 0.0
    for block in elements.values():
        for _, element, *ids in block:
            p = np.array([nodes[n] for n in ids[:4]])
            volume = abs(np.dot(p[1] - p[0], np.cross(p[2] - p[0], p[3] - p[0]))) / 6
            shares = [0.25] * 4 if len(ids) == 4 else [-0.05] * 4 + [0.2] * 6
            total += GRAVITY * rho[element] * volume * sum(w for n, w in zip(ids, shares) if n in bottom)
    return total


class CalculixDecks(GmshScratchCase):
    SCRATCH_PREFIX = "tetsmooth_test_calculix_"

    @classmethod
    def setUpClass(cls):
        require_ccx()  # before the scratch folder, which a skip would leave behind
        super().setUpClass()
        cls.solved = {}
        gmsh = cls.gmsh
        with gmsh_session(gmsh):
            lower, upper = two_layers(gmsh)
            gmsh.model.occ.synchronize()
            gmsh.model.addPhysicalGroup(3, [lower], 1)
            gmsh.model.setPhysicalName(3, 1, "LOWER")
            gmsh.model.addPhysicalGroup(3, [upper], 2)
            gmsh.model.setPhysicalName(3, 2, "UPPER")
            # The physical volumes' node sets, LOWER and UPPER, hold every
            # node. Physical surfaces would be written as CPS3 elements, which
            # ccx takes for plane-stress elements without a section: the
            # faces' node sets are written here instead, as a preprocessor
            # would.
            gmsh.option.setNumber("Mesh.SaveGroupsOfNodes", 1)
            # About 2,800 tets: interior nodes in both layers, and a few
            # seconds for all the solves. Without Gmsh's own optimisation
            # the mesh keeps slivers (radius ratio 0.005 with Gmsh 4.8) for
            # smoothing to improve, as a mesh from elsewhere might.
            gmsh.option.setNumber("Mesh.MeshSizeMax", 0.25)
            gmsh.option.setNumber("Mesh.Optimize", 0)
            gmsh.model.mesh.generate(3)
            gmsh.write(cls.path("order1.inp"))
            gmsh.model.mesh.setOrder(2)
            gmsh.write(cls.path("order2.inp"))

    @staticmethod
    def analysis(case, nodes):
        """The faces' node sets, the materials, sections and the step of a
        load case, to append to a Gmsh deck of these nodes."""
        sets = ""
        for face, axis, value in (("X0", 0, 0), ("Y0", 1, 0), ("Z0", 2, 0), ("Z2", 2, 2)):
            ids = [str(n) for n in sorted(nodes) if abs(nodes[n][axis] - value) < 1e-9]
            # ccx takes at most 16 entries on a line.
            sets += f"*NSET, NSET={face}\n" + "".join(", ".join(ids[k:k + 10]) + "\n" for k in range(0, len(ids), 10))
        if case == "patch":
            boundary = f"X0, 1, 1, 0.\nY0, 2, 2, 0.\nZ0, 3, 3, 0.\nZ2, 3, 3, {DELTA}\n"
            loads, reacting = "", "Z2"
        else:
            boundary = "Z0, 1, 3, 0.\n"
            loads = "".join(f"*DLOAD\n{s}, GRAV, {GRAVITY}, 0., 0., -1.\n" for s in ("LOWER", "UPPER"))
            reacting = "Z0"
        return (sets + materials_and_sections() + "*STEP\n*STATIC\n*BOUNDARY\n" + boundary + loads +
                "*NODE PRINT, NSET=LOWER\nU\n*NODE PRINT, NSET=UPPER\nU\n"
                f"*NODE PRINT, NSET={reacting}, TOTALS=ONLY\nRF\n"
                "*EL PRINT, ELSET=LOWER\nS\n*EL PRINT, ELSET=UPPER\nS\n*END STEP\n")

    @classmethod
    def ccx(cls, job):
        """Runs ccx on job.inp in the scratch folder; fails unless it
        finished without an error or a warning (ccx only warns of an output
        request's missing set, and goes on)."""
        proc = subprocess.run([ccx_binary(), "-i", job], cwd=cls.tmp, capture_output=True, text=True,
                              timeout=300, env={**os.environ, "OMP_NUM_THREADS": "1"})
        out = proc.stdout + proc.stderr
        if proc.returncode != 0 or "Job finished" not in out or re.search(r"\*(ERROR|WARNING)", out):
            raise AssertionError(f"ccx -i {job} exited {proc.returncode}:\n{out[-4000:]}")
        return read_dat(cls.path(job + ".dat"))

    def solve(self, order, case):
        """(nodes, sets, results) of the deck and of its smoothed copy, each
        solved by ccx; computed once per order and case."""
        key = (order, case)
        if key not in self.solved:
            name = f"{case}{order}"
            with open(self.path(f"order{order}.inp")) as src, open(self.path(name + ".inp"), "w") as deck:
                deck.write(src.read() + self.analysis(case, parse_deck(self.path(f"order{order}.inp"))[0]))
            run("smooth", self.path(name + ".inp"), "-o", self.path(f"smooth-{name}.inp"), "--device", "cpu", "-q")
            self.solved[key] = [(parse_deck(self.path(job + ".inp")), parse_sets(self.path(job + ".inp")),
                                 self.ccx(job)) for job in (name, "smooth-" + name)]
        return self.solved[key]

    @staticmethod
    def displacements(results):
        """{node: (ux, uy, uz)} from the two node sets' prints."""
        rows = np.concatenate([results[("displacements", s)] for s in ("LOWER", "UPPER")])
        return {int(r[0]): r[1:4] for r in rows}

    def check_deck_and_quality(self, order):
        """The smoothed deck keeps every set, moved some nodes and did not
        lower the worst radius ratio of the (corner) tets; the worst radius
        ratio before and after, and how many nodes moved."""
        ((nodes_in, elements), sets_in, _), ((nodes_out, _), sets_out, _) = self.solve(order, "patch")
        # The sets the analysis names, and all others, are still there with
        # the same members (ccx would have stopped, or warned, otherwise).
        self.assertEqual(sets_out, sets_in)
        ids = sorted(nodes_in)
        index = {n: i for i, n in enumerate(ids)}
        tets = np.vectorize(index.get)(np.array([e[2:6] for block in elements.values() for e in block]))
        before = radius_ratio(np.array([nodes_in[n] for n in ids]), tets).min()
        after = radius_ratio(np.array([nodes_out[n] for n in ids]), tets).min()
        self.assertGreaterEqual(after, before)
        moved = sum(nodes_in[n] != nodes_out[n] for n in ids)
        self.assertGreater(moved, 0, "smoothing moved no node: the test would prove nothing")
        return before, after, moved

    def check_patch(self, order):
        """Every node of the smoothed deck, at the coordinates the smoothed
        deck gives it, has the exact displacement; every tet the exact,
        uniform stress; the top's reaction is the stress times its area."""
        for (nodes, _), sets, results in self.solve(order, "patch"):
            u = self.displacements(results)
            ids = sorted(nodes)
            self.assertEqual(sorted(u), ids)
            xyz = np.array([nodes[n] for n in ids])
            exact, szz = exact_patch_field(xyz)
            got = np.array([u[n] for n in ids])
            np.testing.assert_allclose(got, exact, rtol=0, atol=PRINTED_RTOL * np.abs(exact).max())
            stress = np.concatenate([results[("stresses", s)] for s in ("LOWER", "UPPER")])[:, 2:]
            np.testing.assert_allclose(stress[:, 2], szz, rtol=PRINTED_RTOL)
            np.testing.assert_allclose(stress[:, [0, 1, 3, 4, 5]], 0, atol=SOLVER_RTOL * szz)
            force = results[("total", "Z2")][0]
            np.testing.assert_allclose(force[2], AREA * szz, rtol=PRINTED_RTOL)
            np.testing.assert_allclose(force[:2], 0, atol=SOLVER_RTOL * AREA * szz)

    def gravity(self, order):
        """The top face's vertical displacements {(x, y, z): uz} of the deck and
        of the smoothed deck under gravity, after checking that in both the
        bottom's reaction balances the weight."""
        weight = GRAVITY * AREA * HEIGHT * (LOWER["rho"] + UPPER["rho"])
        tops = []
        for (nodes, elements), sets, results in self.solve(order, "gravity"):
            # ccx's RF is a node's internal force, which at a fixed node is
            # the reaction plus the load on the node itself: the share of
            # the weight of the tets around it that lands on the bottom's
            # nodes, which depends on the mesh (and smoothing changes it).
            force = results[("total", "Z0")][0]
            np.testing.assert_allclose(force[2] + bottom_weight(nodes, elements, sets), weight, rtol=PRINTED_RTOL)
            np.testing.assert_allclose(force[:2], 0, atol=SOLVER_RTOL * weight)
            u = self.displacements(results)
            # By position: the 4- and 10-node decks number their nodes apart.
            tops.append({nodes[n]: u[n][2] for n in sets[("*NSET", "Z2")]})
        return tops

    def test_linear_tets(self):
        self.check_deck_and_quality(1)
        self.check_patch(1)
        # The top's nodes do not move, so the two meshes' answers can be
        # compared there node by node. Both differ from the true answer by
        # their discretisation error; that of the linear mesh is measured
        # by the quadratic tets on the same corners (far closer to the true
        # answer), and smoothing must not change the answer by more.
        original, smoothed = self.gravity(1)
        self.assertEqual(set(smoothed), set(original), "a node of the top face moved")
        quadratic, _ = self.gravity(2)
        self.assertTrue(set(original) <= set(quadratic))
        error = max(abs(original[p] - quadratic[p]) for p in original)
        change = max(abs(original[p] - smoothed[p]) for p in original)
        self.assertLess(change, error)

    def test_quadratic_tets(self):
        self.check_deck_and_quality(2)
        self.check_patch(2)
        original, smoothed = self.gravity(2)
        self.assertEqual(set(smoothed), set(original), "a node of the top face moved")
        linear, _ = self.gravity(1)
        # As above, with a tolerance a tenth of the linear mesh's error: the
        # quadratic tets' own error is much smaller.
        error = max(abs(linear[p] - original[p]) for p in linear)
        change = max(abs(original[p] - smoothed[p]) for p in original)
        self.assertLess(change, 0.1 * error)


if __name__ == "__main__":
    unittest.main()
