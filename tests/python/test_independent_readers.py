"""tetsmooth's files as other programs see them, and other programs' files as
tetsmooth sees them: every output format written by `tetsmooth convert` is
read back with meshio (and the .msh files with the Gmsh API), and meshes
written by meshio are read by `tetsmooth quality --json` and `convert`.

Runs the binary at $TETSMOOTH_BIN_DIR/tetsmooth (CTest sets it)."""
import contextlib
import json
import os
import shutil
import tempfile
import unittest

import meshio
import numpy as np

from test_cli import CliTestCase, kuhn_lattice, missing, require_binary, run

# The reference coordinates are short binary fractions, so any writer and
# reader that do not lose precision reproduce them exactly; this allows a
# unit in the last place of the largest coordinate (50) anyway.
COORD_ATOL = 1e-14


def gmsh_module():
    """The Gmsh Python API, or None with the reason it cannot be used."""
    try:
        import gmsh
    except Exception as e:  # an import of a compiled module can fail in many ways
        return None, f"cannot import gmsh: {e}"
    return gmsh, ""


def require_gmsh():
    """The Gmsh API, which scripts/install_deps.sh installs (see missing)."""
    gmsh, why = gmsh_module()
    if gmsh is None:
        missing(why)
    return gmsh


class GmshScratchCase(CliTestCase):
    """Tests that need the tetsmooth binary, the Gmsh API (cls.gmsh) and a
    scratch folder (cls.tmp, named after SCRATCH_PREFIX and removed after;
    path() names a file in it)."""

    SCRATCH_PREFIX = "tetsmooth_test_"

    @classmethod
    def setUpClass(cls):
        cls.gmsh = require_gmsh()  # before the scratch folder, which a skip would leave behind
        super().setUpClass()


def boundary_nodes(tets):
    """The nodes (as the rows of `tets` name them) of faces that belong to
    one tet only."""
    faces = np.sort(np.concatenate([tets[:, [1, 2, 3]], tets[:, [0, 2, 3]], tets[:, [0, 1, 3]], tets[:, [0, 1, 2]]]),
                    axis=1)
    unique, counts = np.unique(faces, axis=0, return_counts=True)
    return set(unique[counts == 1].ravel().tolist())


@contextlib.contextmanager
def gmsh_session(gmsh):
    """An initialised, quiet Gmsh for the `with` block, finalised after it."""
    # Options in ~/.gmshrc or the environment must not change what is read:
    # -noenv exists from Gmsh 4.9; older versions only skip the config files.
    major, minor = (int(x) for x in gmsh.__version__.split(".")[:2])
    gmsh.initialize(["", "-noenv"] if (major, minor) >= (4, 9) else [""], readConfigFiles=False)
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        yield
    finally:
        gmsh.finalize()


def two_layers(gmsh):
    """Two 2 x 2 x 1 boxes stacked in z, fragmented so that they share the
    face z = 1, as two volumes (two soil layers); their tags (lower, upper).
    The caller synchronizes the model, after any OCC entities of its own."""
    lower = gmsh.model.occ.addBox(0, 0, 0, 2, 2, 1)
    upper = gmsh.model.occ.addBox(0, 0, 1, 2, 2, 1)
    gmsh.model.occ.fragment([(3, lower)], [(3, upper)])
    return lower, upper


def physical_groups(gmsh):
    """{(dim, tag): number of elements} of the model in the session."""
    counts = {}
    for dim, tag in gmsh.model.getPhysicalGroups():
        n = 0
        for entity in gmsh.model.getEntitiesForPhysicalGroup(dim, tag):
            _, elements, _ = gmsh.model.mesh.getElements(dim, entity)
            n += sum(len(e) for e in elements)
        counts[(dim, tag)] = n
    return counts


def elements_by_tag(gmsh):
    """{dim: {element tag: (type, node tags)}} of the model in the session."""
    found = {}
    for dim in range(4):
        types, tags, nodes = gmsh.model.mesh.getElements(dim=dim)
        for etype, etags, enodes in zip(types, tags, nodes):
            per = len(enodes) // len(etags)
            for k, tag in enumerate(etags):
                found.setdefault(dim, {})[int(tag)] = (int(etype), tuple(int(n) for n in enodes[k * per:(k + 1) * per]))
    return found


def read_with_gmsh(gmsh, path):
    """Nodes in tag order and tets as 0-based rows into them."""
    with gmsh_session(gmsh):
        gmsh.open(path)
        tags, coords, _ = gmsh.model.mesh.getNodes()
        order = np.argsort(tags)
        tags = np.asarray(tags)[order]
        xyz = np.asarray(coords).reshape(-1, 3)[order]
        tets = []
        types, _, node_tags = gmsh.model.mesh.getElements(dim=3)
        for etype, nodes in zip(types, node_tags):
            if etype == 4:  # 4-node tetrahedron
                tets.append(np.asarray(nodes).reshape(-1, 4))
        tets = np.searchsorted(tags, np.concatenate(tets))
        return xyz, tets


