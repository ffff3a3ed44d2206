#!/usr/bin/python3
"""Regenerates gmsh_layers41.msh with the real Gmsh (Debian's python3-gmsh),
and its copies vtu_meshio_gmsh.vtu and vtk_meshio_gmsh.vtk as meshio
(python3-meshio) converts it: two boxes stacked in z, fragmented so that they
share the face z = 0.5, both volumes in one physical group 7, and a point
embedded in the lower one. Only Gmsh's entities tell the two volumes apart
and keep the point in place: in MSH 4.1 its entity blocks and node
classification, in meshio's VTU and VTK the cell data gmsh:geometrical and the
point data gmsh:dim_tags. Run from tests/data."""
import gmsh
import meshio

gmsh.initialize()
gmsh.option.setNumber("General.Terminal", 0)
gmsh.model.add("layers")
gmsh.model.occ.addBox(0, 0, 0, 1, 1, 0.5)
gmsh.model.occ.addBox(0, 0, 0.5, 1, 1, 0.5)
gmsh.model.occ.fragment([(3, 1)], [(3, 2)])
point = gmsh.model.occ.addPoint(0.5, 0.5, 0.25)
gmsh.model.occ.synchronize()
gmsh.model.mesh.embed(0, [point], 3, 1)
gmsh.model.addPhysicalGroup(3, [1, 2], 7)
gmsh.option.setNumber("Mesh.MeshSizeMin", 0.5)
gmsh.option.setNumber("Mesh.MeshSizeMax", 0.5)
gmsh.model.mesh.generate(3)
gmsh.option.setNumber("Mesh.MshFileVersion", 4.1)
gmsh.write("gmsh_layers41.msh")
gmsh.finalize()

mesh = meshio.read("gmsh_layers41.msh")
meshio.write("vtu_meshio_gmsh.vtu", mesh, binary=False)
meshio.write("vtk_meshio_gmsh.vtk", mesh, binary=False)
