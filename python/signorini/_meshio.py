"""A meshio.Mesh as a signorini.Mesh: cell types and node orders translated, the points that no
cell uses left out, boundary parts and regions taken from the mesh's named sets."""

from ._signorini import InputError, Mesh

# numpy is imported when a mesh is converted, not with the package: a script that solves a
# problem file and writes its results starts 0.08 s sooner (docs/performance.md).

# meshio's cell type names (VTK's node orders) and ours (Gmsh's, mesh/cell_type.hpp).
_CELLS = {
    "triangle": "tri3",
    "triangle6": "tri6",
    "quad": "quad4",
    "quad8": "quad8",
    "quad9": "quad9",
    "tetra": "tet4",
    "tetra10": "tet10",
    "hexahedron": "hex8",
    "hexahedron27": "hex27",
}
# VTK's node k is our node ORDER[k] (the tables of output/vtu_file.cpp).
_VTK_ORDER = {
    "tet10": [0, 1, 2, 3, 4, 5, 6, 7, 9, 8],
    "hex27": [0, 1, 2, 3, 4, 5, 6, 7, 8, 11, 13, 9, 16, 18, 19, 17, 10, 12, 14, 15, 22, 23, 21,
              24, 20, 25, 26],
}
_FACETS = {2: ("line", "line3"), 3: ("triangle", "triangle6", "quad", "quad8", "quad9")}
_DIM = {"tri3": 2, "tri6": 2, "quad4": 2, "quad8": 2, "quad9": 2,
        "tet4": 3, "tet10": 3, "hex8": 3, "hex27": 3}


def _ours(kind, nodes):
    import numpy as np

    order = _VTK_ORDER.get(kind)
    if order is None:
        return nodes
    out = np.empty_like(nodes)
    out[:, order] = nodes
    return out


def _named_sets(mesh):
    """{name: [indices per cell block]}: meshio's cell_sets, or gmsh:physical with field_data."""
    import numpy as np

    sets = {}
    for name, per_block in (mesh.cell_sets or {}).items():
        if name.startswith("gmsh:"):
            continue
        sets[name] = [np.asarray(s, dtype=np.int64) if s is not None else np.zeros(0, np.int64)
                      for s in per_block]
    if sets:
        return sets
    physical = mesh.cell_data.get("gmsh:physical")
    if physical is None:
        return sets
    for name, (tag, _dim) in (mesh.field_data or {}).items():
        sets[name] = [np.flatnonzero(np.asarray(p) == tag) for p in physical]
    return sets


def from_meshio(mesh):
    """A signorini.Mesh from a meshio.Mesh.

    Cells of the highest dimension present (triangles and quadrilaterals in 2D; tetrahedra and
    hexahedra in 3D, first or second order) become the cells; named sets of cells one dimension
    down (lines in 2D, triangles or quadrilaterals in 3D) become the boundary parts, and named
    sets of cells the regions, from meshio's cell_sets or Gmsh's physical groups
    (cell_data["gmsh:physical"] with field_data). A 2D mesh may have z coordinates, all equal.
    Points that no cell uses are left out; `Mesh.points` then has the remaining ones in order.
    """
    import numpy as np

    blocks = [(b.type, np.asarray(b.data, dtype=np.int64)) for b in mesh.cells]
    kinds = [_CELLS.get(t) for t, _ in blocks]
    dims = [_DIM[k] for k in kinds if k is not None]
    if not dims:
        raise InputError("mesh: the meshio mesh has no cells signorini takes (triangle, quad, "
                         "tetra, hexahedron and their second-order kinds)")
    dim = max(dims)
    points = np.asarray(mesh.points, dtype=float)
    if points.shape[1] == 3 and dim == 2:
        z = points[:, 2]
        if np.ptp(z) > 1e-9 * max(np.ptp(points[:, :2]), 1e-300):
            raise InputError("mesh: a 2D mesh whose points do not lie in one plane z = constant")
        points = points[:, :2]
    cell_blocks = [i for i, k in enumerate(kinds) if k is not None and _DIM[k] == dim]
    facet_blocks = [i for i, (t, _) in enumerate(blocks) if t in _FACETS[dim]]

    # Points used by a cell, numbered in their order.
    used = np.zeros(len(points), dtype=bool)
    for i in cell_blocks:
        used[blocks[i][1].ravel()] = True
    number = np.full(len(points), -1, dtype=np.int64)
    number[used] = np.arange(int(used.sum()))

    sets = _named_sets(mesh)
    cells = []
    for i in cell_blocks:
        kind = kinds[i]
        nodes = _ours(kind, number[blocks[i][1]])
        region_of = np.full(len(nodes), "", dtype=object)
        for name, per_block in sets.items():
            if i < len(per_block) and len(per_block[i]):
                region_of[per_block[i]] = name
        for region in dict.fromkeys(region_of):
            cells.append((kind, nodes[region_of == region], region))
    boundaries = {}
    for name, per_block in sets.items():
        facets = [number[blocks[i][1][per_block[i]]] for i in facet_blocks
                  if i < len(per_block) and len(per_block[i])]
        if not facets:
            continue
        if len({f.shape[1] for f in facets}) > 1:
            raise InputError(f"mesh: boundary part '{name}' mixes facets of different kinds")
        boundaries[name] = np.concatenate(facets)
    return Mesh(points[used], cells, boundaries)
