"""Meshes from numpy arrays and from meshio: the same solution as the problem file on the same
mesh; node orders of second-order and 3D cells translated; bad arrays refused in one line."""

import subprocess

import meshio
import numpy as np
import pytest

import signorini


def mesh_problem(examples, name):
    """The problem file without its [mesh] section, as a dict, and its mesh file."""
    import tomllib
    with open(examples / name, "rb") as f:
        keys = tomllib.load(f)
    mesh_file = examples / keys.pop("mesh")["file"]
    return keys, mesh_file


@pytest.mark.parametrize("name", ["hertz.toml", "hertz_p2.toml", "hertz_sphere.toml"])
def test_meshio_mesh_solves_as_the_gmsh_file(examples, name):
    keys, mesh_file = mesh_problem(examples, name)
    reference = signorini.solve(signorini.Problem(examples / name))
    mesh = signorini.Mesh.from_meshio(meshio.read(mesh_file))
    result = signorini.solve(signorini.Problem(keys, mesh=mesh))
    # meshio keeps the file's node and cell order, the Gmsh reader sorts its cells: the same
    # discrete problem assembled in another order, equal to rounding.
    assert result.iterations == reference.iterations
    assert result.energy == pytest.approx(reference.energy, rel=1e-12)
    assert result.contact_force == pytest.approx(reference.contact_force, rel=1e-10)
    read = signorini.Mesh.read(mesh_file)
    assert mesh.num_cells == read.num_cells and mesh.num_nodes == read.num_nodes
    assert sorted(mesh.boundary_names) == sorted(read.boundary_names)


def test_arrays_of_a_read_mesh_give_its_bits(examples):
    keys, mesh_file = mesh_problem(examples, "hertz_p2.toml")
    read = signorini.Mesh.read(mesh_file)
    cells = [(t, read.cells(t)) for t in read.cell_types]
    # The boundary facets as (start, end, middle) lines, from the problem's own result
    with_file = signorini.solve(signorini.Problem(keys, mesh=read))
    reference = signorini.solve(signorini.Problem(examples / "hertz_p2.toml"))
    np.testing.assert_array_equal(with_file.u, reference.u)
    assert cells[0][1].shape[1] == 6


def test_two_squares_with_a_clockwise_cell_and_a_region():
    points = np.array([[0, 0], [1, 0], [2, 0], [0, 1], [1, 1], [2, 1]], float)
    mesh = signorini.Mesh(points, [("quad4", [[0, 3, 4, 1]], "soft"), ("quad4", [[1, 2, 5, 4]])],
                          {"bottom": [[0, 1], [1, 2]], "top": [[3, 4], [4, 5]]})
    assert mesh.cells("quad4").tolist() == [[0, 1, 4, 3], [1, 2, 5, 4]]
    assert mesh.region_names == ["soft"]
    np.testing.assert_array_equal(mesh.points, points)
    assert not mesh.points.flags.writeable
    assert mesh.boundary_nodes("bottom").tolist() == [0, 1, 2]
    assert "6 nodes" in repr(mesh)


def test_plane_points_with_a_constant_z_are_a_2d_mesh():
    # As Mesh.from_meshio takes them: z dropped, the same mesh as from two coordinates.
    xy = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], float)
    flat = signorini.Mesh(np.c_[xy, np.full(4, 2.5)], {"quad4": [[0, 1, 2, 3]]})
    assert flat.dim == 2
    np.testing.assert_array_equal(flat.points, xy)


@pytest.mark.parametrize("kwargs,words", [
    (dict(points=np.zeros((3, 4)), cells={}), "expected an array of shape (count, 2) or (count, 3)"),
    (dict(points=[[0, 0], [1, 0], [0, 1]], cells={"tri3": [[0, 1, 7]]}), "node 7 out of range"),
    (dict(points=[[0, 0], [1, 0], [0, 1], [5, 5]], cells={"tri3": [[0, 1, 2]]}),
     "point 3 belongs to no cell"),
    (dict(points=[[0, 0], [1, 0], [0, 1]], cells={"tri4": [[0, 1, 2]]}), "'tri4' is not a cell type"),
    (dict(points=[[0, 0], [1, 0], [0, 1]], cells={"tri3": [[0, 1, 2]]},
          boundaries={"side": [[1, 3]]}), "node 3 out of range"),
    (dict(points=[[0, 0], [1, 0], [0, 1]], cells={"tri3": [[0.5, 1, 2]]}), "expected integers"),
    # a collapsed quad, a doubled cell, points off one plane z = constant
    (dict(points=[[0, 0], [1, 0], [1, 1], [0, 1]], cells={"quad4": [[0, 1, 1, 3], [1, 2, 3, 0]]}),
     "cell 0 names node 1 twice (a collapsed cell)"),
    (dict(points=[[0, 0], [1, 0], [1, 1], [0, 1]], cells={"quad4": [[0, 1, 2, 3], [1, 2, 3, 0]]}),
     "have the same nodes (a doubled cell"),
    (dict(points=[[0, 0, 0], [1, 0, 0], [1, 1, 1], [0, 1, 0]], cells={"quad4": [[0, 1, 2, 3]]}),
     "2D cells on points whose z ranges from 0 to 1"),
])
def test_bad_arrays_raise_input_error(kwargs, words):
    with pytest.raises(signorini.InputError) as e:
        signorini.Mesh(**kwargs)
    assert words in str(e.value)


TET10_BOX = """SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 1, 0.5};
Physical Surface("bottom") = {5};
Physical Surface("top") = {6};
Physical Volume("body") = {1};
Mesh.CharacteristicLengthMax = 0.34;
Mesh.ElementOrder = 2;
"""
HEX27_BOX = """Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0};
Line(1) = {1, 2};
Transfinite Curve{1} = 4;
s[] = Extrude {0, 1, 0} { Line{1}; Layers{3}; Recombine; };
v[] = Extrude {0, 0, 0.5} { Surface{s[1]}; Layers{2}; Recombine; };
Physical Surface("bottom") = {s[1]};
Physical Surface("top") = {v[0]};
Physical Volume("body") = {v[1]};
Mesh.ElementOrder = 2;
"""


@pytest.mark.parametrize("geometry,cell", [(TET10_BOX, "tet10"), (HEX27_BOX, "hex27")])
def test_second_order_3d_node_orders_from_meshio(tmp_path, geometry, cell):
    """tet10 and hex27 through meshio (VTK's node orders) solve as the Gmsh reader's mesh."""
    geo, msh = tmp_path / "box.geo", tmp_path / "box.msh"
    geo.write_text(geometry)
    subprocess.run(["gmsh", "-3", str(geo), "-format", "msh41", "-o", str(msh)],
                   check=True, capture_output=True)
    keys = {"material": {"E": 1.0, "nu": 0.3}, "clamp": [{"boundary": "top"}],
            "body_force": {"f": ["0.1", "0", "-1"]},
            "contact": {"boundary": "bottom", "obstacle": "plane",
                        "point": [0.0, 0.0, -0.05], "normal": [0.2, 0.0, 1.0]}}
    read = signorini.Mesh.read(msh)
    converted = signorini.Mesh.from_meshio(meshio.read(msh))
    assert converted.cell_types == read.cell_types == [cell]
    a = signorini.solve(signorini.Problem(keys, mesh=read))
    b = signorini.solve(signorini.Problem(keys, mesh=converted))
    assert 0 < a.num_active < read.boundary_nodes("bottom").size
    assert b.iterations == a.iterations
    assert b.energy == pytest.approx(a.energy, rel=1e-11)
    assert b.contact_force == pytest.approx(a.contact_force, rel=1e-9)
