#!/usr/bin/env bash
# Builds the libFuzzer targets of tests/fuzz with clang (ASan + UBSan) and
# runs each one for a bounded time, seeded from the fixtures in tests/data.
# Fails if any target finds a crash, a sanitizer report, a leak, an
# exception other than InputError, a timeout or an out-of-memory input.
#
#   scripts/run_fuzzers.sh [target ...]      targets: gmsh medit vtu vtk
#                                            tetgen_node tetgen_ele tsm abaqus
#                                            nastran flac3d exodus ansys lsdyna
#                                            (default: all)
# Environment:
#   FUZZ_SECONDS    time per target (default 20)
#   FUZZ_BUILD_DIR  build folder (default build-fuzz); the growing corpus is
#                   kept in it (fuzz-corpus/<target>), found crashes in
#                   fuzz-artifacts/<target>/
#   FUZZ_JOBS       parallel compile jobs (default 2)
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${FUZZ_BUILD_DIR:-$root/build-fuzz}
seconds=${FUZZ_SECONDS:-20}
jobs=${FUZZ_JOBS:-2}
all_targets=(gmsh medit vtu vtk tetgen_node tetgen_ele tsm abaqus nastran flac3d exodus ansys lsdyna)
targets=("$@")
[[ ${#targets[@]} -eq 0 ]] && targets=("${all_targets[@]}")

for t in "${targets[@]}"; do
  [[ " ${all_targets[*]} " == *" $t "* ]] || { echo "unknown fuzz target '$t' (known: ${all_targets[*]})" >&2; exit 2; }
done

CC=clang-14 CXX=clang++-14 cmake -S "$root" -B "$build" -DCMAKE_C_COMPILER=clang-14 -DCMAKE_CXX_COMPILER=clang++-14 \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTETSMOOTH_FUZZ=ON -DTETSMOOTH_CUDA=OFF -DTETSMOOTH_TESTS=OFF \
  -DTETSMOOTH_BENCH=OFF >/dev/null
cmake --build "$build" --target "${targets[@]/#/fuzz_}" -j "$jobs"

# Seeds: the fixtures of each format (libFuzzer reads every file of a folder).
seeds=$build/fuzz-seeds
rm -rf "$seeds"
seed() {  # seed <target> <fixture globs...>
  local target=$1
  shift
  mkdir -p "$seeds/$target"
  local f
  for f in "$@"; do [[ -f $f ]] && cp "$f" "$seeds/$target/"; done
  return 0
}
data=$root/tests/data
seed gmsh "$data"/gmsh_*.msh
seed medit "$data"/medit_*.mesh
seed vtu "$data"/*.vtu
seed vtk "$data"/*.vtk
seed tetgen_node "$data"/*.node
seed tetgen_ele "$data"/*.ele
seed abaqus "$data"/*.inp
seed nastran "$data"/*.bdf
seed flac3d "$data"/*.f3grid
# An Abaqus deck with parts and an assembly, as Abaqus/CAE writes one: two
# parts of the same numbers, one instance translated and rotated, sets of
# the parts and of the assembly, a reference point and loads through them.
cat >"$seeds/abaqus/parts.inp" <<'INP'
*Heading
*Part, name=Rock
*Node
      1,           0.,           0.,           0.
      2,           1.,           0.,           0.
      3,           0.,           1.,           0.
      4,           0.,           0.,           1.
      5,          0.3,          0.3,          0.3
*Element, type=C3D4
1, 1, 2, 3, 5
2, 1, 2, 5, 4
3, 1, 5, 3, 4
4, 5, 2, 3, 4
*Nset, nset=Base
 1, 2, 3
*Elset, elset=All, generate
 1, 4, 1
** Section: Rock
*Solid Section, elset=All, material=Granite
,
*End Part
*Part, name=Pile
*Node
      1,           0.,           0.,           0.
      2,           1.,           0.,           0.
      3,           0.,           1.,           0.
      4,           0.,           0.,           1.
*Element, type=C3D4
1, 1, 2, 3, 4
*Elset, elset=Pile
 1,
*Solid Section, elset=Pile, material=Steel
,
*End Part
*Assembly, name=Assembly
*Instance, name=Rock-1, part=Rock
*End Instance
*Instance, name=Pile-1, part=Pile
          2.,           0.,           0.
          2.,           0.,           0.,           2.,           0.,           1.,          90.
*End Instance
*Node
      1,           5.,           5.,           5.
*Nset, nset=Top, instance=Pile-1
 4,
*End Assembly
*Material, name=Granite
*Elastic
 50000., 0.25
*Material, name=Steel
*Elastic
 210000., 0.3
*Step, name=Load
*Static
*Boundary
Rock-1.Base, ENCASTRE
Rock-1.5, 1, 1
Top, 3, 3, 0.01
1, 1, 6
*End Step
INP
# A deck in the three field formats besides Gmsh's small field.
cat >"$seeds/nastran/fields.bdf" <<'BDF'
SOL 101
CEND
BEGIN BULK
GRID*                  1                              0.              0.
*                     0.
GRID,2,,1.,0.,0.
GRID    3               0.      1.-0    0.
GRID    4               0.      0.      1.      0       123
GRID    5               1.      1.      1.
CTETRA,1,1,1,2,3,4
RBE2,6,5,123,1,2,3,+
+,4
CTETRA  2       2       2       3       4       5
CTRIA3  3       5       1       2       3
SPC1    1       123     1       THRU    2
RBE3    4               5       123     1.      123     4
ENDDATA
BDF
# A binary FLAC3D grid (flac3d_binary.cpp's layout): a tet and a brick, a
# zone group, a face with a group.
/usr/bin/python3 - "$seeds/flac3d/binary.f3grid" <<'PY'
import struct, sys
corners = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1), (1, 1, 0), (0, 1, 1), (1, 0, 1), (1, 1, 1)]
def text(t):
    return struct.pack("<H", len(t)) + t.encode()
b = struct.pack("<III", 1375135718, 3, 9) + struct.pack("<I3d", 10, 0.25, 0.25, -1.0)
b += b"".join(struct.pack("<I3d", 11 + k, *p) for k, p in enumerate(corners))
b += struct.pack("<I", 2) + struct.pack("<6I", 7, 4, 11, 13, 12, 10) + struct.pack("<10I", 5, 8, *range(11, 19))
b += struct.pack("<I", 1) + text("rock") + text("Default") + struct.pack("<3I", 2, 7, 5)
b += struct.pack("<I", 1) + struct.pack("<5I", 1, 3, 11, 12, 13)
b += struct.pack("<I", 1) + text("base") + text("Default") + struct.pack("<2I", 1, 1)
open(sys.argv[1], "wb").write(b)
PY
# No .tsm fixture is kept (the cache is binary and hashed): write one tet in
# the layout of mesh/io/tsm_cache.hpp.
mkdir -p "$seeds/tsm"
/usr/bin/python3 - "$seeds/tsm/one_tet.tsm" <<'PY'
import struct, sys
body = b"\x89TSM\r\n\x1a\n" + struct.pack("<IIQQ", 1, 0, 4, 1)
body += struct.pack("<12d", 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1) + struct.pack("<4i", 0, 1, 2, 3)
h = 0xcbf29ce484222325
for b in body:
    h = ((h ^ b) * 0x100000001b3) & 0xFFFFFFFFFFFFFFFF
open(sys.argv[1], "wb").write(body + struct.pack("<Q", h))
PY
# LS-DYNA: a deck of every card kind the reader reads (standard, free and
# I10 layouts, one- and two-card solids, shells, beams, sets, loads, parts),
# the same deck in the long layout, and lsdyna-mesh-reader's examples where
# install_deps.sh has put them.
seed lsdyna "$root"/.deps/python/lsdyna_mesh_reader/examples/*.k
/usr/bin/python3 - "$seeds/lsdyna/small.k" "$seeds/lsdyna/long.k" <<'PY'
import sys
nodes = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (1, 1, 0), (0, 0, 1), (1, 0, 1), (0, 1, 1), (1, 1, 1), (0.4, 0.5, 0.6)]
quads = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]
def deck(wide):  # the standard layout, or the long one (every field 20 columns)
    ints = lambda values, width=8: "".join(str(v).rjust(20 if wide else width) for v in values)
    lines = ["*KEYWORD LONG=Y" if wide else "*KEYWORD", "*PART", "rock", ints([1, 1, 1], 10), "*NODE"]
    lines += [ints([i + 1]) + "".join(("%.4f" % c).rjust(20 if wide else 16) for c in p) +
              (ints([7, 0]) if i == 0 else "") for i, p in enumerate(nodes[:8])]
    lines += ["9,0.4,0.5,0.6"]
    lines += ["*ELEMENT_SOLID"]
    number = 0
    for q in quads:
        for tet in ((9, q[0] + 1, q[1] + 1, q[2] + 1), (9, q[0] + 1, q[2] + 1, q[3] + 1)):
            number += 1
            if number == 1:
                lines += [ints([number, 1]), ints(list(tet))]
            else:
                lines.append(ints([number, 1 + number % 2] + list(tet) + [tet[3]] * 4))
    lines += ["*ELEMENT_SHELL_THICKNESS", ints([20, 3, 1, 2, 4, 3]), "0.1,0.1,0.1,0.1"]
    lines += ["*ELEMENT_BEAM", ints([30, 4, 5, 6, 8])]
    lines += ["*SET_NODE_LIST_TITLE", "top", ints([1], 10), ints([5, 6, 7, 8], 10)]
    lines += ["*SET_NODE_LIST_GENERATE", ints([2], 10), ints([1, 2], 10)]
    lines += ["*BOUNDARY_SPC_NODE", ints([3, 0, 1, 1, 1], 10)]
    lines += ["*MAT_ELASTIC", "1,7.8e-9,210000.,0.3", "*END"]
    return "\n".join(lines) + "\n"
open(sys.argv[1], "w").write(deck(False))
open(sys.argv[2], "w").write(deck(True))
PY
# ANSYS: a deck in the older (3i8,6e20.13) layout with a degenerate
# SOLID185 tet, SOLID285 tets of two materials, a shell, a non-solid EBLOCK,
# components and loads; and mapdl-archive's TetBeam example where
# install_deps.sh has put it.
seed ansys "$root"/.deps/python/mapdl_archive/examples/TetBeam.cdb
/usr/bin/python3 - "$seeds/ansys/small.cdb" <<'PY'
import sys
ints = lambda values, width: "".join(str(v).rjust(width) for v in values)
nodes = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (1, 1, 0), (0, 0, 1), (1, 0, 1), (0, 1, 1), (1, 1, 1), (0.4, 0.5, 0.6)]
quads = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]
lines = ["/PREP7", "ET,1,SOLID285", "ET,2,185", "ET,3,181", "NBLOCK,6,SOLID,9,9", "(3i8,6e20.13)"]
lines += [ints([i + 1, 0, 0], 8) + "".join("%20.13E" % c for c in p) for i, p in enumerate(nodes)]
lines += ["N,R5.3,LOC,       -1,", "EBLOCK,19,SOLID,14,14", "(19i8)"]
number = 0
for q in quads:
    for tet in ((9, q[0] + 1, q[1] + 1, q[2] + 1), (9, q[0] + 1, q[2] + 1, q[3] + 1)):
        number += 1
        if number == 1:
            lines.append(ints([1, 2, 1, 1, 0, 0, 0, 0, 8, 0, number, tet[0], tet[1], tet[2], tet[2]] + [tet[3]] * 4, 8))
        else:
            lines.append(ints([1 + number % 2, 1, 1, 1, 0, 0, 0, 0, 4, 0, number] + list(tet), 8))
lines.append(ints([1, 3, 1, 1, 0, 0, 0, 0, 4, 0, 13, 1, 2, 4, 3], 8))
lines += ["       -1", "ET,4,154", "EBLOCK,10,,,1", "(15i9)", ints([14, 4, 4, 4, 12, 5, 6, 8, 8], 9), "       -1"]
lines += ["CMBLOCK,TOP,NODE,        2", "(8i10)", ints([5, -8], 10)]
lines += ["CMBLOCK,HALF,ELEM,        2", "(8i10)", ints([1, -6], 10)]
lines += ["D,2,UX,0.0 $ F,3,FY,1.0 ! loads", "CP,1,UX,4,6", "FINISH"]
open(sys.argv[1], "w").write("\n".join(lines) + "\n")
PY
# fuzz_exodus reads a first byte 0 and the rest as the description of a file
# (exodus_spec.hpp), where any bytes will do; a first byte 1 and the bytes of
# a classic netCDF file: one tet with a side set, 64-bit offset format.
mkdir -p "$seeds/exodus"
head -c 256 /dev/zero | tr '\0' '\2' >"$seeds/exodus/description"
/usr/bin/python3 - "$seeds/exodus/classic" <<'PY'
import os, sys, tempfile
import netCDF4
path = os.path.join(tempfile.mkdtemp(), "tet.exo")
with netCDF4.Dataset(path, "w", format="NETCDF3_64BIT_OFFSET") as f:
    for name, n in [("len_name", 33), ("num_dim", 3), ("num_nodes", 4), ("num_elem", 1), ("num_el_blk", 1),
                    ("num_el_in_blk1", 1), ("num_nod_per_el1", 4), ("num_side_sets", 1), ("num_side_ss1", 1)]:
        f.createDimension(name, n)
    for c, values in zip("xyz", ([0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1])):
        f.createVariable("coord" + c, "f8", ("num_nodes",))[:] = values
    f.createVariable("eb_prop1", "i4", ("num_el_blk",))[:] = [1]
    connect = f.createVariable("connect1", "i4", ("num_el_in_blk1", "num_nod_per_el1"))
    connect.elem_type = "TETRA"
    connect[:] = [[1, 2, 3, 4]]
    f.createVariable("elem_ss1", "i4", ("num_side_ss1",))[:] = [1]
    f.createVariable("side_ss1", "i4", ("num_side_ss1",))[:] = [4]
with open(path, "rb") as f, open(sys.argv[1], "wb") as out:
    out.write(b"\x01" + f.read())
PY

failed=()
for t in "${targets[@]}"; do
  corpus=$build/fuzz-corpus/$t
  artifacts=$build/fuzz-artifacts/$t
  mkdir -p "$corpus" "$artifacts"
  dict=()
  [[ -f $root/tests/fuzz/$t.dict ]] && dict=(-dict="$root/tests/fuzz/$t.dict")
  echo "== fuzz_$t for ${seconds} s"
  # -malloc_limit_mb: a corrupt count must never turn into a huge allocation.
  if ! "$build/tests/fuzz/fuzz_$t" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -malloc_limit_mb=512 \
    -print_final_stats=1 -artifact_prefix="$artifacts/" "${dict[@]}" "$corpus" "$seeds/$t" \
    >"$build/fuzz-$t.log" 2>&1; then
    failed+=("$t")
    tail -n 40 "$build/fuzz-$t.log"
  else
    grep -E "^stat::number_of_executed_units|^#[0-9]+.*DONE" "$build/fuzz-$t.log" | tail -n 2 || true
  fi
done

if [[ ${#failed[@]} -gt 0 ]]; then
  echo "fuzzing found problems in: ${failed[*]} (inputs in $build/fuzz-artifacts/, logs in $build/fuzz-*.log)" >&2
  exit 1
fi
echo "all fuzz targets ran ${seconds} s without a finding"
