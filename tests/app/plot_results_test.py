#!/usr/bin/env python3
"""Unit tests of the pure functions of the plotting script (tools/plot_results.py, the command, and
tools/signorini_figures.py, its module; the figures themselves are tested through the tool, in
plot_test.cpp).

    /usr/bin/python3 tests/app/plot_results_test.py        # exit status 0: all passed

Needs numpy (python3-numpy); matplotlib is not imported.
"""

import importlib.util
import json
import math
import os
import sys
import tempfile
import unittest

TOOLS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools")
SCRIPT = os.path.join(TOOLS, "plot_results.py")
spec = importlib.util.spec_from_file_location("signorini_figures",
                                              os.path.join(TOOLS, "signorini_figures.py"))
plot = importlib.util.module_from_spec(spec)
spec.loader.exec_module(plot)

import numpy as np  # noqa: E402


class UnitsTest(unittest.TestCase):
    def test_every_system_of_the_table(self):
        self.assertEqual(plot.units_of("m-Pa"), ("m", "Pa", "N/m"))
        self.assertEqual(plot.units_of("m-kPa"), ("m", "kPa", "kN/m"))
        self.assertEqual(plot.units_of("m-MPa"), ("m", "MPa", "MN/m"))
        self.assertEqual(plot.units_of("m-GPa"), ("m", "GPa", "GN/m"))
        self.assertEqual(plot.units_of("mm-MPa"), ("mm", "MPa", "N/mm"))

    def test_aliases_name_the_same_systems(self):
        self.assertEqual(plot.units_of("mm-N"), plot.units_of("mm-MPa"))
        self.assertEqual(plot.units_of("m-N"), plot.units_of("m-Pa"))

    def test_the_fields(self):
        units = plot.units_of("mm-N")
        self.assertEqual(units.length, "mm")
        self.assertEqual(units.stress, "MPa")
        self.assertEqual(units.force_per_thickness, "N/mm")

    def test_absent_null_or_unknown_settings_give_no_units(self):
        for setting in (None, "", "MPa", "m-mpa", "M-MPa", "mm-kN", "cm-Pa", " m-MPa", 3, ["m"]):
            with self.subTest(setting=setting):
                self.assertEqual(plot.units_of(setting), plot.NO_UNITS)
                self.assertEqual(plot.units_of(setting), ("", "", ""))

    def test_every_alias_names_a_system(self):
        for alias, system in plot.UNIT_ALIASES.items():
            self.assertIn(system, plot.UNIT_SYSTEMS, alias)

    def test_force_per_thickness_is_stress_times_length(self):
        # N/m^2 x m = N/m; the prefix of the stress stays, mm turns N/mm^2 (MPa) into N/mm.
        for setting, (length, stress, force) in plot.UNIT_SYSTEMS.items():
            with self.subTest(setting=setting):
                self.assertTrue(force.endswith("/" + length), force)
                if length == "m":
                    self.assertEqual(force, stress.replace("Pa", "N") + "/m")

    def test_the_setting_comes_from_the_problem_in_the_summary(self):
        self.assertEqual(plot.units_of_summary({"problem": {"units": "m-MPa"}}).stress, "MPa")
        self.assertEqual(plot.units_of_summary({"problem": {"units": None}}), plot.NO_UNITS)
        self.assertEqual(plot.units_of_summary({"problem": {}}), plot.NO_UNITS)
        self.assertEqual(plot.units_of_summary({}), plot.NO_UNITS)
        self.assertEqual(plot.units_of_summary({"units": "m-MPa"}), plot.NO_UNITS)

    def test_an_unknown_setting_is_said_on_stderr(self):
        with tempfile.TemporaryFile("w+") as err:
            saved, sys.stderr = sys.stderr, err
            try:
                units = plot.units_of_summary({"problem": {"units": "furlongs"}})
                quiet = plot.units_of_summary({"problem": {"units": "furlongs"}}, warnings=False)
            finally:
                sys.stderr = saved
            err.seek(0)
            text = err.read()
        self.assertEqual(units, plot.NO_UNITS)
        self.assertEqual(quiet, plot.NO_UNITS)
        self.assertEqual(text.count("\n"), 1)
        self.assertIn('signorini: warning: units = "furlongs"', text)
        self.assertIn("m-MPa", text)


class LabelsTest(unittest.TestCase):
    def test_axis_labels(self):
        self.assertEqual(plot.axis_label("x", "m"), "x (m)")
        self.assertEqual(plot.axis_label("x", ""), "x")
        self.assertEqual(plot.axis_label("displacement", "mm", -4), "displacement (10⁻⁴ mm)")
        self.assertEqual(plot.axis_label("displacement", "", -4), "displacement (×10⁻⁴)")
        self.assertEqual(plot.axis_label("contact pressure", "Pa", 6),
                         "contact pressure (10⁶ Pa)")

    def test_numbers_with_units(self):
        self.assertEqual(plot.with_unit("0.648", "MN/m"), "0.648 MN/m")
        self.assertEqual(plot.with_unit("0.648", ""), "0.648")

    def test_powers_of_ten_in_plain_text(self):
        self.assertEqual(plot.power_text(-12), "10⁻¹²")
        self.assertEqual(plot.power_text(0), "10⁰")
        self.assertEqual(plot.power_text(3), "10³")

    def test_power_of_ten_of_an_axis(self):
        self.assertEqual(plot.power_of_ten(np.array([-1.9e-4, 6e-5])), -4)
        self.assertEqual(plot.power_of_ten(np.array([1.5, 0.0])), 0)
        self.assertEqual(plot.power_of_ten(np.array([150.0])), 0)  # 10^-2 .. 10^2 stay
        self.assertEqual(plot.power_of_ten(np.array([1.5e6, np.nan])), 6)
        self.assertEqual(plot.power_of_ten(np.array([0.0, 0.0])), 0)
        self.assertEqual(plot.power_of_ten(np.array([np.nan])), 0)


