#!/usr/bin/python3
"""Regenerates, with the real Gmsh (Debian's python3-gmsh), the fixtures of
two boxes stacked in z, fragmented so that they share the face z = 0.5:

* gmsh_layers41.msh, and its copies vtu_meshio_gmsh.vtu and
  vtk_meshio_gmsh.vtk as meshio (python3-meshio) converts it: both volumes in
  one physical group 7, and a point embedded in the lower one. Only Gmsh's
  entities tell the two volumes apart and keep the point in place: in MSH
  4.1 its entity blocks and node classification, in meshio's VTU and VTK the
  cell data gmsh:geometrical and the point data gmsh:dim_tags.
* abaqus_gmsh_layers.inp, an Abaqus deck as Gmsh writes one: each volume in
  its own physical group (11 and 12), the bottom face in group 5, with Gmsh's
  groups of nodes. Gmsh writes each volume's tets under ELSET=Volume<entity>,
  the bottom face's triangles as CPS3 elements, and *ELSET/*NSET lists of
  the physical groups.
* nastran_gmsh_layers.bdf, the same model as Gmsh writes Nastran bulk data in
  small field: CTETRA with the volume's entity tag as PID, the bottom face's
  CTRIA3, no BEGIN BULK.

Run from tests/data."""
import gmsh
import meshio


def two_layers(name, size):
    """A new model of the two boxes, to be meshed with elements of `size`."""
    gmsh.model.add(name)
    gmsh.model.occ.addBox(0, 0, 0, 1, 1, 0.5)
    gmsh.model.occ.addBox(0, 0, 0.5, 1, 1, 0.5)
    gmsh.model.occ.fragment([(3, 1)], [(3, 2)])
    gmsh.model.occ.synchronize()
    gmsh.option.setNumber("Mesh.MeshSizeMin", size)
    gmsh.option.setNumber("Mesh.MeshSizeMax", size)


gmsh.initialize()
gmsh.option.setNumber("General.Terminal", 0)

two_layers("layers", 0.5)
point = gmsh.model.occ.addPoint(0.5, 0.5, 0.25)
gmsh.model.occ.synchronize()
gmsh.model.mesh.embed(0, [point], 3, 1)
gmsh.model.addPhysicalGroup(3, [1, 2], 7)
gmsh.model.mesh.generate(3)
gmsh.option.setNumber("Mesh.MshFileVersion", 4.1)
gmsh.write("gmsh_layers41.msh")

two_layers("abaqus", 0.3)
gmsh.model.addPhysicalGroup(3, [1], 11)
gmsh.model.addPhysicalGroup(3, [2], 12)
bottom = [tag for dim, tag in gmsh.model.getEntities(2) if abs(gmsh.model.occ.getCenterOfMass(dim, tag)[2]) < 1e-9]
gmsh.model.addPhysicalGroup(2, bottom, 5)
gmsh.model.mesh.generate(3)
gmsh.option.setNumber("Mesh.SaveGroupsOfNodes", 1)
gmsh.write("abaqus_gmsh_layers.inp")
gmsh.option.setNumber("Mesh.BdfFieldFormat", 1)
gmsh.write("nastran_gmsh_layers.bdf")
gmsh.finalize()

mesh = meshio.read("gmsh_layers41.msh")
meshio.write("vtu_meshio_gmsh.vtu", mesh, binary=False)
meshio.write("vtk_meshio_gmsh.vtk", mesh, binary=False)
