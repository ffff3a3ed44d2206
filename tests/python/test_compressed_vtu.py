"""Compressed VTU files as other programs write them reach tetsmooth intact.

meshio writes a mesh with zlib (its default) and with LZMA, each with UInt32
and UInt64 headers; meshio writes inline base64 arrays only, so appended
files, raw and base64, are built here in the block layout that the VTK XML
format documents, with Python's zlib and lzma, and meshio's own reader must
read them as the mesh they were made from before tetsmooth is asked to.
`tetsmooth quality --json` must count the nodes and tets, and the output of
`tetsmooth convert` must hold exactly the coordinates and tets that meshio
reads from the compressed file. The mesh spans several of the 32 KiB blocks
that meshio and VTK compress separately. A corrupt block is refused with
exit status 3, naming the file and the array.

Runs the binary at $TETSMOOTH_BIN_DIR/tetsmooth (CTest sets it)."""
import base64
import json
import lzma
import os
import re
import shutil
import tempfile
import unittest
import zlib

import meshio
import numpy as np

from test_cli import EXIT_INPUT, kuhn_lattice, require_binary, run

BLOCK_SIZE = 32768  # meshio's, and VTK's default
COMPRESSORS = {"zlib": ("vtkZLibDataCompressor", zlib), "lzma": ("vtkLZMADataCompressor", lzma)}


def compressed_array(values, codec, header_type, block_size=BLOCK_SIZE):
    """(header, blocks) of one array: the header [#blocks][#u-size][#p-size]
    [#c-size-1]...[#c-size-#blocks] as little-endian header_type integers,
    #p-size 0 for a full last block as VTK writes it; each block compressed
    on its own."""
    raw = values.tobytes()
    blocks = [raw[i:i + block_size] for i in range(0, len(raw), block_size)]
    compressed = [COMPRESSORS[codec][1].compress(b) for b in blocks]
    last = len(blocks[-1]) if blocks else 0
    items = [len(blocks), block_size, 0 if last == block_size else last] + [len(c) for c in compressed]
    header = np.array(items, dtype={"UInt32": "<u4", "UInt64": "<u8"}[header_type]).tobytes()
    return header, b"".join(compressed)


def write_appended(path, xyz, tets, codec, encoding, header_type):
    """A VTU file with every array appended and compressed; in base64 the
    header and the blocks of an array are encoded separately, as VTK does."""
    arrays = [("Points", "Points", "Float64", 3, xyz.astype("<f8")),
              ("Cells", "connectivity", "Int64", 1, tets.astype("<i8")),
              ("Cells", "offsets", "Int64", 1, 4 * np.arange(1, len(tets) + 1, dtype="<i8")),
              ("Cells", "types", "UInt8", 1, np.full(len(tets), 10, dtype="u1"))]
    appended = b""
    sections = {"Points": "", "Cells": ""}
    for section, name, vtk_type, components, values in arrays:
        sections[section] += (f'        <DataArray type="{vtk_type}" Name="{name}" NumberOfComponents="{components}" '
                              f'format="appended" offset="{len(appended)}"/>\n')
        header, blocks = compressed_array(values, codec, header_type)
        appended += base64.b64encode(header) + base64.b64encode(blocks) if encoding == "base64" else header + blocks
    xml = (f'<?xml version="1.0"?>\n'
           f'<VTKFile type="UnstructuredGrid" version="1.0" byte_order="LittleEndian" header_type="{header_type}" '
           f'compressor="{COMPRESSORS[codec][0]}">\n'
           f'  <UnstructuredGrid>\n'
           f'    <Piece NumberOfPoints="{len(xyz)}" NumberOfCells="{len(tets)}">\n'
           f'      <Points>\n{sections["Points"]}      </Points>\n'
           f'      <Cells>\n{sections["Cells"]}      </Cells>\n'
           f'    </Piece>\n'
           f'  </UnstructuredGrid>\n'
           f'  <AppendedData encoding="{encoding}">\n   _')
    with open(path, "wb") as f:
        f.write(xml.encode() + appended + b"\n  </AppendedData>\n</VTKFile>\n")


class CompressedVtu(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        require_binary()
        cls.tmp = tempfile.mkdtemp(prefix="tetsmooth_test_compressed_")
        cls.xyz, cls.tets = kuhn_lattice(12, seed=5)
        # Several blocks per array: the points alone take two.
        assert cls.xyz.nbytes > BLOCK_SIZE

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def path(self, name):
        return os.path.join(self.tmp, name)

    def assert_read_faithfully(self, src):
        """tetsmooth reads `src` as meshio does, and as the mesh it was made from."""
        ref = meshio.read(src)
        np.testing.assert_array_equal(ref.points, self.xyz)
        np.testing.assert_array_equal(ref.cells_dict["tetra"], self.tets)
        q = json.loads(run("quality", src, "--json").stdout)
        self.assertEqual(q["input"]["nodes"], len(ref.points))
        self.assertEqual(q["input"]["tets"], len(ref.cells_dict["tetra"]))
        self.assertEqual(q["quality"]["inverted"], 0)
        back = src + ".back.vtu"
        run("convert", src, back, "-q")
        m = meshio.read(back)
        np.testing.assert_array_equal(m.points, ref.points)  # bit for bit
        np.testing.assert_array_equal(m.cells_dict["tetra"], ref.cells_dict["tetra"])

    def test_what_meshio_writes(self):
        for codec in COMPRESSORS:
            for header_type in (None, "UInt64"):  # None: meshio's default, no header_type (UInt32)
                with self.subTest(compression=codec, header_type=header_type):
                    src = self.path(f"meshio-{codec}-{header_type}.vtu")
                    try:
                        meshio.write(src, meshio.Mesh(self.xyz, [("tetra", self.tets)]), binary=True,
                                     compression=codec, header_type=header_type)
                    except Exception as e:  # a meshio whose Python lacks lzma
                        self.skipTest(f"meshio cannot write {codec}: {e}")
                    with open(src) as f:
                        text = f.read()
                    self.assertIn(f'compressor="{COMPRESSORS[codec][0]}"', text)
                    self.assertIn('format="binary"', text)
                    self.assert_read_faithfully(src)

    def test_appended_raw_and_base64(self):
        for codec in COMPRESSORS:
            for encoding in ("raw", "base64"):
                for header_type in ("UInt32", "UInt64"):
                    with self.subTest(compression=codec, encoding=encoding, header_type=header_type):
                        src = self.path(f"appended-{codec}-{encoding}-{header_type}.vtu")
                        write_appended(src, self.xyz, self.tets, codec, encoding, header_type)
                        self.assert_read_faithfully(src)

    def test_a_corrupt_block_is_refused_naming_the_file_and_the_array(self):
        src = self.path("corrupt.vtu")
        meshio.write(src, meshio.Mesh(self.xyz, [("tetra", self.tets)]))
        with open(src) as f:
            text = f.read()
        # The points' data: a base64 header, its padding, then the blocks;
        # one character in the middle of the first block changed.
        m = re.search(r'Name="Points"[^>]*>\s*[A-Za-z0-9+/]+=*([A-Za-z0-9+/]+)', text)
        at = m.start(1) + 100
        with open(src, "w") as f:
            f.write(text[:at] + ("B" if text[at] == "A" else "A") + text[at + 1:])
        proc = run("quality", src, "--json", check=False)
        self.assertEqual(proc.returncode, EXIT_INPUT, proc.stderr)
        self.assertTrue(proc.stderr.startswith(f"tetsmooth: error: {src}, byte "), proc.stderr)
        self.assertIn(": Points: block 1 of ", proc.stderr)


if __name__ == "__main__":
    unittest.main()