class HelpersTest(unittest.TestCase):
    def test_nice_below(self):
        self.assertEqual(plot.nice_below(1234.0), 1000)
        self.assertEqual(plot.nice_below(0.3), 0.2)
        self.assertEqual(plot.nice_below(5.0), 5)

    def test_the_magnification_of_the_paper(self):
        points = np.array([[0.0, 0.0], [3.0, 0.0], [3.0, 1.0]])
        u = np.array([[0.0, 0.0], [1e-4, 2e-4], [0.0, 0.0]])
        self.assertEqual(plot.magnification(points, u), 1000)
        self.assertEqual(plot.magnification(points, np.zeros((3, 2))), 1.0)

    def test_contact_intervals(self):
        t = np.array([0.0, 1.0, 2.0, 3.0, 4.0, 5.0])
        self.assertEqual(plot.contact_intervals(t, np.array([0, 1, 1, 0, 0, 1]) > 0),
                         [(0.5, 2.5), (4.5, 5.0)])
        self.assertEqual(plot.contact_intervals(t, np.zeros(6, bool)), [])
        self.assertEqual(plot.contact_intervals(t, np.ones(6, bool)), [(0.0, 5.0)])

    def test_padded(self):
        self.assertEqual(plot.padded(0.0, 10.0), (-0.5, 10.5))
        lo, hi = plot.padded(0.0, 0.0)
        self.assertLess(lo, 0.0)
        self.assertGreater(hi, 0.0)

    def test_the_abscissa_along_the_boundary(self):
        flat = {"x": np.array([0.0, 1.0, 2.0]), "y": np.zeros(3)}
        t, label = plot.boundary_coordinate(flat, plot.units_of("m-MPa"))
        self.assertEqual(label, "x (m)")
        np.testing.assert_array_equal(t, flat["x"])
        upright = {"x": np.zeros(3), "y": np.array([0.0, 0.5, 1.0])}
        self.assertEqual(plot.boundary_coordinate(upright, plot.NO_UNITS)[1], "y")
        bent = {"x": np.array([0.0, 3.0, 3.0]), "y": np.array([0.0, 0.0, 4.0])}
        t, label = plot.boundary_coordinate(bent, plot.units_of("mm-N"))
        np.testing.assert_allclose(t, [0.0, 3.0, 7.0])
        self.assertEqual(label, "arc length along the contact boundary (mm)")
        # Two contact boundaries: the arc length along each, from 0 on each.
        two = {"x": np.array([0.0, 1.0, 2.0, 2.0, 2.0]), "y": np.array([0.0, 0.0, 0.0, 0.0, 1.5]),
               "boundary": ["bottom", "bottom", "bottom", "right", "right"]}
        self.assertEqual([(n, list(r)) for n, r in plot.boundary_parts(two)],
                         [("bottom", [0, 1, 2]), ("right", [3, 4])])
        t, label = plot.boundary_coordinate(two, plot.NO_UNITS)
        np.testing.assert_allclose(t, [0.0, 1.0, 2.0, 0.0, 1.5])
        self.assertEqual(label, "arc length along each contact boundary")


class StepsTest(unittest.TestCase):
    """--steps: the load steps of a history, checked against summary.json and steps/."""

    def folder(self, d, steps):
        with open(os.path.join(d, "summary.json"), "w") as f:
            json.dump({"load_steps": [{"factor": (k + 1) / steps, "contact_force": 1.0 + k}
                                      for k in range(steps)]} if steps else {}, f)
        os.makedirs(os.path.join(d, "steps"), exist_ok=True)
        for k in range(1, steps + 1):
            with open(os.path.join(d, plot.step_csv(k)), "w") as f:
                f.write("x,y\n")

    def test_chosen_steps(self):
        with tempfile.TemporaryDirectory() as d:
            self.folder(d, 3)
            self.assertEqual(plot.chosen_steps(d, ""), [])
            self.assertEqual(plot.chosen_steps(d, "3, 1,3"), [1, 3])
            self.assertEqual(plot.chosen_steps(d, "all"), [1, 2, 3])
            with self.assertRaisesRegex(plot.UsageError, "step 4 is not one of the history's"):
                plot.chosen_steps(d, "4")
            with self.assertRaisesRegex(plot.UsageError, "expected step numbers"):
                plot.chosen_steps(d, "one")
            os.unlink(os.path.join(d, plot.step_csv(2)))
            with self.assertRaisesRegex(plot.UsageError, "contact_0002.csv' not found"):
                plot.chosen_steps(d, "2")
        with tempfile.TemporaryDirectory() as d:
            self.folder(d, 0)
            with self.assertRaisesRegex(plot.UsageError, "no loading history"):
                plot.chosen_steps(d, "1")

    def test_the_view_of_a_step(self):
        summary = {"contact_force": 9.0, "friction": {"law": "coulomb", "sticking": 3},
                   "load_steps": [{"factor": 0.5, "contact_force": 4.0, "converged": True},
                                  {"factor": 1.0, "contact_force": 9.0, "converged": True}]}
        view = plot.step_view(summary, 1)
        self.assertEqual(view["contact_force"], 4.0)
        self.assertEqual(view["friction"], {"law": "coulomb"})
        self.assertIn("load step 1 of 2 (factor 0.5)", plot.title_of(view))
        self.assertIn("load step 2 of 2 (factor 1)", plot.title_of(summary))
        self.assertEqual(plot.figure_names(2, True, [2])[-1], "contact_friction_step_0002")
        self.assertEqual(plot.figure_names(3, True, [1])[-2:],
                         ["contact_friction_map", "contact_friction_map_step_0001"])
        self.assertEqual(plot.figure_names(3, False, [1])[-1], "contact_pressure_map_step_0001")


class ReadingTest(unittest.TestCase):
    def write(self, folder, name, text):
        with open(os.path.join(folder, name), "w", encoding="utf-8") as f:
            f.write(text)

    def test_the_normal_comes_from_contact_csv(self):
        with tempfile.TemporaryDirectory() as d:
            self.write(d, "contact.csv", "x,y,u_n,u_t,pressure,gap,n_x,n_y\n"
                                         "0,1,1e-5,2e-5,0.5,0.25,1,0\n"
                                         "0,2,0,0,0,0.5,0.6,0.8\n")
            c = plot.read_contact_csv(d)
        np.testing.assert_array_equal(c["n_x"], [1.0, 0.6])
        np.testing.assert_array_equal(c["n_y"], [0.0, 0.8])
        np.testing.assert_array_equal(c["gap"], [0.25, 0.5])
        np.testing.assert_array_equal(c["pressure"], [0.5, 0.0])

    def test_older_files_without_the_normal_have_the_bottom_edge_one(self):
        with tempfile.TemporaryDirectory() as d:
            self.write(d, "contact.csv", "x,y,u_n,u_t,pressure,gap\n0,0,0,0,0,0\n1,0,0,0,1,0\n")
            c = plot.read_contact_csv(d)
        np.testing.assert_array_equal(c["n_x"], [0.0, 0.0])
        np.testing.assert_array_equal(c["n_y"], [-1.0, -1.0])

    def test_unusable_files_are_usage_errors(self):
        with tempfile.TemporaryDirectory() as d:
            with self.assertRaisesRegex(plot.UsageError, "not found"):
                plot.read_contact_csv(d)
            self.write(d, "contact.csv", "x,y,pressure\n0,0,0\n")
            with self.assertRaisesRegex(plot.UsageError, "expected the columns"):
                plot.read_contact_csv(d)
            self.write(d, "contact.csv", "x,y,u_n,u_t,pressure,gap\n")
            with self.assertRaisesRegex(plot.UsageError, "no contact nodes"):
                plot.read_contact_csv(d)
            self.write(d, "solution.vtu", "")
            with self.assertRaisesRegex(plot.UsageError, "not a VTU file"):
                plot.read_vtu(os.path.join(d, "solution.vtu"))


