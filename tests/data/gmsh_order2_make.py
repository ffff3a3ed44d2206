#!/usr/bin/python3
"""Regenerates gmsh_order2_41.msh with the real Gmsh (Debian's python3-gmsh),
and its copy vtu_meshio_order2.vtu as meshio (python3-meshio) converts it: a
unit box with a spherical cavity (an OCC cut), meshed coarsely and raised to
second order, so it holds 10-node tets (Gmsh type 11), 6-node triangles
(type 9) and 3-node lines (type 8).

Why this shape: Gmsh puts the midside nodes of edges on the sphere onto the
sphere, so the tets touching the cavity have curved edges (and must keep
their shape when smoothed), while the box's faces and the interior give
straight edges whose midside nodes must follow their corners. Physical
groups on the volume (1), on the box's six faces (2), on the cavity (3) and
on the box's twelve edges (4) make Gmsh write the triangles and lines that
tetsmooth passes through unchanged. meshio writes tetra10 in VTK's node
order, which differs from Gmsh's (its last two nodes swapped), so the VTU
checks tetsmooth's reordering against the MSH. The VTU is binary (zlib) so
that it holds the same doubles as the MSH.

Run from tests/data with /usr/bin/python3 (the python3 first on PATH may
lack gmsh and meshio)."""
import gmsh
import meshio

gmsh.initialize()
gmsh.option.setNumber("General.Terminal", 0)
gmsh.model.add("order2")
box = gmsh.model.occ.addBox(0, 0, 0, 1, 1, 1)
# Small and off-centre: at this coarseness every interior node next to the
# cavity belongs to a curved tet and stays fixed, so the cavity must leave
# room for interior nodes that can move. Nearby sizes and places gave a few
# curved tets with a negative Jacobian (checked below); this one gives none.
CENTRE = 0.32
ball = gmsh.model.occ.addSphere(CENTRE, CENTRE, CENTRE, 0.15)
gmsh.model.occ.cut([(3, box)], [(3, ball)])
gmsh.model.occ.synchronize()

volume = gmsh.model.getEntities(3)
assert len(volume) == 1, volume
faces = [tag for _, tag in gmsh.model.getBoundary(volume, oriented=False)]
# The cavity is the one face whose centre of mass is the sphere's centre.
cavity = [f for f in faces if max(abs(c - CENTRE) for c in gmsh.model.occ.getCenterOfMass(2, f)) < 1e-9]
assert len(cavity) == 1, cavity
outer = [f for f in faces if f not in cavity]
edges = sorted({tag for _, tag in gmsh.model.getBoundary([(2, f) for f in outer], combined=False, oriented=False)})
gmsh.model.addPhysicalGroup(3, [volume[0][1]], 1)
gmsh.model.addPhysicalGroup(2, outer, 2)
gmsh.model.addPhysicalGroup(2, cavity, 3)
gmsh.model.addPhysicalGroup(1, edges, 4)

# About 700 tets, no refinement from curvature; at 0.25 Gmsh gives half as
# many, but then no interior corner node is free to move.
gmsh.option.setNumber("Mesh.MeshSizeMin", 0.24)
gmsh.option.setNumber("Mesh.MeshSizeMax", 0.24)
gmsh.option.setNumber("Mesh.MeshSizeFromCurvature", 0)
gmsh.model.mesh.generate(3)
gmsh.model.mesh.setOrder(2)
# Every tet valid: a positive Jacobian determinant at each Gauss point, so
# that the tests can ask the same of the smoothed mesh.
points, weights = gmsh.model.mesh.getIntegrationPoints(11, "Gauss4")
_, determinants, _ = gmsh.model.mesh.getJacobians(11, points)
assert min(determinants) > 0, min(determinants)
gmsh.option.setNumber("Mesh.MshFileVersion", 4.1)
gmsh.option.setNumber("Mesh.Binary", 0)
gmsh.write("gmsh_order2_41.msh")
gmsh.finalize()

mesh = meshio.read("gmsh_order2_41.msh")
# meshio 5.0 reads the MSH 4.1 entities' bounding lists as a cell set
# "gmsh:bounding_entities" that its VTU writer fails to turn into cell data
# (IndexError); it is not a mesh property, so it is left out.
mesh.cell_sets = {}
# Binary (meshio's default, zlib-compressed): its ASCII VTU prints 12 digits,
# and the VTU must hold Gmsh's coordinates bit for bit to be compared with
# the MSH after smoothing.
meshio.write("vtu_meshio_order2.vtu", mesh, binary=True)
