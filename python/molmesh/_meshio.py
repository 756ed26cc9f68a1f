"""Conversion to meshio.Mesh (meshio is imported only when a conversion is asked for)."""


def surface_to_meshio(self):
    """This surface as a meshio.Mesh: triangle cells, with "marker" point/cell data when
    the surface has markers. The arrays are shared with the Surface (no copy)."""
    import meshio

    point_data = {}
    cell_data = {}
    if len(self.vertex_markers):
        point_data["marker"] = self.vertex_markers
    if len(self.face_markers):
        cell_data["marker"] = [self.face_markers]
    return meshio.Mesh(self.vertices, [("triangle", self.faces)], point_data=point_data,
                       cell_data=cell_data)


def tetmesh_to_meshio(self, point_data=None):
    """This tetrahedral mesh as a meshio.Mesh: tetra cells with cell data "region", point
    data "marker" (plus ``point_data``, a dict of (n,) arrays, e.g. a solution), and the
    boundary faces as a second block of triangle cells (region 0) with "boundary_marker",
    as the VTU writer lays them out."""
    import meshio
    import numpy as np

    n_tets = len(self.tetrahedra)
    n_faces = len(self.boundary_faces)
    data = {"marker": self.vertex_markers}
    data.update(point_data or {})
    cells = [("tetra", self.tetrahedra)]
    region = [self.cell_markers]
    boundary = [np.zeros(n_tets, dtype=np.int32)]
    if n_faces:
        cells.append(("triangle", self.boundary_faces))
        region.append(np.zeros(n_faces, dtype=np.int32))
        boundary.append(self.boundary_face_markers)
    return meshio.Mesh(self.vertices, cells, point_data=data,
                       cell_data={"region": region, "boundary_marker": boundary})