class MeshTest(unittest.TestCase):
    @staticmethod
    def rectangle(nx, ny):
        """The cells of signorini's rectangle mesh: node i + j (nx + 1), counterclockwise."""
        n0 = (np.arange(ny)[:, None] * (nx + 1) + np.arange(nx)[None, :]).ravel()
        conn = np.stack([n0, n0 + 1, n0 + 2 + nx, n0 + 1 + nx], axis=1).ravel()
        return {"points": np.zeros(((nx + 1) * (ny + 1), 3)), "connectivity": conn,
                "offsets": 4 * np.arange(1, nx * ny + 1), "types": np.full(nx * ny, 9, np.uint8)}

    def test_a_rectangle_mesh_is_a_grid(self):
        self.assertEqual(plot.structured_grid(self.rectangle(3, 2)), (3, 4))
        self.assertEqual(plot.structured_grid(self.rectangle(1, 1)), (2, 2))

    def test_other_meshes_are_not(self):
        mesh = self.rectangle(3, 2)
        mesh["connectivity"] = mesh["connectivity"].copy()
        mesh["connectivity"][[4, 5]] = mesh["connectivity"][[5, 4]]
        self.assertIsNone(plot.structured_grid(mesh))
        triangles = {"points": np.zeros((4, 3)), "connectivity": np.array([0, 1, 2, 0, 2, 3]),
                     "offsets": np.array([3, 6]), "types": np.array([5, 5])}
        self.assertIsNone(plot.structured_grid(triangles))

    def test_the_outline_is_one_closed_chain(self):
        cells, outline = plot.cells_and_outline(self.rectangle(3, 2))
        self.assertEqual(cells.shape, (6, 4))
        self.assertEqual(len(outline), 1)
        chain = outline[0]
        self.assertEqual(chain[0], chain[-1])
        self.assertEqual(sorted(set(chain)), [0, 1, 2, 3, 4, 7, 8, 9, 10, 11])  # not 5, 6

    def test_the_outline_of_triangles(self):
        triangles = {"points": np.zeros((4, 3)), "connectivity": np.array([0, 1, 2, 0, 2, 3]),
                     "offsets": np.array([3, 6]), "types": np.array([5, 5])}
        _, outline = plot.cells_and_outline(triangles)
        self.assertEqual(len(outline), 1)
        self.assertEqual(sorted(set(outline[0])), [0, 1, 2, 3])
        self.assertEqual(len(outline[0]), 5)  # four edges, closed


class CheckTest(unittest.TestCase):
    def test_check_finds_numpy_and_matplotlib_without_importing_them(self):
        before = set(sys.modules)
        try:
            plot.check_plotting()
        except plot.UsageError as e:
            self.skipTest(f"no matplotlib here: {e}")
        self.assertNotIn("matplotlib", set(sys.modules) - before)


@unittest.skipUnless(hasattr(os, "fork"), "no fork")
class TwoProcessesTest(unittest.TestCase):
    """save_all with two processes (forced), drawing with a stand-in for `draw`: what either
    process wrote goes when either fails."""

    def run_save_all(self, folder, fails):
        """`fails`: None, "helper" (which raises after writing its first figure) or "here"
        (which raises after the helper has written its figures). This process waits a little
        first, so that the helper takes figures."""
        import time

        here = os.getpid()

        def fake_draw(outdir, next_figure, scale, written, formats, warnings=True,
                      hertz=(None, 1), steps=()):
            if os.getpid() == here:
                time.sleep(0.3)
                if fails == "here":
                    raise plot.UsageError("here fails")
            drawn = []
            while (name := next_figure()) is not None:
                drawn.append(name)
                for fmt in formats:
                    tmp = os.path.join(outdir, f".{name}.{fmt}.tmp.{os.getpid()}")
                    written.append((tmp, os.path.join(outdir, f"{name}.{fmt}")))
                    with open(tmp, "w") as f:
                        f.write("a figure")
                if fails == "helper" and os.getpid() != here:
                    raise plot.UsageError("helper fails")
            return drawn

        saved = plot.draw, plot.cores
        plot.draw, plot.cores = fake_draw, lambda: 2
        try:
            plot.save_all(folder, None, True, ["png", "svg"])
        finally:
            plot.draw, plot.cores = saved

    def test_all_figures_when_both_succeed(self):
        with tempfile.TemporaryDirectory() as d:
            self.run_save_all(d, fails=None)
            self.assertEqual(sorted(os.listdir(d)),
                             sorted(f"{n}.{e}" for n in plot.FIGURES for e in ("png", "svg")))

    def test_nothing_when_either_fails(self):
        for fails in ("helper", "here"):
            with self.subTest(fails=fails), tempfile.TemporaryDirectory() as d:
                with self.assertRaisesRegex(plot.UsageError, f"{fails} fails"):
                    self.run_save_all(d, fails)
                self.assertEqual(os.listdir(d), [])


def surface(points, normals, pressure, pieces, displacement=None):
    """contact.csv's columns of a 3D contact surface, with contact.vtu's faces (as draw() reads
    them): `pieces` rows of node numbers, three or four (a triangle's last repeated)."""
    points, normals = np.asarray(points, float), np.asarray(normals, float)
    rows = [list(r) + [r[-1]] * (4 - len(r)) for r in pieces]
    contact = {name: points[:, k] for k, name in enumerate("xyz")}
    contact.update({f"n_{name}": normals[:, k] for k, name in enumerate("xyz")})
    contact["pressure"] = np.asarray(pressure, float)
    contact["faces"] = {"pieces": np.array(rows, dtype=np.int64).reshape(-1, 4),
                        "displacement": displacement}
    return contact


def grid(nx, ny, x1=1.0, y1=1.0):
    """The nodes (i x1 / nx, j y1 / ny, 0), node i + (nx + 1) j, and the quadrilaterals between
    them (every other turned the other way, as faces need not agree on their winding)."""
    xs, ys = np.meshgrid(np.linspace(0.0, x1, nx + 1), np.linspace(0.0, y1, ny + 1))
    points = np.stack([xs.ravel(), ys.ravel(), 0.0 * xs.ravel()], axis=1)
    quads = []
    for j in range(ny):
        for i in range(nx):
            q = [i + (nx + 1) * j, i + 1 + (nx + 1) * j, i + 1 + (nx + 1) * (j + 1),
                 i + (nx + 1) * (j + 1)]
            quads.append(q if (i + j) % 2 == 0 else q[::-1])
    return points, quads