class IndependentReaders(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        require_binary()
        cls.tmp = tempfile.mkdtemp(prefix="tetsmooth_test_readers_")
        # The reference: a mesh built here, with coordinates known exactly,
        # given to tetsmooth by meshio's ASCII VTU writer.
        xyz, cls.tets = kuhn_lattice(4, seed=11)
        # Not a unit box, so scale errors would show; multiples of 1/256 so
        # that every writer, meshio's 12-digit ASCII VTU included, prints
        # them exactly.
        cls.xyz = np.round(xyz * 12.5 * 256) / 256
        cls.source = os.path.join(cls.tmp, "source.vtu")
        meshio.write(cls.source, meshio.Mesh(cls.xyz, [("tetra", cls.tets)]), binary=False)

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def path(self, name):
        return os.path.join(self.tmp, name)

    def assert_same_mesh(self, xyz, tets):
        self.assertEqual(len(xyz), len(self.xyz))
        self.assertEqual(len(tets), len(self.tets))
        np.testing.assert_allclose(xyz, self.xyz, rtol=0, atol=COORD_ATOL)
        np.testing.assert_array_equal(tets, self.tets)

    # tetsmooth writes, others read ------------------------------------------

    OUTPUTS = [("msh41.msh", "msh41"), ("msh41-binary.msh", "msh41-binary"), ("msh22.msh", "msh22"),
               ("out.vtu", "vtu"), ("out.vtk", "vtk"), ("out.mesh", "medit"), ("out.node", "tetgen")]

    def test_meshio_reads_every_format_tetsmooth_writes(self):
        for name, fmt in self.OUTPUTS:
            with self.subTest(format=fmt):
                out = self.path(name)
                run("convert", self.source, out, "--output-format", fmt, "-q")
                m = meshio.read(out)
                self.assertEqual(set(m.cells_dict), {"tetra"})
                self.assert_same_mesh(m.points, m.cells_dict["tetra"])

    def test_meshio_reads_what_tetsmooth_carries_through(self):
        # Extras tetsmooth keeps and writes back, in files meshio must still
        # read: several TetGen tet attributes (whole ones, which meshio reads
        # as ints, written as integers however the input spelled them), and
        # Medit's Identifier and Geometry sections.
        tets = self.tets + 1
        base = self.path("attrs")
        with open(base + ".node", "w", encoding="utf-8") as handle:
            handle.write(f"{len(self.xyz)} 3 0 0\n")
            for i, p in enumerate(self.xyz):
                handle.write(f"{i + 1} {p[0]!r} {p[1]!r} {p[2]!r}\n")
        with open(base + ".ele", "w", encoding="utf-8") as handle:
            handle.write(f"{len(tets)} 4 2\n")
            for t, tet in enumerate(tets):
                handle.write(f"{t + 1} {tet[0]} {tet[1]} {tet[2]} {tet[3]} {1e6 + t % 2:e} {t}\n")
        run("convert", base + ".node", self.path("attrs_out.node"), "-q")
        m = meshio.read(self.path("attrs_out.node"))
        self.assert_same_mesh(m.points, m.cells_dict["tetra"])
        np.testing.assert_array_equal(m.cell_data["tetgen:ref"][0], 1000000 + np.arange(len(tets)) % 2)
        np.testing.assert_array_equal(m.cell_data["tetgen:ref2"][0], np.arange(len(tets)))

        medit = self.path("named.mesh")
        run("convert", self.source, medit, "-q")
        with open(medit, encoding="utf-8") as handle:
            text = handle.read()
        with open(medit, "w", encoding="utf-8") as handle:
            handle.write(text.replace("Dimension 3\n", 'Dimension 3\nIdentifier\n"slope, v2"\nGeometry\nsupport.mesh\n', 1))
        run("convert", medit, self.path("named_out.mesh"), "-q")
        with open(self.path("named_out.mesh"), encoding="utf-8") as handle:
            self.assertIn('Identifier\n"slope, v2"\n', handle.read())
        m = meshio.read(self.path("named_out.mesh"))
        self.assert_same_mesh(m.points, m.cells_dict["tetra"])

    def test_gmsh_reads_the_msh_files(self):
        gmsh = require_gmsh()
        for name, fmt in self.OUTPUTS:
            if not name.endswith(".msh"):
                continue
            with self.subTest(format=fmt):
                out = self.path("gmsh-" + name)
                run("convert", self.source, out, "--output-format", fmt, "-q")
                self.assert_same_mesh(*read_with_gmsh(gmsh, out))

    def test_fields_reach_other_readers(self):
        for name in ("fields.vtu", "fields.vtk", "fields.msh"):
            with self.subTest(output=name):
                out = self.path(name)
                run("convert", self.source, out, "-q")
                m = meshio.read(out)
                self.assertIn("quality", m.cell_data)
                self.assertIn("boundary", m.point_data)
                boundary = np.asarray(m.point_data["boundary"]).ravel()
                self.assertEqual(int(boundary.sum()), 5 ** 3 - 3 ** 3)

    # others write, tetsmooth reads ------------------------------------------

    INPUTS = [("meshio41.msh", dict(file_format="gmsh", binary=False)),
              ("meshio41-binary.msh", dict(file_format="gmsh", binary=True)),
              ("meshio22.msh", dict(file_format="gmsh22", binary=False)),
              ("meshio22-binary.msh", dict(file_format="gmsh22", binary=True)),
              ("meshio-ascii.vtu", dict(binary=False)),
              ("meshio-binary.vtu", dict(binary=True, compression=None)),
              ("meshio-zlib.vtu", dict(binary=True)),  # meshio's default
              ("meshio.vtk", dict(binary=False)),
              ("meshio.mesh", dict())]

    # Variants tetsmooth may not read. It must then refuse them with a clear
    # message and exit status 3, never misread them.
    OPTIONAL_INPUTS = [("meshio-binary.vtk", dict(binary=True), "binary")]

    def write_with_meshio(self, name, kwargs):
        src = self.path(name)
        meshio.write(src, meshio.Mesh(self.xyz, [("tetra", self.tets)]), **kwargs)
        return src

    def assert_read_faithfully(self, src, quality_proc):
        q = json.loads(quality_proc.stdout)
        self.assertEqual(q["input"]["nodes"], len(self.xyz))
        self.assertEqual(q["input"]["tets"], len(self.tets))
        self.assertEqual(q["quality"]["inverted"], 0)
        # Coordinates and tets survive a trip through tetsmooth's reader.
        back = src + ".back.vtu"
        run("convert", src, back, "-q")
        m = meshio.read(back)
        self.assert_same_mesh(m.points, m.cells_dict["tetra"])

    def test_tetsmooth_reads_what_meshio_writes(self):
        for name, kwargs in self.INPUTS:
            with self.subTest(input=name):
                src = self.write_with_meshio(name, kwargs)
                self.assert_read_faithfully(src, run("quality", src, "--json"))

    def test_unsupported_variants_are_refused_clearly(self):
        for name, kwargs, reason in self.OPTIONAL_INPUTS:
            with self.subTest(input=name):
                src = self.write_with_meshio(name, kwargs)
                proc = run("quality", src, "--json", check=False)
                if proc.returncode == 0:
                    self.assert_read_faithfully(src, proc)
                    continue
                self.assertEqual(proc.returncode, 3, proc.stderr)
                self.assertTrue(proc.stderr.startswith(f"tetsmooth: error: {src}:"), proc.stderr)
                self.assertIn(reason, proc.stderr)

    def test_gmsh_written_mesh(self):
        gmsh = require_gmsh()
        src = self.path("gmsh-box.msh")
        gmsh.initialize([""], readConfigFiles=False)
        try:
            gmsh.option.setNumber("General.Terminal", 0)
            gmsh.model.occ.addBox(0, 0, 0, 1, 2, 3)
            gmsh.model.occ.synchronize()
            gmsh.option.setNumber("Mesh.MeshSizeMax", 0.5)
            gmsh.model.mesh.generate(3)
            gmsh.write(src)
            _, _, node_tags = gmsh.model.mesh.getElements(dim=3)
            tets = sum(len(n) for n in node_tags) // 4
            before = elements_by_tag(gmsh)
        finally:
            gmsh.finalize()
        q = json.loads(run("quality", src, "--json").stdout)
        self.assertEqual(q["input"]["tets"], tets)
        self.assertEqual(q["quality"]["inverted"], 0)
        self.assertGreater(q["quality"]["min"], 0)
        # Gmsh numbers the points, lines and triangles before the tets; a
        # smoothed file keeps every element's tag and nodes, as Gmsh reads it.
        self.assertNotEqual(sorted(before[3])[0], 1)
        for fmt in ("msh41", "msh41-binary", "msh22"):
            with self.subTest(format=fmt):
                out = self.path(f"gmsh-box-smooth-{fmt}.msh")
                run("smooth", src, "-o", out, "--output-format", fmt, "-q")
                with gmsh_session(gmsh):
                    gmsh.open(out)
                    self.assertEqual(elements_by_tag(gmsh), before)
                # meshio reads field data only in ascending element order,
                # which the kept tags follow (it reads no MSH 2.2 field data
                # of files with more than one element type).
                if fmt != "msh22":
                    m = meshio.read(out)
                    self.assertEqual(len(m.cells_dict["tetra"]), tets)
                    quality = np.concatenate([block for block, cells in zip(m.cell_data["quality"], m.cells)
                                              if cells.type == "tetra"])
                    self.assertEqual(len(quality), tets)
                    self.assertTrue(np.all((quality > 0) & (quality <= 1 + 1e-12)))  # 1 up to rounding


if __name__ == "__main__":
    unittest.main()
