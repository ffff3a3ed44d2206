#!/usr/bin/python3
"""Regenerates gmsh_box_{ascii41,binary41,binary22}.msh with the real Gmsh
(Debian's python3-gmsh): a coarse unit box, the volume in physical group 7
"solid" and one face in group 3 "left"; and gmsh_box_{param22,
param_binary22}.msh, the same mesh in MSH 2.2 with Mesh.SaveParametric,
whose nodes come in a $ParametricNodes section. Run from tests/data."""
import gmsh

gmsh.initialize()
gmsh.option.setNumber("General.Terminal", 0)
gmsh.model.add("box")
gmsh.model.occ.addBox(0, 0, 0, 1, 1, 1)
gmsh.model.occ.synchronize()
gmsh.model.addPhysicalGroup(3, [1], 7)
gmsh.model.setPhysicalName(3, 7, "solid")
gmsh.model.addPhysicalGroup(2, [1], 3)
gmsh.model.setPhysicalName(2, 3, "left")
gmsh.model.mesh.setSize(gmsh.model.getEntities(0), 0.7)
gmsh.option.setNumber("Mesh.MeshSizeMax", 0.7)
gmsh.option.setNumber("Mesh.MeshSizeFromCurvature", 0)
gmsh.model.mesh.generate(3)
for version, binary, name in [(4.1, 0, "gmsh_box_ascii41.msh"), (4.1, 1, "gmsh_box_binary41.msh"),
                              (2.2, 1, "gmsh_box_binary22.msh")]:
    gmsh.option.setNumber("Mesh.MshFileVersion", version)
    gmsh.option.setNumber("Mesh.Binary", binary)
    gmsh.write(name)
gmsh.option.setNumber("Mesh.SaveParametric", 1)
for version, binary, name in [(2.2, 0, "gmsh_box_param22.msh"), (2.2, 1, "gmsh_box_param_binary22.msh")]:
    gmsh.option.setNumber("Mesh.MshFileVersion", version)
    gmsh.option.setNumber("Mesh.Binary", binary)
    gmsh.write(name)
gmsh.finalize()