def bottom_with_wall(n=4, pressure=2.0):
    """A body's bottom face z = 0 over (0, 1)^2 in n x n quadrilaterals (n even), pressed all
    over, and, in the same contact part, a wall free of pressure that stands on it along
    x = 0.5 (the face of a slot cut up into the body, z up to 0.5): seen along z, the wall's
    nodes fall onto the middle of the patch."""
    points, quads = grid(n, n)
    normals = np.tile([0.0, 0.0, -1.0], (len(points), 1))
    bottom = len(points)
    foot = [n // 2 + (n + 1) * j for j in range(n + 1)]
    rows = [foot]
    for z in (0.25, 0.5):
        rows.append(list(range(len(points), len(points) + n + 1)))
        points = np.vstack([points, [[0.5, j / n, z] for j in range(n + 1)]])
        normals = np.vstack([normals, np.tile([1.0, 0.0, 0.0], (n + 1, 1))])
    wall = [[r0[j], r0[j + 1], r1[j + 1], r1[j]] for r0, r1 in zip(rows, rows[1:])
            for j in range(n)]
    p = np.where(np.arange(len(points)) < bottom, pressure, 0.0)
    return surface(points, normals, p, quads + wall), quads, bottom


def area(polygons):
    """The total area of polygons (rows of four corners in the plane)."""
    x, y = polygons[..., 0], polygons[..., 1]
    return float(np.sum(0.5 * np.abs(np.sum(x * np.roll(y, -1, axis=1)
                                             - np.roll(x, -1, axis=1) * y, axis=1))))


class SurfaceTest(unittest.TestCase):
    """3D: the faces of the contact surface that the pressure map draws (contact.vtu's, those
    that face the obstacle), not every node projected along the view."""

    def test_the_side_walls_are_left_out(self):
        contact, quads, bottom = bottom_with_wall()
        view = plot.surface_view(contact)
        self.assertEqual((view.k, view.side), (2, -1))  # seen from below, the obstacle's side
        self.assertEqual((view.i, view.j), (0, 1))
        self.assertEqual(sorted(sorted(r) for r in view.pieces.tolist()),
                         sorted(sorted(q) for q in quads))
        self.assertTrue(np.all(view.seen[:bottom]))
        self.assertFalse(np.any(view.seen[bottom:]))
        self.assertAlmostEqual(view.spacing, 0.25)

    def test_no_zero_pressure_hole_in_the_patch(self):
        # The wall's nodes, projected, lie on the patch's middle line with no pressure: drawn
        # from the nodes, the uniformly pressed patch had a zero-pressure stripe there.
        contact, _, _ = bottom_with_wall()
        view = plot.surface_view(contact)
        polygons, colours = plot.pieces_coloured(view, contact["pressure"])
        np.testing.assert_allclose(colours, 2.0)
        self.assertAlmostEqual(area(polygons), 1.0)  # the whole square, no gap
        self.assertEqual(polygons.shape[1:], (4, 2))
        # Cut finer where the mesh is coarse: 16 faces into 10 x 10.
        self.assertEqual(len(polygons), 16 * 100)

    def test_the_pieces_interpolate_the_nodal_values(self):
        points, quads = grid(1, 1)
        contact = surface(points, np.tile([0.0, 0.0, -1.0], (4, 1)), points[:, 0],
                          [quads[0], [0, 1, 2]])
        view = plot.surface_view(contact)
        polygons, colours = plot.pieces_coloured(view, contact["pressure"], most=4 * 2)
        self.assertEqual(len(polygons), 8)  # each piece into 2 x 2
        centres = np.array([np.mean(np.unique(q, axis=0), axis=0) for q in polygons])
        # p = x on both pieces, the triangle's linear, the quadrilateral's bilinear
        np.testing.assert_allclose(colours, centres[:, 0], atol=1e-12)

    def test_the_nearest_faces_are_drawn_last_and_those_turned_away_not(self):
        square = [[0, 0], [1, 0], [1, 1], [0, 1]]
        points = ([[x, y, 0.2] for x, y in square] + [[x, y, 0.0] for x, y in square]
                  + [[x, y, 0.1] for x, y in square])
        normals = [[0.0, 0.0, -1.0]] * 8 + [[0.0, 0.0, 1.0]] * 4  # the last turned upwards
        contact = surface(points, normals, [1.0] * 12,
                          [[4, 5, 6, 7], [8, 9, 10, 11], [0, 1, 2, 3]])
        view = plot.surface_view(contact)
        self.assertEqual(view.pieces.tolist(), [[0, 1, 2, 3], [4, 5, 6, 7]])  # z = 0 nearest

    def test_the_view_follows_the_pressed_faces(self):
        # More nodes on a side wall (normal x) than on the pressed base (normal -z): their mean
        # normal is sideways, the pressure's down.
        normals = [[0.0, 0.0, -1.0]] * 3 + [[1.0, 0.0, 0.0]] * 10
        points = np.zeros((13, 3))
        pressed = surface(points, normals, [1.0] * 3 + [0.0] * 10, [])
        self.assertEqual(plot.view_axis(pressed), (2, -1))
        self.assertEqual(plot.surface_plane(pressed), (0, 1))
        loose = surface(points, normals, [0.0] * 13, [])
        self.assertEqual(plot.view_axis(loose), (0, 1))

    def test_faces_from_contact_vtu(self):
        points = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [2, 0, 0], [2, 1, 0],
                           [1.5, 0, 0], [2, 0.5, 0], [1.5, 0.5, 0]], float)
        u = np.tile([0.0, 0.0, -1e-3], (len(points), 1))
        contact = {name: points[:, k] for k, name in enumerate("xyz")}
        with tempfile.TemporaryDirectory() as d:
            self.assertIsNone(plot.read_contact_faces(d, contact))  # older results
            path = os.path.join(d, "contact.vtu")
            # A quadrilateral and a quadratic triangle (corners 1, 4, 5, middles 6, 7, 8).
            write_vtu(path, points, [[0, 1, 2, 3], [1, 4, 5, 6, 7, 8]], [9, 22],
                      [("displacement", "Float64", 3, u)])
            faces = plot.read_contact_faces(d, contact)
            self.assertEqual(faces["pieces"].tolist(),
                             [[0, 1, 2, 3], [1, 6, 8, 8], [6, 4, 7, 7], [8, 7, 5, 5],
                              [6, 7, 8, 8]])
            np.testing.assert_array_equal(faces["displacement"], u)
            moved = dict(contact, x=contact["x"] + 0.5)
            with self.assertRaisesRegex(plot.UsageError, "does not hold the nodes of contact.csv"):
                plot.read_contact_faces(d, moved)
            self.assertIsNone(plot.contact_faces(d, moved, warnings=False))
            write_vtu(path, points, [[0, 1]], [3], [])
            with self.assertRaisesRegex(plot.UsageError, "cells of VTK type 3 are not faces"):
                plot.read_contact_faces(d, contact)


def quarter(n=8, radius=0.6, u_x=lambda x: 1e-3 * x, clamps=(("x",), ("y",))):
    """A quarter model of a body pressed onto a plane about the origin: its bottom (0, 1)^2,
    the pressure 1 - r^2 / radius^2, held by rollers on its symmetry planes x = 0 and y = 0
    (there u_x = 0 and u_y = 0), and the summary that says so."""
    points, quads = grid(n, n)
    x, y = points[:, 0], points[:, 1]
    p = np.maximum(0.0, 1.0 - (x * x + y * y) / radius ** 2)
    u = np.stack([u_x(x), 1e-3 * y, -1e-3 + 0.0 * x], axis=1)
    contact = surface(points, np.tile([0.0, 0.0, -1.0], (len(x), 1)), p, quads, u)
    summary = {"problem": {"clamp": [{"boundary": f"{c[0]}sym", "components": list(c)}
                                     for c in clamps]}}
    return contact, summary


class SymmetryTest(unittest.TestCase):
    """The contact_pressure profile of a quarter model: its centre on the symmetry planes."""

    def centre(self, contact, summary):
        view = plot.surface_view(contact)
        planes = plot.symmetry_planes(summary, contact, view)
        a, b, p, copies = plot.mirrored(view.a[view.seen], view.b[view.seen],
                                        contact["pressure"][view.seen], planes)
        centre, _, line = plot.zone_shape(a, b, p, view.spacing)
        self.assertFalse(line)
        return planes, centre, copies

    def test_the_centre_of_a_quarter_model_lies_on_its_symmetry_planes(self):
        planes, centre, copies = self.centre(*quarter())
        self.assertEqual(planes, [(0, 0.0), (1, 0.0)])
        np.testing.assert_allclose(centre, [0.0, 0.0], atol=1e-12)
        # 81 nodes, 72 images across x = 0 (not those on it), 72 + 64 across y = 0
        self.assertEqual(np.bincount(copies).tolist(), [81, 72 + 72, 64])

    def test_without_contact_vtu_the_displacement_of_contact_csv(self):
        contact, summary = quarter()
        contact["u"] = contact["faces"]["displacement"]
        contact["faces"]["displacement"] = None
        planes, centre, _ = self.centre(contact, summary)
        self.assertEqual(planes, [(0, 0.0), (1, 0.0)])
        del contact["u"]
        self.assertEqual(self.centre(contact, summary)[0], [])  # nothing to tell them by

    def test_without_the_rollers_the_centre_is_the_parts(self):
        contact, _ = quarter()
        planes, centre, _ = self.centre(contact, {"problem": {"clamp": []}})
        self.assertEqual(planes, [])
        self.assertTrue(np.all(centre > 0.1), centre)  # the old centre, off the planes

    def test_a_plane_whose_nodes_move_is_no_symmetry_plane(self):
        planes, centre, _ = self.centre(*quarter(u_x=lambda x: 1e-3 * (x + 1.0)))
        self.assertEqual(planes, [(1, 0.0)])
        self.assertAlmostEqual(centre[1], 0.0)
        self.assertGreater(centre[0], 0.1)

    def test_the_planes_held(self):
        summary = {"problem": {
            "clamp": [{"boundary": "a", "components": ["x"]},
                      {"boundary": "b", "components": ["x", "y"]},  # not a roller
                      {"boundary": "c"}],
            "displacement": [{"boundary": "d", "z": "0"}, {"boundary": "e", "y": "0.001"},
                             {"boundary": "f", "x": "t"}]}}
        self.assertEqual(plot.held_planes(summary), [0, 2])
        self.assertEqual(plot.held_planes({}), [])


class LineContactTest(unittest.TestCase):
    def test_a_band_of_contact_is_a_line(self):
        points, quads = grid(20, 10, 1.0, 0.5)
        p = np.maximum(0.0, 1.0 - ((points[:, 0] - 0.5) / 0.08) ** 2)  # 0.1 wide, 0.5 long
        centre, direction, line = plot.zone_shape(points[:, 0], points[:, 1], p, 0.05)
        self.assertTrue(line)
        np.testing.assert_allclose(centre, [0.5, 0.25], atol=1e-12)
        self.assertEqual(direction.tolist(), [0.0, 1.0])

    def test_one_row_of_nodes_in_contact_is_a_line(self):
        # A cylinder on a coarse mesh (examples/box_on_cylinder.toml): the nodes in contact
        # on the line x = 0.5 alone, the zone's width the node spacing.
        points, _ = grid(8, 4, 1.0, 0.5)
        p = np.where(np.abs(points[:, 0] - 0.5) < 1e-9, 4.0, 0.0)
        _, direction, line = plot.zone_shape(points[:, 0], points[:, 1], p, 0.125)
        self.assertTrue(line)
        self.assertEqual(direction.tolist(), [0.0, 1.0])

    def test_a_slanting_line_keeps_its_direction(self):
        t = np.linspace(-1.0, 1.0, 41)
        a = np.concatenate([t, t + 0.05, t - 0.05])
        b = np.concatenate([t, t - 0.05, t + 0.05])
        _, direction, line = plot.zone_shape(a, b, np.ones_like(a), 0.05)
        self.assertTrue(line)
        self.assertAlmostEqual(abs(direction[0]), math.sqrt(0.5))
        self.assertAlmostEqual(abs(direction[1]), math.sqrt(0.5))

    def test_a_round_zone_is_not(self):
        contact, _ = quarter()
        a, b, p, _ = plot.mirrored(contact["x"], contact["y"], contact["pressure"],
                                   [(0, 0.0), (1, 0.0)])
        self.assertFalse(plot.zone_shape(a, b, p, 0.125)[2])
        self.assertIsNone(plot.zone_shape(a, b, 0.0 * p, 0.125))


class ResultantTest(unittest.TestCase):
    """The pressure map's title gives the force the reactions balance (resultants.contact), not
    the sum of h_j l_j."""

    @staticmethod
    def text(summary, k, unit):
        return plot.resultant_text(summary, k, unit).replace(plot.NBSP, " ")

    def test_the_resultant_not_the_sum_of_the_normal_forces(self):
        summary = {"resultants": {"contact": [0.0, 0.0, 5.0]}, "contact_force": 6.0}
        self.assertEqual(self.text(summary, 2, "N"), ", contact resultant R_z = 5 N")
        self.assertEqual(plot.contact_resultant(summary, 2), (5.0, 5.0))
        tilted = {"resultants": {"contact": [3.0, 0.0, 4.0]}, "contact_force": 6.0}
        self.assertEqual(self.text(tilted, 2, "N"), ", contact resultant R_z = 4 N (|R| = 5 N)")
        older = {"contact_force_vector": [0.0, -2.0, 0.0], "contact_force": 6.0}
        self.assertEqual(self.text(older, 1, ""), ", contact resultant R_y = -2")
        self.assertEqual(self.text({"contact_force": 6.0}, 2, "N"), ", contact force 6 N")
        # The number keeps its name and unit when the title is wrapped.
        self.assertNotIn(" ", plot.resultant_text(tilted, 2, "N")[len(", contact resultant "):]
                         .split(" (")[0])

    def test_a_load_step_has_its_own_force_only(self):
        summary = {"resultants": {"contact": [0.0, 0.0, 9.0]}, "contact_force": 9.0,
                   "contact_force_vector": [0.0, 0.0, 9.0],
                   "load_steps": [{"factor": 0.5, "contact_force": 4.0}, {"factor": 1.0}]}
        view = plot.step_view(summary, 1)
        self.assertIsNone(plot.contact_resultant(view, 2))
        self.assertEqual(self.text(view, 2, "N"), ", contact force 4 N")


def write_vtu(path, points, cells, types, arrays):
    """A .vtu as signorini writes them (raw appended data, docs/output.md): `cells` lists of
    node numbers, `types` their VTK types, `arrays` the point data (name, "Float64" or "UInt8",
    components, values)."""
    import struct

    offsets = np.cumsum([len(c) for c in cells])
    geometry = [("Points", "Float64", 3, points),
                ("connectivity", "Int64", 1, np.concatenate([np.asarray(c) for c in cells])),
                ("offsets", "Int64", 1, offsets), ("types", "UInt8", 1, np.asarray(types))]
    tags, blob, offset = {}, b"", 0
    for name, kind, components, values in arrays + geometry:
        raw = np.ascontiguousarray(values, "<f8" if kind == "Float64" else
                                   "<i8" if kind == "Int64" else "u1").tobytes()
        tags[name] = (f'<DataArray type="{kind}" Name="{name}" NumberOfComponents="{components}" '
                      f'format="appended" offset="{offset}"/>')
        blob += struct.pack("<Q", len(raw)) + raw
        offset += 8 + len(raw)
    point_data = "".join(tags[name] for name, *_ in arrays)
    header = ('<?xml version="1.0"?>\n<VTKFile type="UnstructuredGrid" version="1.0" '
              'byte_order="LittleEndian" header_type="UInt64"><UnstructuredGrid>'
              f'<Piece NumberOfPoints="{len(points)}" NumberOfCells="{len(cells)}">'
              f'<PointData>{point_data}</PointData><Points>{tags["Points"]}</Points>'
              f'<Cells>{tags["connectivity"]}{tags["offsets"]}{tags["types"]}</Cells></Piece>'
              '</UnstructuredGrid><AppendedData encoding="raw">_')
    with open(path, "wb") as f:
        f.write(header.encode() + blob + b"</AppendedData></VTKFile>\n")


def write_results(folder, gap=lambda x: 0.0 * x, units="m-MPa", normals=True, nx=12, ny=4):
    """A small set of results as signorini writes them (docs/output.md): the strip (0, 3) x (0, 1)
    lifted at its right end, resting on a foundation with the gap `gap(x)` along its bottom
    edge (where the gap is 0, it touches)."""
    import json

    xs, ys = np.meshgrid(np.linspace(0.0, 3.0, nx + 1), np.linspace(0.0, 1.0, ny + 1))
    x, y = xs.ravel(), ys.ravel()
    u = np.stack([1e-5 * y * x, 2e-5 * (x / 3.0) ** 2, 0.0 * x], axis=1)
    von_mises = 1.0 + x * (1.0 - y)
    bottom = np.flatnonzero(y == 0.0)
    g = gap(x[bottom])
    touching = g <= 0.0
    pressure = np.where(touching, 1.0, 0.0)
    n0 = (np.arange(ny)[:, None] * (nx + 1) + np.arange(nx)[None, :]).ravel()
    cells = np.stack([n0, n0 + 1, n0 + 2 + nx, n0 + 1 + nx], axis=1)
    active = np.zeros(len(x), np.uint8)
    active[bottom[touching]] = 1
    arrays = [("displacement", "Float64", 3, u), ("von_mises", "Float64", 1, von_mises),
              ("contact_active", "UInt8", 1, active)]
    write_vtu(os.path.join(folder, "solution.vtu"), np.stack([x, y, 0.0 * x], axis=1),
              [list(c) for c in cells], [9] * len(cells), arrays)
    with open(os.path.join(folder, "contact.csv"), "w") as f:
        f.write("x,y,u_n,u_t,pressure,gap" + (",n_x,n_y" if normals else "") + "\n")
        for j, node in enumerate(bottom):
            row = [x[node], 0.0, -u[node, 1], u[node, 0], pressure[j], g[j]]
            f.write(",".join(repr(float(v)) for v in row + ([0.0, -1.0] if normals else [])) + "\n")
    summary = {"converged": True, "method": "uzawa_gnm", "n_dofs": 2 * len(x),
               "message": "converged", "contact_force": float(pressure.sum()),
               "dual_changes": [1.0, 1e-3, 1e-6, 1e-9], "gnm_iterations": [5, 2, 2, 1],
               "problem": {"name": "synthetic", "units": units, "mesh": {"nx": nx, "ny": ny},
                           "solver": {"uzawa_tolerance": 1e-8}}}
    with open(os.path.join(folder, "summary.json"), "w") as f:
        json.dump(summary, f)


def have_matplotlib():
    return importlib.util.find_spec("matplotlib") is not None


@unittest.skipUnless(have_matplotlib(), "no matplotlib")
class ScriptTest(unittest.TestCase):
    """The whole script on small synthetic results, with one process and with two."""

    def run_script(self, folder, one_core=False):
        import subprocess

        return subprocess.run(
            [sys.executable, SCRIPT, "--quiet", "--format", "png,svg", folder],
            capture_output=True, text=True,
            preexec_fn=(lambda: os.sched_setaffinity(0, {min(os.sched_getaffinity(0))}))
            if one_core else None)

    @staticmethod
    def limits(svg_path):
        import re

        with open(svg_path, encoding="utf-8") as f:
            text = f.read()
        number = r"([-+0-9.eE]+|nan|inf|-inf)"
        m = re.search(f"axes: x from {number} to {number}, y from {number} to {number}", text)
        return [float(v) for v in m.groups()], text

    def test_a_curved_foundation_with_one_and_with_two_processes(self):
        for one_core in (True, False):
            with self.subTest(one_core=one_core), tempfile.TemporaryDirectory() as d:
                # A cylinder of radius 3 touching the strip at x = 1.5: gaps up to 0.4 m, 10^4
                # times the displacements.
                write_results(d, gap=lambda x: 3.0 - np.sqrt(9.0 - (x - 1.5) ** 2))
                r = self.run_script(d, one_core)
                self.assertEqual(r.returncode, 0, r.stderr)
                self.assertEqual(r.stderr, "")
                self.assertEqual(sorted(f for f in os.listdir(d) if f.endswith((".png", ".svg"))),
                                 sorted(f"{n}.{e}" for n in plot.FIGURES for e in ("png", "svg")))
                self.assertFalse([f for f in os.listdir(d) if ".tmp." in f])
                (x0, x1, y0, y1), svg = self.limits(os.path.join(d, "deformed_von_mises.svg"))
                self.assertGreater(x0, -0.2)
                self.assertLess(x1, 3.3)
                self.assertGreater(y0, -0.5)  # the foundation, 0.4 m below at the ends: cut
                self.assertLess(y1, 1.3)
                self.assertIn(">von Mises stress (MPa)</text>", svg)
                self.assertIn(">rigid foundation at its true place x + g·ν (not magnified)<", svg)
                (_, _, y0, y1), svg = self.limits(os.path.join(d, "contact_displacement.svg"))
                self.assertLess(abs(y0), 1e-3)  # the displacements, not the gap, set the axis
                self.assertLess(abs(y1), 1e-3)
                self.assertIn(">displacement (10⁻⁵ m)</text>", svg)

    def test_older_results_without_the_normal_or_the_units(self):
        with tempfile.TemporaryDirectory() as d:
            write_results(d, units=None, normals=False)
            r = self.run_script(d)
            self.assertEqual(r.returncode, 0, r.stderr)
            for name in plot.FIGURES:
                with open(os.path.join(d, name + ".svg"), encoding="utf-8") as f:
                    self.assertNotIn("MPa", f.read(), name)
            (x0, x1, y0, y1), svg = self.limits(os.path.join(d, "deformed_von_mises.svg"))
            self.assertAlmostEqual(y0, -0.12, delta=0.02)  # g = 0: the foundation at y = 0
            self.assertIn(">rigid foundation</text>", svg)

    def test_an_error_in_either_process_leaves_nothing_behind(self):
        # A missing file is found before the drawing begins; a broken one by the process that
        # draws the deformed body (either of the two), after the others have drawn their figures.
        for broken in (False, True):
            for one_core in (True, False):
                with self.subTest(broken=broken, one_core=one_core), \
                        tempfile.TemporaryDirectory() as d:
                    write_results(d)
                    vtu = os.path.join(d, "solution.vtu")
                    os.unlink(vtu)
                    if broken:
                        with open(vtu, "w") as f:
                            f.write("<VTKFile> not really")
                    with open(os.path.join(d, "convergence.png"), "w") as f:
                        f.write("an earlier figure")
                    r = self.run_script(d, one_core)
                    self.assertEqual(r.returncode, 2)
                    self.assertEqual(r.stderr.count("\n"), 1, r.stderr)
                    self.assertTrue(r.stderr.startswith(
                        f"signorini: error: cannot read '{vtu}': not a VTU file" if broken else
                        f"signorini: error: '{vtu}' not found (results of an older signorini? "
                        "run solve again)"), r.stderr)
                    self.assertEqual(sorted(os.listdir(d)),
                                     sorted(["contact.csv", "convergence.png", "summary.json"]
                                            + (["solution.vtu"] if broken else [])))
                    with open(os.path.join(d, "convergence.png")) as f:
                        self.assertEqual(f.read(), "an earlier figure")


def write_results_3d(folder, line=False):
    """Small 3D results as signorini writes them (docs/output.md): a body pressed onto a plane
    below it. The quarter model of quarter() (rollers on x = 0 and y = 0), its contact part
    with a side wall at x = 1 that does not touch; or, with `line`, a block on a roller along
    y, the pressure on a band along x = 0.5. The summary's resultant (the force the reactions
    balance) is 0.8 times its sum of h_j l_j."""
    import json

    if line:
        points, quads = grid(20, 10, 1.0, 0.5)
        p = np.maximum(0.0, 1.0 - ((points[:, 0] - 0.5) / 0.08) ** 2)
        u = np.tile([0.0, 0.0, -1e-3], (len(points), 1))
        contact = surface(points, np.tile([0.0, 0.0, -1.0], (len(points), 1)), p, quads, u)
        clamps = []
    else:
        contact, summary = quarter()
        clamps = summary["problem"]["clamp"]
        # The side wall x = 1, up to z = 0.3, free: nodes 81 on.
        foot = [8 + 9 * j for j in range(9)]
        top = list(range(81, 90))
        for name, values in (("x", 1.0), ("y", np.linspace(0.0, 1.0, 9)), ("z", 0.3)):
            contact[name] = np.concatenate([contact[name], np.broadcast_to(values, 9)])
        for name, values in (("n_x", 1.0), ("n_y", 0.0), ("n_z", 0.0), ("pressure", 0.0)):
            contact[name] = np.concatenate([contact[name], np.full(9, values)])
        wall = [[foot[j], foot[j + 1], top[j + 1], top[j]] for j in range(8)]
        faces = contact["faces"]
        faces["pieces"] = np.vstack([faces["pieces"], wall])
        faces["displacement"] = np.vstack([faces["displacement"],
                                           [[1e-3, 1e-3 * y, -1e-3] for y in contact["y"][81:]]])
    points = np.stack([contact[c] for c in "xyz"], axis=1)
    normals = np.stack([contact[f"n_{c}"] for c in "xyz"], axis=1)
    u = contact["faces"]["displacement"]
    cells = [list(r) for r in contact["faces"]["pieces"]]
    arrays = [("displacement", "Float64", 3, u), ("normal", "Float64", 3, normals),
              ("contact_pressure", "Float64", 1, contact["pressure"])]
    for name in ("contact.vtu", "solution.vtu"):  # the 3D figures never read solution.vtu
        write_vtu(os.path.join(folder, name), points, cells, [9] * len(cells), arrays)
    with open(os.path.join(folder, "contact.csv"), "w") as f:
        f.write("x,y,z,u_n,u_tx,u_ty,u_tz,pressure,gap,n_x,n_y,n_z,boundary\n")
        for k in range(len(points)):
            u_n = float(u[k] @ normals[k])
            row = list(points[k]) + [u_n] + list(u[k] - u_n * normals[k]) + \
                [contact["pressure"][k], 0.0] + list(normals[k])
            f.write(",".join(repr(float(v)) for v in row) + ",outer\n")
    force = 0.01 * float(np.sum(contact["pressure"]))
    summary = {"converged": True, "method": "uzawa_gnm", "n_dofs": 3 * len(points),
               "message": "converged", "contact_force": force,
               "resultants": {"contact": [0.0, 0.0, 0.8 * force]},
               "dual_changes": [1.0, 1e-3, 1e-6, 1e-9], "gnm_iterations": [5, 2, 2, 1],
               "problem": {"name": "synthetic", "units": "m-MPa",
                           "mesh": {"type": "gmsh", "file": "body.msh"}, "clamp": clamps,
                           "contact": {"boundary": "outer", "obstacle": "plane"},
                           "solver": {"uzawa_tolerance": 1e-8}}}
    with open(os.path.join(folder, "summary.json"), "w") as f:
        json.dump(summary, f)
    return summary


@unittest.skipUnless(have_matplotlib(), "no matplotlib")
class ThreeDimensionalScriptTest(unittest.TestCase):
    """The whole script on small synthetic 3D results: the profile of a quarter model centred
    on its symmetry planes, a line contact's across the line, the map's title with the
    resultant."""

    def run_script(self, folder):
        import subprocess

        r = subprocess.run([sys.executable, SCRIPT, "--quiet", "--format", "svg", folder],
                           capture_output=True, text=True)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(r.stderr, "")

    def test_a_quarter_model(self):
        with tempfile.TemporaryDirectory() as d:
            summary = write_results_3d(d)
            self.run_script(d)
            (x0, x1, _, _), svg = ScriptTest.limits(os.path.join(d, "contact_pressure.svg"))
            self.assertAlmostEqual(x0, -x1)  # the whole zone about its centre, (0, 0)
            # The farthest node in contact: (0.5, 0.25), r^2 = 0.3125 < 0.6^2.
            self.assertAlmostEqual(x1, 1.6 * math.sqrt(0.3125), places=5)
            self.assertIn(">x (distance from the centre of the contact zone) (m)</text>", svg)
            self.assertIn("mirrored across x = 0 and y = 0)</text>", svg)
            self.assertIn(">nodes within half a spacing of the line y = 0</text>", svg)
            (x0, x1, y0, y1), svg = ScriptTest.limits(os.path.join(d,
                                                                  "contact_pressure_map.svg"))
            nbsp = plot.NBSP
            self.assertIn(f"R_z{nbsp}={nbsp}{0.8 * summary['contact_force']:.4g}{nbsp}MN", svg)
            self.assertNotIn(f"{summary['contact_force']:.4g}", svg)
            self.assertIn("the 22 nodes in contact, of 81", svg)  # not the wall's 9 more
            self.assertLess(x0, 0.0)
            self.assertGreater(x1, 1.0)

    def test_a_line_contact(self):
        with tempfile.TemporaryDirectory() as d:
            write_results_3d(d, line=True)
            self.run_script(d)
            (x0, x1, _, _), svg = ScriptTest.limits(os.path.join(d, "contact_pressure.svg"))
            self.assertAlmostEqual(x0, -1.6 * 0.05)  # across the line, not along it
            self.assertAlmostEqual(x1, 1.6 * 0.05)
            self.assertIn(">x − 0.5 (distance from the line of contact, which runs along y) (m)"
                          "</text>", svg)
            self.assertIn(">nodes within half a spacing of the section y = 0.25 across the "
                          "line</text>", svg)


class FormatsTest(unittest.TestCase):
    def test_formats_in_the_order_given_each_once(self):
        self.assertEqual(plot.formats_of("png"), ["png"])
        self.assertEqual(plot.formats_of("SVG, png,svg,pdf"), ["svg", "png", "pdf"])

    def test_an_unknown_format_names_the_known_ones(self):
        for text in ("jpg", "png,", "png;svg", ""):
            with self.subTest(text=text), self.assertRaises(plot.UsageError) as e:
                plot.formats_of(text)
            self.assertIn(f"--format {text}: ", str(e.exception))
            self.assertIn("expected png, svg or pdf", str(e.exception))

    def test_png_chunks_and_pixels(self):
        """The PNG writer against Pillow's reader: the pixels of the canvas, the text chunks."""
        if not have_matplotlib():
            self.skipTest("no matplotlib")
        import zlib

        plot.import_plotting()
        from PIL import Image

        fig = plot.new_figure(2.0, 1.0)
        ax = fig.add_axes([0.2, 0.2, 0.7, 0.7])
        ax.plot([0, 1], [0, 1], color="tab:red")
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "f.png")
            plot.write_png(fig, path, {"Title": "f", "Description": "axes: x from 0 to 1"})
            rgba = np.asarray(fig.canvas.buffer_rgba())
            with Image.open(path) as im:
                self.assertEqual(im.mode, "RGB")
                self.assertEqual(im.size, (2 * plot.DPI, plot.DPI))
                self.assertEqual(im.text, {"Title": "f", "Description": "axes: x from 0 to 1"})
                self.assertAlmostEqual(im.info["dpi"][0], plot.DPI, places=1)
                self.assertTrue(np.array_equal(np.asarray(im), rgba[..., :3]))
            with open(path, "rb") as f:
                data = f.read()
            # Every chunk's CRC, as a strict reader checks them.
            at = 8
            while at < len(data):
                n = int.from_bytes(data[at:at + 4], "big")
                kind, body = data[at + 4:at + 8], data[at + 8:at + 8 + n]
                self.assertEqual(int.from_bytes(data[at + 8 + n:at + 12 + n], "big"),
                                 zlib.crc32(kind + body), kind)
                at += 12 + n
            self.assertEqual(at, len(data))
            self.assertEqual(kind, b"IEND")


class LegendTest(unittest.TestCase):
    """Legends kept off the curves (legend_off_the_curves), checked by sampling every curve
    densely in the figure's pixels: no sample inside the legend's box."""

    @staticmethod
    def samples_inside(legend, axes):
        box = legend.get_window_extent(legend.figure.canvas.get_renderer())
        n = 0
        for a in axes:
            for line in a.get_lines():
                if line.get_gid() == "reference":
                    continue
                xy = line.get_transform().transform(np.column_stack(line.get_data()))
                t = np.linspace(0.0, 1.0, 200)[:, None]
                for p, q in zip(xy[:-1], xy[1:]):
                    pts = p + t * (q - p)
                    n += int(np.sum((pts[:, 0] > box.x0) & (pts[:, 0] < box.x1) &
                                    (pts[:, 1] > box.y0) & (pts[:, 1] < box.y1)))
        return n

    def setUp(self):
        if not have_matplotlib():
            self.skipTest("no matplotlib")
        plot.import_plotting()

    def test_curves_everywhere_make_room_at_the_top(self):
        fig = plot.new_figure(6.0, 3.0)
        ax = fig.add_axes([0.1, 0.1, 0.8, 0.8])
        x = np.linspace(0.0, 1.0, 50)
        for k in range(11):  # level lines through every place a legend could go
            ax.plot(x, np.full_like(x, k / 10.0), label=f"curve {k}" if k < 3 else None)
        ax.axhline(0.5, color="0.6", gid="reference")
        ax.set_ylim(0.0, 1.0)
        legend = plot.legend_off_the_curves(ax, fontsize=plot.LEGEND_SIZE)
        self.assertEqual(self.samples_inside(legend, [ax]), 0)
        self.assertEqual(plot.covered_curves(legend, [ax]), [])
        self.assertGreater(ax.get_ylim()[1], 1.05)  # room made above the curves
        self.assertEqual(ax.get_ylim()[0], 0.0)

    def test_a_free_place_is_taken_as_it_is(self):
        fig = plot.new_figure(6.0, 3.0)
        ax = fig.add_axes([0.1, 0.1, 0.8, 0.8])
        x = np.linspace(0.0, 1.0, 50)
        ax.plot(x, x, label="rising")
        ax.set_ylim(0.0, 1.0)
        legend = plot.legend_off_the_curves(ax, fontsize=plot.LEGEND_SIZE)
        self.assertEqual(self.samples_inside(legend, [ax]), 0)
        self.assertEqual(ax.get_ylim(), (0.0, 1.0))

    def test_the_twin_axis_curves_count_too(self):
        # loc="best" weighs ax's curves only: the right axis's curve lies where it would go.
        fig = plot.new_figure(6.0, 3.0)
        ax = fig.add_axes([0.1, 0.1, 0.8, 0.8])
        right = ax.twinx()
        x = np.linspace(0.0, 1.0, 50)
        ax.plot(x, 0.1 * x, label="low")
        right.plot(x, np.full_like(x, 0.95), label="high, on the right axis")
        ax.set_ylim(0.0, 1.0)
        right.set_ylim(0.0, 1.0)
        best = ax.legend(loc="best", fontsize=plot.LEGEND_SIZE)
        fig.canvas.draw()
        covered_by_best = self.samples_inside(best, [ax, right])
        legend = plot.legend_off_the_curves(ax, [ax, right], fontsize=plot.LEGEND_SIZE)
        self.assertGreater(covered_by_best, 0)
        self.assertEqual(self.samples_inside(legend, [ax, right]), 0)


if __name__ == "__main__":
    unittest.main()
