#!/usr/bin/env python3
"""Draws the figures of a signorini run from its output folder (docs/output.md).

    python3 tools/plot_results.py OUTDIR [--format png,svg,pdf] [--scale S] [--steps LIST]
                                   [--quiet]
    python3 tools/plot_results.py --check [--format ...]  # numpy and matplotlib there? (0 or 2)

This module does the work; tools/plot_results.py, the command, only imports it, so that Python
can take the module compiled in advance (__pycache__, written by the build and the installation)
instead of compiling its 1,300 lines on every run.

`signorini plot OUTDIR` and `signorini solve ... --plot` run this script. It reads
OUTDIR/summary.json, contact.csv and solution.vtu (in 3D contact.vtu) and writes, as PNG (and SVG
or PDF with --format):

    contact_displacement   normal and tangential displacement along the contact boundary
    contact_pressure       the contact pressure along the contact boundary, where the body touches
    deformed_von_mises     the deformed body x + s u(x) coloured by the von Mises stress
    convergence            the Uzawa residual per iteration and GNM iterations per Uzawa step
    contact_friction       with friction (contact.csv with the columns tangential, slip, state):
                           the pressure, the tangential traction and the slip along the contact
                           boundary, the sticking and sliding zones shaded

and for a 3D problem (contact.csv with a z column):

    contact_pressure_map   the pressure over the faces of the contact surface (contact.vtu's)
                           that face the obstacle, seen along the normal where the body presses;
                           the title gives the contact resultant (summary.json's resultants)
    contact_pressure       the pressure along a line through the centre of the contact zone (on
                           the symmetry planes of a part of a body), every node at its distance
                           from the centre, and Hertz's profile where it applies (a rigid sphere,
                           or --hertz-radius R for a body of radius R); for a line contact, across
                           the line, against the distance from its axis
    convergence            as in 2D
    contact_friction_map   with friction: each node's state over the contact surface, and the
                           tangential traction as arrows

With a loading history, --steps 1,3 (or all) draws the contact figure of those steps too, from
steps/contact_NNNN.csv: contact_friction_step_NNNN (contact_pressure_step_NNNN without friction;
in 3D contact_friction_map_step_NNNN or contact_pressure_map_step_NNNN).

The unit labels come from the `units` setting (summary.json: problem.units, e.g. "m-MPa"); without
it the labels carry no units. Each file's description (PNG Description, SVG dc:description, PDF
Subject) holds the limits of its main axes, "axes: x from X0 to X1, y from Y0 to Y1", in the
units of the data. Exit status: 0 written, 2 a missing package, an unknown format or an unusable
output folder (one line on stderr), 1 anything else.

Speed matters (the PNG figures of a 480 x 160 mesh in under a second, docs/output.md): pyplot and
mathtext are never used, the axes are placed by hand (no layout engine, which draws each figure
once more), solution.vtu is mapped, not read, the mesh is one rasterised quadrilateral mesh, the
PNG files are written without Pillow, the garbage collector runs once per figure, and on a
machine with two cores or more two processes draw the figures.
"""

import argparse
import csv
import json
import math
import os
import sys
import textwrap
from collections import namedtuple

# Line styles of the contact boundaries when there are several.
STYLES = ["-", (0, (5, 2)), (0, (1, 1.5)), (0, (5, 2, 1, 2))]
FIGURES = ["contact_displacement", "contact_pressure", "deformed_von_mises", "convergence"]
FIGURES_3D = ["contact_pressure_map", "contact_pressure", "convergence"]
# The formats `--format` accepts, and the default: pictures to look at; vectors (SVG, PDF) on
# request, since each format draws every figure once more.
FORMATS = ["png", "svg", "pdf"]
DEFAULT_FORMATS = "png"
DPI = 150


class UsageError(Exception):
    """A problem the user can fix (exit status 2): a missing file, a missing package."""


def fail(status, message):
    sys.stderr.write("signorini: error: " + " ".join(str(message).split("\n")) + "\n")
    sys.exit(status)


def warn(message):
    sys.stderr.write("signorini: warning: " + " ".join(str(message).split("\n")) + "\n")


def missing_package(reason):
    return UsageError(
        f"plotting needs numpy and matplotlib for {sys.executable} ({reason}); on Debian: "
        "apt-get install python3-matplotlib"
    )


def check_plotting():
    """Whether numpy and matplotlib can be found, without importing them (which takes half a
    second): `solve --plot` asks before every solve."""
    import importlib.util

    for name in ("numpy", "matplotlib"):
        try:
            found = importlib.util.find_spec(name) is not None
        except (ImportError, ValueError) as e:
            raise missing_package(e)
        if not found:
            raise missing_package(f"No module named '{name}'")


def keep_freed_memory():
    """Memory that is freed stays with the process and serves the next figure: on a virtual
    machine a page fault on fresh memory can cost 20 microseconds, and a 150 dpi picture touches
    thousands of pages (glibc's mallopt: no mmap for large blocks, no trimming of the heap)."""
    try:
        import ctypes

        libc = ctypes.CDLL("libc.so.6")
        libc.mallopt(-3, 1 << 30)  # M_MMAP_THRESHOLD
        libc.mallopt(-1, 1 << 30)  # M_TRIM_THRESHOLD
    except (ImportError, OSError, AttributeError):
        pass  # not glibc: only slower


def import_plotting():
    # numpy's BLAS threads are of no use here and take CPU time from the drawing.
    for name in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
        os.environ.setdefault(name, "1")
    keep_freed_memory()
    # The cyclic garbage collector stays off: during the imports it would walk the young objects
    # again and again (a few percent of the import time) and while drawing it would look through
    # every figure's objects; draw_and_save collects once after each figure.
    import gc

    gc.disable()
    try:
        import numpy  # noqa: F401
        import matplotlib

        # Text in the SVG files stays text (searchable, editable), not glyph outlines.
        matplotlib.rcParams["svg.fonttype"] = "none"
        # No TeX-like math: its parser takes longer to set up than drawing all the figures, and a
        # '$' in a problem's name is printed as it is.
        matplotlib.rcParams["text.parse_math"] = False
        matplotlib.rcParams["axes.formatter.use_mathtext"] = False
        # SVG files that are the same for the same results (no date, no random ids).
        matplotlib.rcParams["svg.hashsalt"] = "signorini"
        import matplotlib.figure  # noqa: F401
        import matplotlib.backends.backend_agg  # noqa: F401
        import PIL.Image
    except ImportError as e:
        raise missing_package(e)
    if hasattr(PIL.Image.core, "set_blocks_max"):
        PIL.Image.core.set_blocks_max(64)  # Pillow, too, keeps the memory of its images
    # What is imported stays: the collections after each figure (draw_and_save) look at the
    # figure's objects only.
    gc.freeze()


# Units -------------------------------------------------------------------------------------

# The `units` setting, "{length}-{stress}" -> (length, stress and pressure, force per unit of
# thickness = stress x length). To accept another setting, add a row.
UNIT_SYSTEMS = {
    "m-Pa": ("m", "Pa", "N/m"),
    "m-kPa": ("m", "kPa", "kN/m"),
    "m-MPa": ("m", "MPa", "MN/m"),
    "m-GPa": ("m", "GPa", "GN/m"),
    "mm-MPa": ("mm", "MPa", "N/mm"),
}
# Other names of the same systems: a force unit instead of a stress unit.
UNIT_ALIASES = {
    "mm-N": "mm-MPa",  # N and mm: stresses in N/mm^2 = MPa
    "m-N": "m-Pa",  # N and m: stresses in N/m^2 = Pa
}

Units = namedtuple("Units", ["length", "stress", "force_per_thickness"])
NO_UNITS = Units("", "", "")
# The unit of a force (stress x length^2: 3D contact forces) in each system.
FORCE_UNITS = {"m-Pa": "N", "m-kPa": "kN", "m-MPa": "MN", "m-GPa": "GN", "mm-MPa": "N"}


def force_unit(summary):
    problem = summary.get("problem")
    setting = problem.get("units") if isinstance(problem, dict) else None
    return FORCE_UNITS.get(UNIT_ALIASES.get(setting, setting), "") if setting else ""


def units_of(setting):
    """The unit labels of a `units` setting; NO_UNITS (empty strings) when it is absent (None) or
    not one of UNIT_SYSTEMS and UNIT_ALIASES."""
    if not isinstance(setting, str):
        return NO_UNITS
    row = UNIT_SYSTEMS.get(UNIT_ALIASES.get(setting, setting))
    return Units(*row) if row else NO_UNITS


def units_of_summary(summary, warnings=True):
    problem = summary.get("problem")
    setting = problem.get("units") if isinstance(problem, dict) else None
    units = units_of(setting)
    if warnings and setting is not None and units == NO_UNITS:
        warn(f"units = {json.dumps(setting)} in summary.json is not one of "
             f"{', '.join(list(UNIT_SYSTEMS) + list(UNIT_ALIASES))}: the figures have no units")
    return units


SUPERSCRIPTS = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")


def power_text(k):
    """10^k in plain text: 10⁻⁵."""
    return "10" + str(k).translate(SUPERSCRIPTS)


def axis_label(quantity, unit, k=0):
    """'quantity (unit)', with the power of ten of the axis: 'quantity (10⁻⁵ m)'; without a unit
    'quantity' or 'quantity (×10⁻⁵)'."""
    if k != 0:
        return f"{quantity} ({power_text(k)} {unit})" if unit else f"{quantity} (×{power_text(k)})"
    return f"{quantity} ({unit})" if unit else quantity


def with_unit(number_text, unit):
    return f"{number_text} {unit}" if unit else number_text


# Reading the results -----------------------------------------------------------------------


def read_summary(outdir):
    path = os.path.join(outdir, "summary.json")
    try:
        with open(path, encoding="utf-8") as f:
            return json.load(f)
    except FileNotFoundError:
        raise UsageError(f"'{path}' not found: is '{outdir}' the output folder of signorini solve?")
    except (OSError, ValueError) as e:
        raise UsageError(f"cannot read '{path}': {e}")


def read_contact_csv(outdir, name="contact.csv"):
    """The columns of contact.csv (or of `name`, a step's) as arrays; the normal (n_x, n_y) is
    (0, -1), the paper's bottom edge, in the files of older versions, which did not write it."""
    import numpy as np

    path = os.path.join(outdir, name)
    try:
        with open(path, newline="", encoding="utf-8") as f:
            rows = list(csv.reader(f))
        header = [h.strip() for h in rows[0]] if rows else []
        # Every column is a number but the boundary's name (a text column of newer files) and
        # friction's node state.
        text = [k for k, h in enumerate(header) if h in ("boundary", "state")]
        boundary = [k for k, h in enumerate(header) if h == "boundary"]
        body = np.array([[0.0 if k in text else float(v) for k, v in enumerate(r)]
                         for r in rows[1:] if r], dtype=float)
        if body.size == 0:
            body = body.reshape(0, len(header))
        if body.ndim != 2 or body.shape[1] != len(header):
            raise ValueError("rows of different lengths")
        if "z" in header:  # 3D: the tangential displacement is a vector
            columns = {k: body[:, header.index(k)]
                       for k in ("x", "y", "z", "u_n", "pressure", "gap", "n_x", "n_y", "n_z")}
            tangential = np.stack([body[:, header.index(k)] for k in ("u_tx", "u_ty", "u_tz")],
                                  axis=1)
            columns["u_t"] = np.linalg.norm(tangential, axis=1)
            # The displacement u_n nu + u_t (for the symmetry planes, where contact.vtu's is
            # not there)
            normal = np.stack([columns[k] for k in ("n_x", "n_y", "n_z")], axis=1)
            columns["u"] = columns["u_n"][:, None] * normal + tangential
        else:
            columns = {k: body[:, header.index(k)]
                       for k in ("x", "y", "u_n", "u_t", "pressure", "gap")}
        # The contact boundary of each row (one name in files of one boundary or older ones).
        names = ([r[boundary[0]] for r in rows[1:] if r] if boundary else [""] * len(body))
        columns["boundary"] = names
        if "state" in header:  # friction: in 3D the tangential traction a Cartesian vector
            columns["tangential"] = (np.stack([body[:, header.index(f"tangential_{a}")]
                                               for a in "xyz"], axis=1) if "z" in header
                                     else body[:, header.index("tangential")])
            columns["slip"] = body[:, header.index("slip")]
            columns["state"] = [r[header.index("state")].strip() for r in rows[1:] if r]
        if "z" in header:
            pass  # the normal was read above
        elif "n_x" in header and "n_y" in header:
            columns["n_x"] = body[:, header.index("n_x")]
            columns["n_y"] = body[:, header.index("n_y")]
        else:
            columns["n_x"] = np.zeros(len(body))
            columns["n_y"] = -np.ones(len(body))
    except FileNotFoundError:
        raise UsageError(f"'{path}' not found: is '{outdir}' the output folder of signorini solve?")
    except (OSError, IndexError, TypeError, ValueError) as e:
        raise UsageError(f"cannot read '{path}': expected the columns x,y,u_n,u_t,pressure,gap "
                         f"(2D) or x,y,z,u_n,u_tx,u_ty,u_tz,pressure,gap,n_x,n_y,n_z (3D) ({e})")
    if len(body) == 0:
        raise UsageError(f"'{path}' has no contact nodes")
    return columns


def contact_header(outdir):
    """The column names of contact.csv, read before numpy is imported, so that the list of
    figures is known at once; none when it cannot be read (check_results and read_contact_csv
    say why)."""
    try:
        with open(os.path.join(outdir, "contact.csv"), encoding="utf-8") as f:
            return [h.strip() for h in f.readline().split(",")]
    except OSError:
        return []


def contact_friction(outdir):
    """True if contact.csv has friction's columns (a `state` column)."""
    return "state" in contact_header(outdir)


def contact_dimension(outdir):
    """3 if contact.csv has a z column (a 3D problem), else 2."""
    return 3 if "z" in contact_header(outdir) else 2


def check_results(outdir):
    """The errors that need no numpy, said before it and matplotlib are imported (half a second):
    summary.json readable, contact.csv and solution.vtu there."""
    read_summary(outdir)
    path = os.path.join(outdir, "contact.csv")
    if not os.path.exists(path):
        raise UsageError(f"'{path}' not found: is '{outdir}' the output folder of signorini solve?")
    path = os.path.join(outdir, "solution.vtu")
    if not os.path.exists(path) and not os.path.exists(os.path.join(outdir, "solution.pvtu")):
        raise UsageError(f"'{path}' not found (results of an older signorini? run solve again)")


VTK_TYPES = {"Float64": "f8", "Float32": "f4", "Int64": "i8", "Int32": "i4", "UInt64": "u8",
             "UInt32": "u4", "UInt8": "u1", "Int8": "i1"}


def read_vtu(path):
    """The points, cells and point data of a .vtu written by signorini (raw appended data, read
    with numpy: docs/output.md)."""
    import mmap
    import xml.etree.ElementTree as ET

    import numpy as np

    try:
        with open(path, "rb") as f:
            # Mapped, not read: only the pages of the arrays used are touched, in a tenth of the
            # time. (An empty file cannot be mapped.)
            empty = os.fstat(f.fileno()).st_size == 0
            raw = b"" if empty else mmap.mmap(f.fileno(), 0, access=mmap.ACCESS_READ)
    except FileNotFoundError:
        raise UsageError(f"'{path}' not found (results of an older signorini? run solve again)")
    except (OSError, ValueError) as e:
        raise UsageError(f"cannot read '{path}': {e}")
    try:
        start = raw.find(b"<AppendedData")
        if start < 0:
            raise ValueError("no <AppendedData> block")
        close = raw.find(b">", start)
        underscore = raw.find(b"_", close) if close >= 0 else -1
        if underscore < 0:
            raise ValueError("no '_' at the start of the appended data")
        data = memoryview(raw)[underscore + 1:]
        root = ET.fromstring(raw[:start].decode("utf-8") + "</VTKFile>")
        order = "<" if root.get("byte_order", "LittleEndian") == "LittleEndian" else ">"
        header = np.dtype(order + VTK_TYPES[root.get("header_type", "UInt32")])
        piece = root.find("UnstructuredGrid/Piece")
        n_points = int(piece.get("NumberOfPoints"))
        n_cells = int(piece.get("NumberOfCells"))

        def array(element, count):
            if element.get("format") != "appended":
                raise ValueError(f"array '{element.get('Name')}' is not in the appended block")
            offset = int(element.get("offset"))
            size = int(np.frombuffer(data[offset:offset + header.itemsize], header)[0])
            dtype = np.dtype(order + VTK_TYPES[element.get("type")])
            components = int(element.get("NumberOfComponents", "1"))
            begin = offset + header.itemsize
            values = np.frombuffer(data[begin:begin + size], dtype)
            if count is not None and values.size != count * components:
                raise ValueError(f"array '{element.get('Name')}' has {values.size} values, "
                                 f"expected {count * components}")
            return values.reshape(-1, components) if components > 1 else values

        points = array(piece.find("Points/DataArray"), n_points)
        cells = {e.get("Name"): e for e in piece.findall("Cells/DataArray")}
        connectivity = array(cells["connectivity"], None)
        offsets = array(cells["offsets"], n_cells)
        types = array(cells["types"], n_cells)
        point_data = {e.get("Name"): array(e, n_points) for e in piece.findall("PointData/DataArray")}
    except (ValueError, KeyError, TypeError, AttributeError, IndexError, ET.ParseError) as e:
        raise UsageError(f"cannot read '{path}': not a VTU file as signorini writes them ({e})")
    return {"points": points, "connectivity": connectivity, "offsets": offsets, "types": types,
            "point_data": point_data}


def read_solution(outdir):
    """solution.vtu, or where a run on several MPI ranks wrote it in pieces (docs/output.md), the
    pieces that solution.pvtu names put together: their points once each (a point that two
    pieces share has the same coordinates and values in both), their cells renumbered."""
    import re
    import xml.etree.ElementTree as ET

    import numpy as np

    whole = os.path.join(outdir, "solution.vtu")
    pvtu = os.path.join(outdir, "solution.pvtu")
    if os.path.exists(whole) or not os.path.exists(pvtu):
        return read_vtu(whole)
    try:
        sources = [e.get("Source") for e in ET.parse(pvtu).getroot().iter("Piece")]
    except (OSError, ET.ParseError) as e:
        raise UsageError(f"cannot read '{pvtu}': {e}")
    if not sources or any(s is None or not re.fullmatch(r"[\w.-]+", s) for s in sources):
        raise UsageError(f"cannot read '{pvtu}': expected the pieces as file names beside it")
    pieces = [read_vtu(os.path.join(outdir, s)) for s in sources]
    points = np.concatenate([p["points"] for p in pieces])
    unique, first, inverse = np.unique(points, axis=0, return_index=True, return_inverse=True)
    inverse = inverse.reshape(-1)
    start, entries, connectivity, offsets = 0, 0, [], []
    for p in pieces:
        connectivity.append(inverse[start + p["connectivity"]])
        offsets.append(p["offsets"] + entries)
        start += len(p["points"])
        entries += p["connectivity"].size
    names = pieces[0]["point_data"].keys()
    data = {name: np.concatenate([p["point_data"][name] for p in pieces])[first] for name in names}
    return {"points": unique, "connectivity": np.concatenate(connectivity),
            "offsets": np.concatenate(offsets), "types": np.concatenate([p["types"] for p in pieces]),
            "point_data": data}


# Helpers -----------------------------------------------------------------------------------


def nice_below(value):
    """The largest of 1, 2, 5 x 10^k that is <= value (value > 0)."""
    k = math.floor(math.log10(value))
    for m in (5, 2, 1):
        if m * 10 ** k <= value * (1 + 1e-12):
            return m * 10 ** k
    return 10 ** k


def magnification(points, displacement):
    """s such that the largest displacement, magnified, is about 10 % of the body's size."""
    import numpy as np

    size = float(np.max(points.max(axis=0) - points.min(axis=0)))
    largest = float(np.sqrt(np.max(np.einsum("ij,ij->i", displacement, displacement)))) \
        if len(displacement) else 0.0
    if largest <= 0.0 or size <= 0.0 or not math.isfinite(largest):
        return 1.0
    return max(1.0, nice_below(0.1 * size / largest))


def power_of_ten(values):
    """k such that values / 10^k lie roughly in (-1000, 1000), for an axis label "(10^k m)"."""
    import numpy as np

    finite = np.abs(values[np.isfinite(values)])
    largest = float(finite.max()) if finite.size else 0.0
    if largest == 0.0:
        return 0
    k = math.floor(math.log10(largest))
    return 0 if -2 <= k <= 2 else k


def padded(lo, hi, fraction=0.05):
    """[lo, hi] widened by `fraction` of its length either side (a little around 0 if empty)."""
    span = hi - lo
    if not span > 0:
        span = abs(hi) if hi != 0 else 1.0
    return lo - fraction * span, hi + fraction * span


def boundary_parts(contact):
    """[(name, rows)]: the rows of each contact boundary, in the order of contact.csv."""
    import numpy as np

    names = contact.get("boundary") or [""] * len(contact["x"])
    parts, start = [], 0
    for i in range(1, len(names) + 1):
        if i == len(names) or names[i] != names[start]:
            parts.append((names[start], np.arange(start, i)))
            start = i
    return parts


def boundary_coordinate(contact, units):
    """The abscissa of the contact-boundary plots: x or y if the boundary is straight along it,
    else the arc length from the first contact node. With several contact boundaries, the arc
    length along each, from its first node."""
    import numpy as np

    parts = boundary_parts(contact)
    x, y = contact["x"], contact["y"]
    if len(parts) > 1:
        t = np.zeros(len(x))
        for _, rows in parts:
            xs, ys = x[rows], y[rows]
            t[rows] = np.concatenate([[0.0], np.cumsum(np.hypot(np.diff(xs), np.diff(ys)))])
        return t, axis_label("arc length along each contact boundary", units.length)
    if np.ptp(y) <= 1e-9 * max(np.ptp(x), 1e-300):
        return x, axis_label("x", units.length)
    if np.ptp(x) <= 1e-9 * max(np.ptp(y), 1e-300):
        return y, axis_label("y", units.length)
    s = np.concatenate([[0.0], np.cumsum(np.hypot(np.diff(x), np.diff(y)))])
    return s, axis_label("arc length along the contact boundary", units.length)


def contact_intervals(t, active):
    """[(t_begin, t_end)] of the runs of active nodes, extended half a spacing either side so that
    a single active node still shows."""
    import numpy as np

    n = len(t)
    a = np.concatenate([[False], np.asarray(active, dtype=bool), [False]])
    starts = np.flatnonzero(a[1:] & ~a[:-1])
    ends = np.flatnonzero(~a[1:] & a[:-1]) - 1
    intervals = []
    for j, k in zip(starts, ends):
        lo = t[j] - 0.5 * (t[j] - t[j - 1]) if j > 0 else t[j]
        hi = t[k] + 0.5 * (t[k + 1] - t[k]) if k + 1 < n else t[k]
        intervals.append((float(min(lo, hi)), float(max(lo, hi))))
    return intervals


def shade_contact(ax, intervals, label=True):
    for i, (lo, hi) in enumerate(intervals):
        ax.axvspan(lo, hi, color="tab:orange", alpha=0.15, lw=0,
                   label="in contact (pressure > 0)" if label and i == 0 else None)


def wrapped(text, width_inches):
    """`text` with its lines broken to fit a figure `width_inches` wide (10 pt text)."""
    columns = max(40, int(width_inches * 12))
    return "\n".join(textwrap.fill(line, columns) for line in text.split("\n"))


def title_of(summary):
    problem = summary.get("problem", {})
    mesh = problem.get("mesh", {})
    name = problem.get("name", "problem")
    if "nz" in mesh:  # the 3D box
        text = (f"{name}: {mesh.get('nx', '?')} × {mesh.get('ny', '?')} × {mesh.get('nz', '?')} "
                f"mesh of {mesh.get('cell', 'hex8')} cells")
    elif "nx" in mesh:
        cell = mesh.get("cell", "quad4")
        text = f"{name}: {mesh.get('nx', '?')} × {mesh.get('ny', '?')} mesh"
        if cell != "quad4":
            text += f" of {cell} cells"
    elif mesh.get("type") == "box":
        text = f"{name}: a box mesh"
    elif mesh.get("type") == "given":  # arrays from a program (the Python package)
        text = f"{name}: a given mesh of {mesh.get('cells', '?')} cells"
    else:  # a mesh from a file
        text = f"{name}: {os.path.basename(str(mesh.get('file', '?')))}"
    if "n_dofs" in summary:
        text += f" ({summary['n_dofs']} unknowns)"
    text += f", {summary.get('method', '?')}"
    steps = summary.get("load_steps")
    if isinstance(steps, list) and steps:  # a loading history: the step drawn, else the last
        k = summary.get("_step", len(steps))
        factor = steps[k - 1].get("factor", 1) if isinstance(steps[k - 1], dict) else 1
        text += f", load step {k} of {len(steps)} (factor {factor:g})"
    if not summary.get("converged", True):
        text += f" — NOT CONVERGED ({summary.get('termination', '?')})"
    return text


def step_view(summary, k):
    """summary.json as for load step k (from 1) of its loading history: that step's contact
    force and convergence, and `_step` for the titles (title_of)."""
    steps = summary.get("load_steps")
    if not isinstance(steps, list) or not 1 <= k <= len(steps):
        raise UsageError(f"--steps: no load step {k} in summary.json (" +
                         (f"steps 1 to {len(steps)})" if isinstance(steps, list) and steps
                          else "no loading history)"))
    view = dict(summary)
    step = steps[k - 1]
    view["contact_force"] = step.get("contact_force")
    # The resultants are the last step's: a step's map gives its contact_force instead.
    view.pop("resultants", None)
    view.pop("contact_force_vector", None)
    view["converged"] = step.get("converged", True)
    view["termination"] = "at this step"
    view["_step"] = k
    if isinstance(summary.get("friction"), dict):  # the states: counted from the step's csv
        view["friction"] = {"law": summary["friction"].get("law", "?")}
    return view


def step_csv(k):
    """A load step's contact.csv, relative to the output folder (result_writer.cpp)."""
    return os.path.join("steps", f"contact_{k:04d}.csv")


def step_figure(name, k):
    return f"{name}_step_{k:04d}"


# Layout ------------------------------------------------------------------------------------
#
# The axes are placed by hand, from the sizes of the texts around them: a layout engine
# (constrained layout) would draw every figure once more to measure it, which takes longer than
# drawing it. Sizes are in points (1/72 inch).

BORDER = 5.0  # white around the drawing
TICK = 3.5 + 3.5  # tick length and the gap to its label
LABEL_PAD = 4.0  # between the tick labels and the axis label
TITLE_PAD = 6.0  # between an axes and its title
TEXT_SIZE = 10.0  # tick labels, axis labels, titles
LEGEND_SIZE = 8.0


def new_figure(width, height):
    """A figure with its own Agg canvas (which keeps one renderer, and the sizes of the texts it
    measured, for the PNG), without a layout engine."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    fig = Figure(figsize=(width, height))
    FigureCanvasAgg(fig)
    return fig


class Measure:
    """Sizes of texts as matplotlib draws them."""

    def __init__(self):
        from matplotlib.backends.backend_agg import RendererAgg

        self.renderer = RendererAgg(1, 1, 72)  # 72 dpi: pixels are points
        self.fonts = {}
        self.sizes = {}

    def size(self, text, size):
        """(width, height, descent) of one line."""
        key = (text, size)
        if key not in self.sizes:
            self.sizes[key] = self.renderer.get_text_width_height_descent(text, self.font(size),
                                                                          False)
        return self.sizes[key]

    def font(self, size):
        from matplotlib.font_manager import FontProperties

        if size not in self.fonts:
            self.fonts[size] = FontProperties(size=size)
        return self.fonts[size]

    def width(self, text, size=TEXT_SIZE):
        return max((self.size(line, size)[0] for line in text.split("\n") if line), default=0.0)

    def height(self, text, size=TEXT_SIZE):
        """Of a block of lines, 1.2 lines apart (matplotlib's line spacing); 0 for no text."""
        if not text:
            return 0.0
        _, h, d = self.size("lp", size)
        return (text.count("\n")) * (h - d) * 1.2 + h

    def tick_labels(self, axis):
        """The tick labels `axis` will draw with its present limits and size (the major ones,
        and the minor ones a log axis labels when it spans less than a few decades); the major
        ticks; the offset text."""
        lo, hi = sorted(axis.get_view_interval())
        slack = 1e-9 * (hi - lo)

        def within(locator):
            return [x for x in locator() if lo - slack <= x <= hi + slack]

        locs = within(axis.get_major_locator())
        formatter = axis.get_major_formatter()
        labels = [t for t in formatter.format_ticks(locs) if t]
        minor = axis.get_minor_formatter()
        if type(minor).__name__ != "NullFormatter":
            labels += [t for t in minor.format_ticks(within(axis.get_minor_locator())) if t]
        offset = formatter.get_offset() if hasattr(formatter, "get_offset") else ""
        return labels, locs, offset

    def left(self, ax):
        """Room for the y tick labels and the y label of `ax`."""
        labels, _, offset = self.tick_labels(ax.yaxis)
        room = TICK + max((self.width(t) for t in labels), default=0.0)
        if ax.get_ylabel():
            room += LABEL_PAD + self.height(ax.get_ylabel())
        return room, self.height(offset)

    def bottom(self, ax):
        """Room for the x tick labels and the x label of `ax`; and how far the last tick label
        reaches beyond the right end of the axis."""
        labels, locs, offset = self.tick_labels(ax.xaxis)
        room = TICK + (self.height("0") if labels else 0.0)
        if ax.get_xlabel():
            room += LABEL_PAD + self.height(ax.get_xlabel())
        room += self.height(offset)
        lo, hi = sorted(ax.get_xlim())
        beyond = 0.0
        if labels and locs and hi > lo and len(labels) == len(locs):
            # The label of a tick at the right end sticks out by half its width.
            if abs(locs[-1] - hi) <= 0.02 * (hi - lo):
                beyond = 0.5 * self.width(labels[-1])
        return room, beyond


def place(fig, ax, left, bottom, width, height):
    """Puts `ax` at (left, bottom), width x height, in points from the figure's lower left."""
    w, h = fig.get_size_inches() * 72.0
    ax.set_position([left / w, bottom / h, width / w, height / h])


def place_single(fig, ax, measure, title):
    """The layout of a figure with one axes and a title above it."""
    w, h = fig.get_size_inches() * 72.0
    top = BORDER + measure.height(title) + TITLE_PAD
    for _ in range(2):  # the number of ticks depends on the size of the axes
        left, offset = measure.left(ax)
        bottom, beyond = measure.bottom(ax)
        left += BORDER
        bottom += BORDER
        right = BORDER + max(beyond, 2.0)
        place(fig, ax, left, bottom, w - left - right, h - bottom - top - offset)


def place_with_right_axis(fig, ax, right, measure, title):
    """place_single for axes with a second y axis on the right (`right`, ax.twinx()): room for
    its tick labels and label too."""
    w, h = fig.get_size_inches() * 72.0
    top = BORDER + measure.height(title) + TITLE_PAD
    for _ in range(2):
        left, offset = measure.left(ax)
        room, right_offset = measure.left(right)
        bottom, _ = measure.bottom(ax)
        left += BORDER
        bottom += BORDER
        place(fig, ax, left, bottom, w - left - BORDER - room,
              h - bottom - top - max(offset, right_offset))
        right.set_position(ax.get_position())


def legend_columns(measure, labels, width, most=4):
    """(columns, rows, height) of a frameless legend of `labels` that fits `width` points."""
    em = LEGEND_SIZE
    entry = [2.0 * em + 0.8 * em + measure.width(t, LEGEND_SIZE) for t in labels]
    n = len(labels)
    for columns in range(min(most, n), 0, -1):
        rows = -(-n // columns)
        # matplotlib fills the columns one after the other, the first n % columns with one entry
        # more than the others
        sizes = [n // columns + (1 if c < n % columns else 0) for c in range(columns)]
        starts = [sum(sizes[:c]) for c in range(columns)]
        widths = [max(entry[b:b + k], default=0.0) for b, k in zip(starts, sizes)]
        total = sum(widths) + 2.0 * em * (columns - 1) + 2 * 0.4 * em
        if total <= width or columns == 1:
            break
    line = measure.height("lp", LEGEND_SIZE)
    height = 2 * 0.4 * em + rows * line + (rows - 1) * 0.5 * em
    return columns, rows, height


def covered_curves(legend, axes):
    """The labels of the curves drawn on `axes` that `legend` covers: a line whose path crosses
    the legend's box, or a marker inside it (the zero lines, gid "reference", do not count)."""
    import numpy as np

    box = legend.get_window_extent(legend.figure.canvas.get_renderer())
    covered = []
    for a in axes:
        for line in a.get_lines():
            if not line.get_visible() or line.get_gid() == "reference":
                continue
            path = line.get_transform().transform_path(line.get_path())
            v = path.vertices
            if len(v) == 0:
                continue
            inside = np.any((v[:, 0] >= box.x0) & (v[:, 0] <= box.x1) &
                            (v[:, 1] >= box.y0) & (v[:, 1] <= box.y1))
            drawn = line.get_linestyle() not in ("None", "none", "", " ")
            if inside or (drawn and len(v) > 1 and path.intersects_bbox(box, filled=False)):
                covered.append(line.get_label())
    return covered


LEGEND_PLACES = ("upper right", "upper left", "lower left", "lower right", "center right",
                 "center left", "lower center", "upper center", "center")


def legend_off_the_curves(ax, axes=None, relayout=None, **kwargs):
    """ax.legend(**kwargs) where it covers no curve of `axes` (default [ax]; every y axis of a
    figure with a twin axis, which loc="best" does not weigh): "best", else the first free one of
    matplotlib's places; where each covers a curve, the y axis grows at the top by the legend's
    height and the legend goes to the upper right, above the curves. Call it once the axes are
    placed (`relayout()` places them again after the y axis grew). Returns the legend."""
    axes = [ax] if axes is None else axes
    for loc in ("best",) + LEGEND_PLACES:
        legend = ax.legend(loc=loc, **kwargs)
        if not covered_curves(legend, axes):
            return legend
    legend = ax.legend(loc="upper right", **kwargs)
    box = legend.get_window_extent(legend.figure.canvas.get_renderer())
    frame = ax.get_window_extent()
    share = min((box.height + 6.0) / max(frame.height, 1.0), 0.6)  # of the axes' height
    for a in axes:
        lo, hi = a.get_ylim()
        if a.get_yscale() == "log" and lo > 0 and hi > 0:
            a.set_ylim(lo, lo * (hi / lo) ** (1.0 / (1.0 - share)))
        else:
            a.set_ylim(lo, lo + (hi - lo) / (1.0 - share))
    if relayout is not None:
        relayout()
    return legend


def describe_limits(ax, yscale=1.0):
    """The axis limits in the units of the data, for the files' description (tests read it)."""
    x0, x1 = ax.get_xlim()
    y0, y1 = ax.get_ylim()
    return f"axes: x from {x0:.6g} to {x1:.6g}, y from {y0 * yscale:.6g} to {y1 * yscale:.6g}"


# The figures -------------------------------------------------------------------------------
#
# Each returns (figure, description): the description goes into the files' metadata.


def figure_displacement(summary, contact, units, measure):
    import numpy as np

    t, xlabel = contact["t"], contact["t_label"]
    u_n, u_t, gap = contact["u_n"], contact["u_t"], contact["gap"]
    # The displacements set the axis; the gap, which may be many times larger (a curved
    # foundation), is drawn where it falls within reach of them.
    shown = np.concatenate([u_n, u_t, [0.0]])
    shown = shown[np.isfinite(shown)]
    lo, hi = (float(shown.min()), float(shown.max())) if shown.size else (0.0, 0.0)
    has_gap = bool(np.any(gap != 0.0))
    finite_gap = gap[np.isfinite(gap)]
    gap_clipped = False
    if has_gap and finite_gap.size:
        span = hi - lo if hi > lo else max(float(np.max(np.abs(finite_gap))), 1e-300)
        # At most one span of the displacements more on either side: the curves keep at least a
        # third of the height.
        g_lo, g_hi = float(finite_gap.min()), float(finite_gap.max())
        lo, hi = min(lo, max(g_lo, lo - span)), max(hi, min(g_hi, hi + span))
        gap_clipped = g_lo < lo or g_hi > hi
    k = power_of_ten(np.array([lo, hi]))
    scale = 10.0 ** k
    y0, y1 = padded(lo / scale, hi / scale)

    fig = new_figure(8, 4.5)
    ax = fig.add_axes([0.1, 0.1, 0.8, 0.8])
    shade_contact(ax, contact["intervals"])
    ax.axhline(0.0, color="0.6", lw=0.8, gid="reference")
    for i, (name, rows) in enumerate(contact["parts"]):
        on = f" on '{name}'" if len(contact["parts"]) > 1 else ""
        style = STYLES[i % len(STYLES)]
        ax.plot(t[rows], u_n[rows] / scale, color="tab:blue", lw=1.6, ls=style,
                label=("normal uₙ = u·ν (ν: outward normal)" if has_gap else
                       "normal uₙ = u·ν (ν outward: uₙ < 0 lifts off)") + on)
        ax.plot(t[rows], u_t[rows] / scale, color="tab:green", lw=1.6, ls=style,
                label="tangential uₜ = u·τ" + on)
        if has_gap:
            ax.plot(t[rows], gap[rows] / scale, color="k", lw=1.0,
                    ls="--" if len(contact["parts"]) == 1 else style,
                    label="gap g (the bound: uₙ ≤ g)" +
                          (", partly off the axis" if gap_clipped else "") + on)
    ax.set_xlim(*padded(float(t.min()), float(t.max()), 0.05) if len(t) > 1 else (-1, 1))
    ax.set_ylim(y0, y1)
    ax.set_xlabel(xlabel)
    ax.set_ylabel(axis_label("displacement", units.length, k))
    title = wrapped(title_of(summary) + "\nDisplacement along the contact boundar" +
                    ("ies" if len(contact["parts"]) > 1 else "y"), 8)
    ax.set_title(title, fontsize=TEXT_SIZE, y=1.0)
    ax.grid(True, alpha=0.3)
    place_single(fig, ax, measure, title)
    legend_off_the_curves(ax, relayout=lambda: place_single(fig, ax, measure, title),
                          fontsize=LEGEND_SIZE)
    return fig, describe_limits(ax, scale)


def figure_pressure(summary, contact, units, measure):
    import numpy as np

    t, xlabel = contact["t"], contact["t_label"]
    p = contact["pressure"]
    k = power_of_ten(p)  # large numbers in Pa: the power of ten goes into the axis label
    scale = 10.0 ** k
    fig = new_figure(8, 4.5)
    ax = fig.add_axes([0.1, 0.1, 0.8, 0.8])
    intervals = contact["intervals"]
    shade_contact(ax, intervals)
    for i, (name, rows) in enumerate(contact["parts"]):
        ax.plot(t[rows], p[rows] / scale, color="tab:red", lw=1.6, ls=STYLES[i % len(STYLES)],
                label="contact pressure l = −σₙ" +
                      (f" on '{name}'" if len(contact["parts"]) > 1 else ""))
    touching = p > 0
    if np.any(touching):
        ax.plot(t[touching], p[touching] / scale, "o", color="tab:red", ms=2.5,
                label=f"nodes in contact: {int(np.count_nonzero(touching))} of {len(p)}")
    ax.axhline(0.0, color="0.6", lw=0.8, gid="reference")
    ax.set_xlabel(xlabel)
    ax.set_ylabel(axis_label("contact pressure", units.stress, k))
    ax.set_xlim(*padded(float(t.min()), float(t.max()), 0.05) if len(t) > 1 else (-1, 1))
    top = max(float(np.nanmax(p)), 0.0) / scale
    bottom = min(0.0, float(np.nanmin(p)) / scale)
    ax.set_ylim(bottom - 0.02 * max(top, 1e-300), top + 0.05 * (top - bottom) if top > bottom
                else 1.0)
    where = ", ".join(with_unit(f"{lo:.3g} to {hi:.3g}", units.length) for lo, hi in intervals[:4])
    if len(intervals) > 4:
        where += ", ..."
    subtitle = "Contact pressure along the contact boundar" + \
        ("ies" if len(contact["parts"]) > 1 else "y")
    subtitle += f" (touching: {where})" if intervals else " (no contact)"
    title = wrapped(title_of(summary) + "\n" + subtitle, 8)
    ax.set_title(title, fontsize=TEXT_SIZE, y=1.0)
    force = summary.get("contact_force")
    if isinstance(force, (int, float)):
        ax.plot([], [], " ",
                label="total contact force " + with_unit(f"{force:.4g}", units.force_per_thickness))
    ax.grid(True, alpha=0.3)
    place_single(fig, ax, measure, title)
    legend_off_the_curves(ax, relayout=lambda: place_single(fig, ax, measure, title),
                          fontsize=LEGEND_SIZE)
    return fig, describe_limits(ax, scale)


def shade_states(ax, t, states):
    """The sticking and the sliding nodes' zones, each run extended half a spacing either side."""
    for state, color, text in (("sticking", "tab:green", "sticking"),
                               ("sliding", "tab:purple", "sliding")):
        for i, (lo, hi) in enumerate(contact_intervals(t, [s == state for s in states])):
            ax.axvspan(lo, hi, color=color, alpha=0.13, lw=0, label=text if i == 0 else None)


def friction_law(summary):
    """The friction law as summary.json names it."""
    friction = summary.get("friction")
    return friction.get("law", "?") if isinstance(friction, dict) else "?"


def state_counts(states):
    """'12 sticking, 20 sliding, 8 separated' for the nodes' states."""
    return ", ".join(f"{sum(1 for s in states if s == name)} {name}"
                     for name in ("sticking", "sliding", "separated"))


def figure_friction(summary, contact, units, measure):
    """2D friction: the pressure, the tangential traction (signed, along tau) and its bound where
    the node slides, and the slip on a second axis, with the stick and slip zones shaded."""
    import numpy as np

    t, xlabel = contact["t"], contact["t_label"]
    p, q, slip = contact["pressure"], contact["tangential"], contact["slip"]
    states = contact["state"]
    k = power_of_ten(np.concatenate([p, np.abs(q)]))
    scale = 10.0 ** k
    fig = new_figure(8, 4.5)
    ax = fig.add_axes([0.1, 0.1, 0.75, 0.8])
    shade_states(ax, t, states)
    for i, (name, rows) in enumerate(contact["parts"]):
        on = f" on '{name}'" if len(contact["parts"]) > 1 else ""
        style = STYLES[i % len(STYLES)]
        ax.plot(t[rows], p[rows] / scale, color="tab:red", lw=2.6, ls=style,
                label="contact pressure" + on if i == 0 or on else None)
        ax.plot(t[rows], q[rows] / scale, color="tab:blue", lw=1.4, ls=style,
                label="tangential traction (along the slip where sliding)" + on
                if i == 0 or on else None)
    ax.axhline(0.0, color="0.6", lw=0.8, gid="reference")
    ax.set_xlabel(xlabel)
    ax.set_ylabel(axis_label("traction", units.stress, k))
    ax.set_xlim(*padded(float(t.min()), float(t.max()), 0.05) if len(t) > 1 else (-1, 1))
    # A small contact zone on a long boundary: zoomed onto it, with as much again either side.
    touching = np.array([s != "separated" for s in states], dtype=bool)
    zoomed = False
    if np.any(touching) and len(t) > 1:
        lo, hi = float(t[touching].min()), float(t[touching].max())
        if hi - lo < 0.4 * (float(t.max()) - float(t.min())):
            pad = max(hi - lo, 1e-12 * max(abs(lo), abs(hi), 1.0))
            ax.set_xlim(lo - pad, hi + pad)
            zoomed = True
    right = ax.twinx()
    # The slip where the node touches (a separated node moves freely: no slip to speak of).
    slip = np.where(touching, slip, np.nan)
    ks = power_of_ten(slip[touching]) if np.any(touching) else 0
    right.plot(t, slip / 10.0 ** ks, color="black", lw=1.0, ls=(0, (4, 2)),
               label="slip (accumulated) where touching")
    right.set_ylabel(axis_label("slip", units.length, ks))
    top = float(np.nanmax(slip)) / 10.0 ** ks if np.any(touching) else 1.0
    right.set_ylim(bottom=0.0, top=max(top, 1e-300) * 1.1)
    subtitle = f"Friction ({friction_law(summary)}) along the contact boundary: " + \
        state_counts(states) + (" (zoomed onto the contact zone)" if zoomed else "")
    title = wrapped(title_of(summary) + "\n" + subtitle, 8)
    ax.set_title(title, fontsize=TEXT_SIZE, y=1.0)
    ax.grid(True, alpha=0.3)
    handles, labels = ax.get_legend_handles_labels()
    more, more_labels = right.get_legend_handles_labels()
    place_with_right_axis(fig, ax, right, measure, title)
    legend_off_the_curves(ax, [ax, right],
                          lambda: place_with_right_axis(fig, ax, right, measure, title),
                          handles=handles + more, labels=labels + more_labels,
                          fontsize=LEGEND_SIZE)
    return fig, describe_limits(ax, scale)


def structured_grid(vtu):
    """(ny + 1, nx + 1) if the cells are the quadrilaterals of a rectangle mesh numbered row by
    row (node i + j (nx + 1), as signorini numbers them), else None."""
    import numpy as np

    conn, types = vtu["connectivity"], vtu["types"]
    n_points = len(vtu["points"])
    if len(types) == 0 or not np.all(types == 9) or conn.size != 4 * len(types):
        return None
    q = conn.reshape(-1, 4)
    nxp = int(q[0, 3])
    if nxp < 2 or n_points % nxp != 0:
        return None
    nyp = n_points // nxp
    if nyp < 2 or (nxp - 1) * (nyp - 1) != len(q):
        return None
    n0 = (np.arange(nyp - 1)[:, None] * nxp + np.arange(nxp - 1)[None, :]).ravel()
    expected = np.stack([n0, n0 + 1, n0 + 1 + nxp, n0 + nxp], axis=1)
    return (nyp, nxp) if np.array_equal(q, expected) else None


def cells_and_outline(vtu):
    """The cells as polygons of point numbers (an (n, k) array for one kind of cell, else a list)
    and the outline: the boundary edges joined into polylines."""
    import numpy as np

    conn, offsets, types = vtu["connectivity"], vtu["offsets"], vtu["types"]
    # VTK cell type -> (points per cell, the points around its boundary in order): quadratic
    # cells are drawn as polygons through their corner and mid-edge nodes, so that curved edges
    # stay curved (a biquadratic quadrilateral's centre node is not drawn).
    polygon = {5: (3, [0, 1, 2]), 9: (4, [0, 1, 2, 3]), 22: (6, [0, 3, 1, 4, 2, 5]),
               23: (8, [0, 4, 1, 5, 2, 6, 3, 7]), 28: (9, [0, 4, 1, 5, 2, 6, 3, 7])}
    kinds = set(int(t) for t in np.unique(types)) if len(types) else set()
    if len(kinds) == 1 and next(iter(kinds)) in polygon and \
            conn.size == polygon[next(iter(kinds))][0] * len(types):
        count, order = polygon[next(iter(kinds))]
        cells = conn.reshape(-1, count)[:, order]
    else:
        begins = np.concatenate([[0], offsets[:-1]])
        cells = [conn[b:e][polygon[int(kind)][1]] for b, e, kind in zip(begins, offsets, types)
                 if int(kind) in polygon]
        if not cells:
            raise UsageError("solution.vtu has no triangles or quadrilaterals to draw")
    if isinstance(cells, list):
        edges = np.array([[c[i], c[(i + 1) % len(c)]] for c in cells for i in range(len(c))])
    else:
        edges = np.stack([cells, np.roll(cells, -1, axis=1)], axis=2).reshape(-1, 2)
    # An edge of one cell only is on the boundary.
    a = np.minimum(edges[:, 0], edges[:, 1]).astype(np.int64)
    b = np.maximum(edges[:, 0], edges[:, 1]).astype(np.int64)
    _, index, count = np.unique(a * (int(b.max()) + 1) + b, return_index=True, return_counts=True)
    return cells, chains_of(edges[index[count == 1]])


def chains_of(edges):
    """The boundary edges joined into polylines (lists of point numbers), so that a dashed line
    is dashed along the whole outline and not restarted at every edge."""
    neighbours = {}
    for a, b in edges:
        neighbours.setdefault(int(a), []).append(int(b))
        neighbours.setdefault(int(b), []).append(int(a))
    used = set()
    chains = []
    # Open chains start at nodes of odd degree; what is left are closed loops.
    starts = [n for n, nb in neighbours.items() if len(nb) % 2 == 1] + list(neighbours)
    for start in starts:
        node = start
        chain = [node]
        while True:
            step = next((m for m in neighbours[node] if (min(node, m), max(node, m)) not in used),
                        None)
            if step is None:
                break
            used.add((min(node, step), max(node, step)))
            chain.append(step)
            node = step
        if len(chain) > 1:
            chains.append(chain)
    return chains


def draw_body(ax, vtu, deformed, values, clim, cell_pixels):
    """The deformed body coloured by `values`, rasterised (in the SVG too: 10^5 shaded cells as
    vectors would make a file of 100 MB); returns the colour mapping and the outline (chains of
    point numbers). Cells of more than a few pixels are shaded smoothly between the nodes
    (Gouraud); smaller ones get the mean of their nodes, which looks the same and is drawn many
    times faster."""
    import numpy as np
    from matplotlib.collections import PolyCollection

    smooth = cell_pixels >= 3.5
    grid = structured_grid(vtu)
    if grid is not None:
        nyp, nxp = grid
        X = deformed[:, 0].reshape(nyp, nxp)
        Y = deformed[:, 1].reshape(nyp, nxp)
        C = values.reshape(nyp, nxp)
        if not smooth:
            C = 0.25 * (C[:-1, :-1] + C[:-1, 1:] + C[1:, :-1] + C[1:, 1:])
        image = ax.pcolormesh(X, Y, C, shading="gouraud" if smooth else "flat", cmap="viridis",
                              vmin=clim[0], vmax=clim[1], rasterized=True, antialiased=False)
        ring = np.concatenate([np.arange(nxp),                                     # bottom
                               np.arange(2 * nxp - 1, nyp * nxp, nxp),             # right
                               np.arange(nyp * nxp - 2, (nyp - 1) * nxp - 1, -1),  # top
                               np.arange((nyp - 2) * nxp, -1, -nxp)])              # left
        return image, [ring]
    cells, outline = cells_and_outline(vtu)
    if smooth or isinstance(cells, list):
        from matplotlib.tri import Triangulation

        if isinstance(cells, list):
            tri = np.array([[c[0], c[i], c[i + 1]] for c in cells for i in range(1, len(c) - 1)])
        else:
            tri = np.concatenate([cells[:, [0, i, i + 1]] for i in range(1, cells.shape[1] - 1)])
        mesh = Triangulation(deformed[:, 0], deformed[:, 1], tri)
        image = ax.tripcolor(mesh, values, shading="gouraud" if smooth else "flat",
                             cmap="viridis", vmin=clim[0], vmax=clim[1], rasterized=True)
    else:
        image = PolyCollection(deformed[cells], array=values[cells].mean(axis=1), cmap="viridis",
                               edgecolors="none", antialiased=False, rasterized=True)
        image.set_clim(*clim)
        ax.add_collection(image, autolim=False)
    return image, outline


def figure_deformed(summary, vtu, contact, scale, units, measure):
    import numpy as np
    from matplotlib.collections import LineCollection

    points = vtu["points"][:, :2]
    data = vtu["point_data"]
    for name in ("displacement", "von_mises"):
        if name not in data:
            raise UsageError(f"solution.vtu has no point data '{name}'")
    u = data["displacement"][:, :2]
    vm = np.asarray(data["von_mises"], dtype=float)
    s = magnification(points, u) if scale is None else scale
    deformed = points + s * u

    # The rigid foundation at its true place, x_j + g_j nu_j: the displacement is magnified s
    # times, the foundation is not (with a curved foundation it would be thousands of body sizes
    # away). Where the gap is not 0, the dashed line x_j + s g_j nu_j is where the magnified body
    # meets the foundation: the nodes in contact lie on it.
    normal = np.stack([contact["n_x"], contact["n_y"]], axis=1)
    base = np.stack([contact["x"], contact["y"]], axis=1)
    gap = contact["gap"]
    foundation = base + gap[:, None] * normal
    magnified = base + s * gap[:, None] * normal
    has_gap = bool(np.any(gap != 0.0))

    # The drawing: the body, undeformed and deformed, and the foundation near it (at most 10 % of
    # the body's size beyond the body).
    extent = points.max(axis=0) - points.min(axis=0)
    size = float(max(extent)) if float(max(extent)) > 0 else 1.0
    lo = np.minimum(points.min(axis=0), deformed.min(axis=0))
    hi = np.maximum(points.max(axis=0), deformed.max(axis=0))
    finite = foundation[np.all(np.isfinite(foundation), axis=1)]
    if len(finite):
        reach = 0.1 * size
        lo, hi = (np.minimum(lo, np.maximum(finite.min(axis=0), lo - reach)),
                  np.maximum(hi, np.minimum(finite.max(axis=0), hi + reach)))
    lo, hi = lo - 0.04 * size, hi + 0.04 * size
    inside = np.all((finite >= lo) & (finite <= hi), axis=1) if len(finite) else np.zeros(0, bool)

    # The axes take the shape of the drawing, at most 7.5 x 6.5 inches.
    aspect = float((hi[1] - lo[1]) / (hi[0] - lo[0]))
    axes_w = min(7.5, 6.5 / aspect) * 72.0
    axes_h = axes_w * aspect

    # A stress singularity (a corner where a clamp meets a load) can exceed the rest of the body
    # many times over at one node; the colour scale then ends at the 99.9th percentile, so that
    # the body is not drawn in one colour, and the colour bar says so.
    top = float(np.nanmax(vm))
    clip = float(np.nanpercentile(vm, 99.9))
    clipped = top > 1.1 * clip
    k = power_of_ten(np.array([top]))
    vm_scale = 10.0 ** k
    clim = (float(np.nanmin(vm)) / vm_scale, (clip if clipped else top) / vm_scale)
    n_cells = max(len(vtu["types"]), 1)
    cell_pixels = (axes_w / 72.0 * DPI * math.sqrt(extent[0] * extent[1] / n_cells)
                   / (hi[0] - lo[0])) if extent[0] > 0 and extent[1] > 0 else 0.0

    # The axes at their final size first (the ticks depend on it), their place comes later.
    bar_gap, bar_w = 0.2 * 72, max(9.0, 0.9 * axes_h / 20)
    fig = new_figure((axes_w + 200) / 72, (axes_h + 200) / 72)
    ax = fig.add_axes([0, 0, 1, 1])
    cax = fig.add_axes([0, 0, 1, 1])
    place(fig, ax, 50, 50, axes_w, axes_h)
    place(fig, cax, 60 + axes_w, 50, bar_w, 0.9 * axes_h)
    image, outline = draw_body(ax, vtu, deformed, vm / vm_scale, clim, cell_pixels)
    ax.add_collection(LineCollection([points[c] for c in outline], colors="0.3",
                                     linewidths=0.9, linestyles=(0, (4, 3)),
                                     label="undeformed body"), autolim=False)
    ax.add_collection(LineCollection([deformed[c] for c in outline], colors="k",
                                     linewidths=0.6), autolim=False)
    # A rigid plane or disc (contact.obstacle) is drawn as it is, across the drawing; a gap
    # formula as the points x + g nu of the contact nodes.
    obstacles = summary.get("problem", {}).get("contact", {})
    obstacles = obstacles if isinstance(obstacles, list) else [obstacles]
    shapes = [o.get("obstacle", "gap") for o in obstacles]
    # The magnified body may reach into a plane or disc that the true one only touches: the
    # legend says so where it does (deeper than 0.1 % of the body's size), so that the overlap
    # is not read as penetration.
    def crossing(depth):
        return bool(s != 1.0 and np.nanmax(depth) > 1e-3 * size)

    magnified_note = f" (the body, its displacement magnified {s:g} times, crosses it)"
    for i, obstacle in enumerate(obstacles):
        shape = shapes[i]
        first = i == shapes.index(shape)  # one legend entry per kind
        if shape == "plane":
            p, n = np.array(obstacle["point"], float), np.array(obstacle["normal"], float)
            t = np.array([n[1], -n[0]]) / np.hypot(*n)
            reach = 2.0 * float(np.hypot(*(hi - lo)))
            line = np.array([p - reach * t, p + reach * t])
            depth = -((deformed - p[:2]) @ (n[:2] / np.hypot(*n[:2])))
            label = "rigid plane (not moved)" + (magnified_note if crossing(depth) else "")
            ax.plot(line[:, 0], line[:, 1], color="tab:brown", lw=3, alpha=0.8,
                    solid_capstyle="butt", label=label if first else None, zorder=0)
        elif shape == "disc":
            c, r = np.array(obstacle["centre"], float), float(obstacle["radius"])
            a = np.linspace(0.0, 2.0 * np.pi, 721)
            distance = np.hypot(*(deformed - c[:2]).T)
            depth = distance - r if obstacle.get("inside", False) else r - distance
            label = "rigid disc (not moved)" + (magnified_note if crossing(depth) else "")
            ax.plot(c[0] + r * np.cos(a), c[1] + r * np.sin(a), color="tab:brown", lw=3,
                    alpha=0.8, label=label if first else None, zorder=0)
        else:
            if not has_gap:
                label = "rigid foundation"
            elif np.any(inside):
                label = "rigid foundation at its true place x + g·ν (not magnified)"
            else:
                label = ("rigid foundation: outside the drawing (gap " +
                         with_unit(f"{np.nanmin(gap):.3g} to {np.nanmax(gap):.3g}", units.length) +
                         ")")
            parts = contact["parts"]
            rows = parts[i][1] if len(parts) == len(obstacles) else slice(None)
            ax.plot(foundation[rows, 0], foundation[rows, 1], color="tab:brown", lw=3, alpha=0.8,
                    solid_capstyle="butt", label=label if first else None, zorder=0)
    shape = "gap" if "gap" in shapes else shapes[0]
    # Only where the two lines can be told apart.
    if shape == "gap" and len(obstacles) == 1 and has_gap and s != 1.0 and \
            np.nanmax(np.abs((s - 1.0) * gap)) > 0.005 * size:
        ax.plot(magnified[:, 0], magnified[:, 1], color="tab:brown", lw=1.2, ls=(0, (5, 2)),
                label=f"foundation with the gap magnified {s:g} times: where the magnified "
                      "body touches it", zorder=2.5)
    active = data.get("contact_active")
    if active is not None and np.any(active):
        ax.plot(deformed[active == 1, 0], deformed[active == 1, 1], "o", ms=1.8,
                color="tab:orange", label="nodes in contact", zorder=3)
    if clipped:
        at = int(np.nanargmax(vm))
        ax.plot(deformed[at, 0], deformed[at, 1], "x", color="tab:red", ms=8, mew=2, zorder=4,
                label=f"max {with_unit(f'{top:.3g}', units.stress)} at "
                      f"({points[at, 0]:.3g}, {points[at, 1]:.3g}), above the colour scale")
    ax.set_aspect("equal")
    ax.set_xlim(lo[0], hi[0])
    ax.set_ylim(lo[1], hi[1])
    ax.set_xlabel(axis_label("x", units.length))
    ax.set_ylabel(axis_label("y", units.length))
    bar = fig.colorbar(image, cax=cax, extend="max" if clipped else "neither")
    bar.set_label(axis_label("von Mises stress", units.stress, k))
    bar.solids.set_rasterized(False)  # 256 rectangles: as vectors, one raster less in the SVG

    # The figure around the axes: the y labels on the left, the colour bar on the right, the
    # legend and the title above.
    left, _ = measure.left(ax)
    bottom, beyond = measure.bottom(ax)
    left += BORDER
    bottom += BORDER
    bar_gap = max(bar_gap, beyond + 4.0)
    bar_labels, _, _ = measure.tick_labels(cax.yaxis)
    right = (bar_gap + bar_w + TICK + max((measure.width(t) for t in bar_labels), default=0.0)
             + LABEL_PAD + measure.height(bar.ax.get_ylabel()) + BORDER)
    width = max(8.0 * 72, left + axes_w + right)
    shift = 0.5 * (width - (left + axes_w + right))  # a narrow body: centred
    title = wrapped(title_of(summary) +
                    f"\nDeformed body x + s·u(x), displacements magnified s = {s:g} times" +
                    (" (the foundation is not)" if has_gap and s != 1.0 else "") +
                    ", coloured by the von Mises stress", width / 72)
    labels = ax.get_legend_handles_labels()[1]
    columns, _, legend_h = legend_columns(measure, labels, width - 2 * BORDER)
    top_room = BORDER + measure.height(title) + 4.0 + legend_h + 0.5 * LEGEND_SIZE
    height = bottom + axes_h + top_room
    fig.set_size_inches(width / 72, height / 72)
    place(fig, ax, left + shift, bottom, axes_w, axes_h)
    place(fig, cax, left + shift + axes_w + bar_gap, bottom + 0.05 * axes_h, bar_w, 0.9 * axes_h)
    fig.suptitle(title, fontsize=TEXT_SIZE, y=1.0 - BORDER / height, va="top")
    # Above the drawing, where it cannot hide a part of the body, centred like the title.
    ax.legend(fontsize=LEGEND_SIZE, loc="lower center", frameon=False, ncol=columns,
              bbox_to_anchor=(0.5, (bottom + axes_h) / height), bbox_transform=fig.transFigure)
    return fig, describe_limits(ax)


def log_formatter(minor):
    """Labels of a log axis as 10⁻⁸ and 2×10⁻⁸, in plain text (no mathtext)."""
    from matplotlib.ticker import LogFormatter

    class PlainPowerFormatter(LogFormatter):
        def _num_to_string(self, x, vmin, vmax):
            e = math.floor(math.log10(x) + 1e-9)
            m = x / 10.0 ** e
            m_text = f"{round(m)}" if abs(m - round(m)) < 1e-6 else f"{m:.2g}"
            return power_text(e) if m_text == "1" else f"{m_text}×{power_text(e)}"

    if minor:
        return PlainPowerFormatter(labelOnlyBase=False, minor_thresholds=(2, 0.5))
    return PlainPowerFormatter(labelOnlyBase=True)


def figure_convergence(summary, measure):
    import numpy as np
    from matplotlib.ticker import MaxNLocator

    method = summary.get("method", "uzawa_gnm")
    changes = np.array([np.nan if v is None else v for v in summary.get("dual_changes", [])],
                       dtype=float)
    steps = np.arange(1, len(changes) + 1)
    fig = new_figure(11, 4.2)
    left = fig.add_axes([0.1, 0.1, 0.35, 0.7])
    right = fig.add_axes([0.6, 0.1, 0.35, 0.7])
    outer = "Newton iteration" if method == "semismooth_newton" else "Uzawa iteration k"

    left.set_yscale("log")
    left.yaxis.set_major_formatter(log_formatter(False))
    left.yaxis.set_minor_formatter(log_formatter(True))
    shown = np.isfinite(changes) & (changes > 0)
    if np.any(shown):
        left.plot(steps[shown], changes[shown], "o-", color="tab:blue", ms=4,
                  label="‖lᵏ − lᵏ⁻¹‖ / ‖lᵏ‖")
    tol = summary.get("problem", {}).get("solver", {}).get("uzawa_tolerance")
    if method != "semismooth_newton" and isinstance(tol, (int, float)) and tol > 0:
        left.axhline(tol, color="tab:red", ls="--", lw=1, label=f"tolerance {tol:g}")
    left.set_xlabel(outer)
    left.set_ylabel("relative change of the contact pressure")
    left_title = ("Uzawa residual" if method != "semismooth_newton" else
                  "Change of the contact pressure (the method stops\nwhen the active set repeats)")
    left.set_title(left_title, fontsize=TEXT_SIZE, y=1.0)
    left.grid(True, which="both", alpha=0.3)
    if len(steps) <= 30:
        left.set_xticks(steps)

    if method == "uzawa_gnm":
        gnm = np.array(summary.get("gnm_iterations", []), dtype=float)
        bars = right.bar(np.arange(1, len(gnm) + 1), gnm, color="tab:green")
        if len(gnm) <= 40:
            right.bar_label(bars, fmt="%d", fontsize=LEGEND_SIZE)
            right.set_xticks(np.arange(1, len(gnm) + 1))
        right.set_ylabel("GNM iterations")
        right_title = "Generalised Newton iterations per Uzawa step"
        right.set_ylim(0, max(gnm.max() if len(gnm) else 1, 1) * 1.15)
    else:
        active = np.array(summary.get("active_set_sizes", []), dtype=float)
        right.plot(np.arange(1, len(active) + 1), active, "o-" if len(active) <= 50 else "-",
                   color="tab:green", ms=4)
        right.set_ylabel("nodes in the active set")
        right_title = "Active set size per iteration"
        right.yaxis.set_major_locator(MaxNLocator(integer=True))
    right.set_title(right_title, fontsize=TEXT_SIZE, y=1.0)
    right.set_xlabel(outer)
    right.grid(True, axis="y", alpha=0.3)
    title = wrapped(title_of(summary) + f"\nConvergence: {summary.get('message', '')}", 11)
    fig.suptitle(title, fontsize=TEXT_SIZE, y=1.0 - BORDER / (4.2 * 72), va="top")

    w, h = 11 * 72.0, 4.2 * 72.0
    top = (BORDER + measure.height(title) + 8.0
           + max(measure.height(left_title), measure.height(right_title)) + TITLE_PAD)

    def layout():
        for _ in range(2):  # the number of ticks depends on the size of the axes
            l1, o1 = measure.left(left)
            l2, o2 = measure.left(right)
            b1, _ = measure.bottom(left)
            b2, beyond = measure.bottom(right)
            bottom = BORDER + max(b1, b2)
            gap = 24.0 + l2
            width = (w - BORDER - l1 - gap - BORDER - max(beyond, 2.0)) / 2
            place(fig, left, BORDER + l1, bottom, width, h - bottom - top - o1)
            place(fig, right, BORDER + l1 + width + gap, bottom, width, h - bottom - top - o2)

    layout()
    if left.get_legend_handles_labels()[0]:
        legend_off_the_curves(left, relayout=layout, fontsize=LEGEND_SIZE)
    return fig, describe_limits(left)


# 3D: the contact surface -------------------------------------------------------------------

AXIS_NAMES = "xyz"
NBSP = "\u00a0"  # a space that textwrap does not break

# The linear pieces of contact.vtu's faces (VTK cell type: the pieces as positions in the cell's
# node list, counterclockwise as the face). A quadratic face is drawn as the pieces between its
# corner and middle nodes, so that the middle nodes' pressures show as well.
FACE_PIECES = {
    5: [(0, 1, 2)],  # VTK_TRIANGLE
    9: [(0, 1, 2, 3)],  # VTK_QUAD
    22: [(0, 3, 5), (3, 1, 4), (5, 4, 2), (3, 4, 5)],  # VTK_QUADRATIC_TRIANGLE
    23: [(0, 4, 7), (4, 1, 5), (5, 2, 6), (6, 3, 7), (4, 5, 6, 7)],  # VTK_QUADRATIC_QUAD
    28: [(0, 4, 8, 7), (4, 1, 5, 8), (8, 5, 2, 6), (7, 8, 6, 3)],  # VTK_BIQUADRATIC_QUAD
}

SurfaceView = namedtuple("SurfaceView", "i j k side a b seen pieces spacing")
SurfaceView.__doc__ = """The contact surface as the 3D figures show it: seen along axis k from
the side `side` (+1: from k = +infinity, -1: from -infinity, 0: no side), (i, j) the other two
axes and (a, b) every node's coordinates along them; `seen` marks the nodes of the faces drawn,
`pieces` those faces as rows of four node numbers (a triangle's last repeated), the farthest
first (None where contact.vtu gave no faces: then every node is seen), `spacing` a typical
distance between neighbouring nodes in the plane (i, j)."""


def read_contact_faces(outdir, contact):
    """contact.vtu's faces cut into linear pieces (FACE_PIECES), as rows of four numbers of
    contact.csv's nodes (a triangle's last repeated), with the nodes' displacement: {"pieces",
    "displacement"}. contact.vtu holds the contact nodes in contact.csv's order; None where it
    is missing (results of an older signorini), unreadable, or not of these nodes (raises
    UsageError then, for the caller to say)."""
    import numpy as np

    path = os.path.join(outdir, "contact.vtu")
    if not os.path.exists(path):
        return None
    vtu = read_vtu(path)
    points = np.asarray(vtu["points"], dtype=float)
    nodes = np.stack([contact[name] for name in AXIS_NAMES], axis=1)
    size = float(np.max(np.ptp(nodes, axis=0))) if len(nodes) else 0.0
    if points.shape != nodes.shape or not np.allclose(points, nodes, rtol=0.0,
                                                      atol=1e-9 * max(size, 1e-300)):
        raise UsageError(f"'{path}' does not hold the nodes of contact.csv")
    offsets = np.asarray(vtu["offsets"], dtype=np.int64)
    starts = np.concatenate([[0], offsets[:-1]])
    connectivity = np.asarray(vtu["connectivity"], dtype=np.int64)
    types = np.asarray(vtu["types"])
    pieces = []
    for kind in np.unique(types):
        if int(kind) not in FACE_PIECES:
            raise UsageError(f"'{path}': cells of VTK type {int(kind)} are not faces")
        cells = np.flatnonzero(types == kind)
        for piece in FACE_PIECES[int(kind)]:
            columns = list(piece) + [piece[-1]] * (4 - len(piece))
            pieces.append(connectivity[starts[cells][:, None] + np.array(columns)[None, :]])
    pieces = np.concatenate(pieces) if pieces else np.zeros((0, 4), np.int64)
    if pieces.size and (pieces.min() < 0 or pieces.max() >= len(nodes)):
        raise UsageError(f"'{path}': a face names a node that is not there")
    displacement = vtu["point_data"].get("displacement")
    if displacement is not None and np.shape(displacement) != nodes.shape:
        displacement = None
    return {"pieces": pieces, "displacement": displacement}


def contact_faces(outdir, contact, warnings=True):
    """read_contact_faces, or None with a warning where contact.vtu cannot serve (the figures
    then triangulate the nodes, as for results without it)."""
    try:
        return read_contact_faces(outdir, contact)
    except UsageError as e:
        if warnings:
            warn(f"{e}; the contact surface is drawn from contact.csv's nodes alone")
        return None


def view_axis(contact):
    """(k, side): the axis the contact surface is seen along and from which side. The axis
    closest to the outward normal where the body presses (the normals weighted by the pressure,
    which leaves out the side walls of a contact part that do not touch), or, without contact,
    to the mean normal; seen from the side it faces, the obstacle's (a box face from below, a
    sphere's cap from outside)."""
    import numpy as np

    normals = np.stack([contact["n_x"], contact["n_y"], contact["n_z"]], axis=1)
    p = np.maximum(contact["pressure"], 0.0)
    n = (p @ normals) / np.sum(p) if np.any(p > 0) else np.mean(normals, axis=0)
    if not np.any(n != 0):
        return 2, 0
    k = int(np.argmax(np.abs(n)))
    # A surface pressed all round (a body inside a ring) faces no side: its faces are all drawn.
    typical = float(np.mean(np.linalg.norm(normals, axis=1)))
    return k, (0 if abs(n[k]) < 0.05 * typical else int(np.sign(n[k])))


def facing_pieces(contact, pieces, k, side):
    """The pieces that face the viewer on the side `side` of axis k (their outward normal, which
    the nodes' normals orient, within about 87 degrees of the direction towards him), the
    farthest first: the faces of the contact surface that press on the obstacle, without the
    side walls (seen edge on, their nodes would fall on the patch) and the faces turned away."""
    import numpy as np

    if side == 0 or len(pieces) == 0:
        return pieces
    points = np.stack([contact[name] for name in AXIS_NAMES], axis=1)
    normals = np.stack([contact["n_x"], contact["n_y"], contact["n_z"]], axis=1)
    corners = points[pieces]
    # The cross product of the diagonals: twice the area along the normal (a triangle's too,
    # its last corner repeated).
    normal = np.cross(corners[:, 2] - corners[:, 0], corners[:, 3] - corners[:, 1])
    outward = np.einsum("fd,fd->f", normal, normals[pieces].sum(axis=1))
    normal *= np.where(outward < 0, -1.0, 1.0)[:, None]
    length = np.linalg.norm(normal, axis=1)
    facing = side * normal[:, k] > 0.05 * length
    kept = pieces[facing & (length > 0)]
    depth = side * points[kept].mean(axis=1)[:, k]
    return kept[np.argsort(depth, kind="stable")]


def surface_view(contact):
    """The SurfaceView of `contact` (its faces, where contact.vtu gave them, in
    contact["faces"])."""
    import numpy as np

    k, side = view_axis(contact)
    i, j = [m for m in range(3) if m != k]
    a, b = contact[AXIS_NAMES[i]], contact[AXIS_NAMES[j]]
    faces = contact.get("faces")
    pieces = facing_pieces(contact, faces["pieces"], k, side) if faces else None
    if pieces is None or len(pieces) == 0:
        return SurfaceView(i, j, k, side, a, b, np.ones(len(a), dtype=bool), None,
                           node_spacing(a, b))
    seen = np.zeros(len(a), dtype=bool)
    seen[pieces.ravel()] = True
    # The spacing where the body touches: a mesh is often finer there than elsewhere.
    touching = np.any(contact["pressure"][pieces] > 0, axis=1)
    near = pieces[touching] if np.any(touching) else pieces
    ends = np.roll(near, -1, axis=1)
    edges = np.hypot(a[near] - a[ends], b[near] - b[ends]).ravel()
    edges = edges[edges > 0]  # not a triangle's repeated corner
    spacing = float(np.median(edges)) if edges.size else 0.0
    return SurfaceView(i, j, k, side, a, b, seen, pieces, spacing)


def surface_plane(contact):
    """(i, j): the two coordinates that show the contact surface best (view_axis)."""
    k, _ = view_axis(contact)
    i, j = [m for m in range(3) if m != k]
    return i, j


def surface_triangulation(a, b):
    """A Delaunay triangulation of the projected nodes without the triangles that bridge gaps
    (between two contact surfaces, or across a hole): those with an edge over three times the
    median edge length. For results without contact.vtu, whose faces are drawn otherwise."""
    import numpy as np
    from matplotlib.tri import Triangulation

    tri = Triangulation(a, b)
    t = tri.triangles
    if len(t) == 0:
        return tri
    pa, pb = a[t], b[t]
    edges = np.hypot(pa - np.roll(pa, 1, axis=1), pb - np.roll(pb, 1, axis=1))
    typical = np.median(edges)
    if typical > 0:
        tri.set_mask(np.max(edges, axis=1) > 3.0 * typical)
    return tri


def subdivision_weights(m, triangle):
    """(weights at the corners of each sub-piece, weights at its centre): a piece cut into m x m
    sub-pieces (quadrilaterals, or triangles as quadrilaterals with the last corner repeated),
    as weights of the piece's four corners (linear on a triangle, bilinear on a
    quadrilateral)."""
    import numpy as np

    def weights(s, t):
        if triangle:  # s, t barycentric towards corners 1 and 2; corner 3 is corner 2
            return [1.0 - s - t, s, t, 0.0]
        return [(1 - s) * (1 - t), s * (1 - t), s * t, (1 - s) * t]

    corners = []
    for u in range(m):
        for v in range(m):
            if triangle:
                if u + v < m:
                    corners.append([(u, v), (u + 1, v), (u, v + 1), (u, v + 1)])
                if u + v < m - 1:
                    corners.append([(u + 1, v), (u + 1, v + 1), (u, v + 1), (u, v + 1)])
            else:
                corners.append([(u, v), (u + 1, v), (u + 1, v + 1), (u, v + 1)])
    at = np.array([[weights(s / m, t / m) for s, t in c] for c in corners])
    distinct = [sorted(set(c), key=c.index) for c in corners]
    centre = np.array([np.mean([weights(s / m, t / m) for s, t in d], axis=0) for d in distinct])
    return at, centre


def pieces_coloured(view, values, most=30000):
    """(polygons, colours): the pieces of `view` in the plane (i, j), each cut into up to 10 x 10
    sub-pieces (as many as keep their number below `most`), each coloured by `values`
    interpolated to its centre: a flat picture of the nodal values, smooth where the mesh is
    coarse, in the pieces' order (the farthest first)."""
    import numpy as np

    pieces = view.pieces
    m = int(max(1, min(10, math.sqrt(most / max(len(pieces), 1)))))
    xy = np.stack([view.a, view.b], axis=1)
    polygons, colours, order = [], [], []
    triangle = pieces[:, 3] == pieces[:, 2]
    for kind in (True, False):
        rows = np.flatnonzero(triangle == kind)
        if len(rows) == 0:
            continue
        at, centre = subdivision_weights(m, kind)
        chosen = pieces[rows]
        polygons.append(np.einsum("sck,fkd->fscd", at, xy[chosen]).reshape(-1, 4, 2))
        colours.append(np.einsum("sk,fk->fs", centre, values[chosen]).ravel())
        order.append(np.repeat(rows, len(at)))
    order = np.concatenate(order)
    keep = np.argsort(order, kind="stable")  # back to the pieces' order, farthest first
    return np.concatenate(polygons)[keep], np.concatenate(colours)[keep]


def contact_zone(contact, i, j, seen=None):
    """The centre of the contact zone (the pressure-weighted mean of the touching nodes) and its
    extent, in the plane (i, j); None without contact. `seen`: the nodes to count (all)."""
    import numpy as np

    coords = [contact[AXIS_NAMES[i]], contact[AXIS_NAMES[j]]]
    p = contact["pressure"]
    touching = p > 0
    if seen is not None:
        touching &= seen
    if not np.any(touching):
        return None
    w = p[touching]
    centre = [float(np.sum(c[touching] * w) / np.sum(w)) for c in coords]
    extent = [(float(c[touching].min()), float(c[touching].max())) for c in coords]
    return centre, extent


def node_spacing(a, b):
    """A typical distance between neighbouring nodes of the surface (the median edge of its
    triangulation)."""
    import numpy as np

    tri = surface_triangulation(a, b)
    edges = tri.edges
    if len(edges) == 0:
        return 0.0
    return float(np.median(np.hypot(a[edges[:, 0]] - a[edges[:, 1]],
                                    b[edges[:, 0]] - b[edges[:, 1]])))


def zoom_onto_zone(ax, zone, view):
    """A small contact zone (contact_zone) on a large surface: the axes zoomed onto it. Returns
    whether they were."""
    import numpy as np

    if zone is None:
        return False
    _, ((a0, a1), (b0, b1)) = zone
    c0, c1 = 0.5 * (a0 + a1), 0.5 * (b0 + b1)  # the middle of the zone's extent
    size = max(a1 - a0, b1 - b0, view.spacing * 4)
    whole = max(np.ptp(view.a[view.seen]), np.ptp(view.b[view.seen]))
    if size >= 0.4 * whole:
        return False
    half = 0.8 * size
    ax.set_xlim(c0 - half, c0 + half)
    ax.set_ylim(c1 - half, c1 + half)
    return True


def place_map(fig, ax, measure, title, cax=None):
    """A map (equal axes) under its title, as large as the figure allows: with a colour bar
    `cax` to its right, without one centred. The figure loses the height that a map wider than
    tall leaves empty, and the colour bar is as tall as the map."""
    w, h = fig.get_size_inches() * 72.0
    top_margin = BORDER + measure.height(title) + TITLE_PAD
    bar = 12.0 + 14.0 + 46.0 + 2 * TEXT_SIZE if cax else 0.0  # the bar, its ticks and label
    x0, x1 = ax.get_xlim()
    y0, y1 = ax.get_ylim()
    ratio = abs(y1 - y0) / abs(x1 - x0) if x1 != x0 and y1 != y0 else 1.0
    for _ in range(2):
        left, offset = measure.left(ax)
        bottom, _ = measure.bottom(ax)
        left += BORDER
        bottom += BORDER
        width = w - left - bar - BORDER
        height = h - bottom - top_margin - offset
        size = min(width, height)
        if ratio < 1.0:  # wider than tall: as wide as the room allows, the figure lower
            size = min(width, height / ratio)
            height = max(size * ratio, 0.4 * size)
            h = bottom + height + top_margin + offset
            fig.set_size_inches(w / 72.0, h / 72.0)
        if cax:
            place(fig, ax, left, bottom, size, height)
            place(fig, cax, left + size + 12.0, bottom, 14.0, height)
        else:
            place(fig, ax, left + 0.5 * (w - left - BORDER - size), bottom, size, height)


def figure_friction_map(summary, contact, units, measure):
    """3D friction: the contact surface seen as in the pressure map, each node of the faces seen
    coloured by its state (sticking, sliding, separated), the tangential traction as arrows in
    that plane."""
    import numpy as np

    view = surface_view(contact)
    i, j, a, b, seen = view.i, view.j, view.a, view.b, view.seen
    states = contact["state"]
    q = contact["tangential"]
    fig = new_figure(7.5, 7.0)
    ax = fig.add_axes([0.1, 0.1, 0.8, 0.8])
    for state, color in (("separated", "0.75"), ("sticking", "tab:green"),
                         ("sliding", "tab:purple")):
        rows = np.array([s == state for s in states], dtype=bool) & seen
        if np.any(rows):
            ax.plot(a[rows], b[rows], "o", color=color, ms=2.5 if len(a) > 2000 else 4,
                    label=f"{state}: {int(np.count_nonzero(rows))}", zorder=2)
    moving = (np.hypot(q[:, i], q[:, j]) > 0) & seen
    if np.any(moving):
        arrows = ax.quiver(a[moving], b[moving], q[moving, i], q[moving, j], color="black",
                           angles="xy", zorder=3, width=0.003)
        reference = float(np.max(np.hypot(q[moving, i], q[moving, j])))
        ax.quiverkey(arrows, 0.82, 1.0, reference, with_unit(f"{reference:.3g}", units.stress)
                     if units.stress else f"{reference:.3g}", labelpos="W", coordinates="axes",
                     fontproperties={"size": LEGEND_SIZE})
    ax.set_aspect("equal")
    ax.set_xlabel(axis_label(AXIS_NAMES[i], units.length))
    ax.set_ylabel(axis_label(AXIS_NAMES[j], units.length))
    zoomed = zoom_onto_zone(ax, contact_zone(contact, i, j, seen), view)
    subtitle = (f"Friction ({friction_law(summary)}) over the contact surface, seen along "
                f"{AXIS_NAMES[view.k]}; arrows: the tangential traction")
    subtitle += " (zoomed onto the contact zone)" if zoomed else ""
    title = wrapped(title_of(summary) + "\n" + subtitle, 7.5)
    ax.set_title(title, fontsize=TEXT_SIZE, y=1.0)
    ax.legend(fontsize=LEGEND_SIZE, loc="lower right")
    place_map(fig, ax, measure, title)
    return fig, describe_limits(ax)


def contact_resultant(summary, k):
    """(R_k, |R|): the force of the obstacle on the body that the reactions balance
    (summary.json's resultants.contact, -sum_j h_j l_j nu_j with friction's tangential forces),
    its component along axis k and its length; None where the summary has none (results of an
    older signorini, a load step's view). Not contact_force, sum_j h_j l_j, which adds up the
    normal forces whatever their directions: on a curved or faceted surface the two differ."""
    vector = summary.get("resultants", {}).get("contact") \
        if isinstance(summary.get("resultants"), dict) else None
    if vector is None:
        vector = summary.get("contact_force_vector")
    if not (isinstance(vector, list) and len(vector) == 3 and
            all(isinstance(v, (int, float)) for v in vector)):
        return None
    return float(vector[k]), math.sqrt(sum(v * v for v in vector))


def resultant_text(summary, k, unit):
    """The map's words for the contact force (contact_resultant; a load step's contact_force,
    where the summary has no resultant). Its spaces do not break (NBSP): the title's wrapping
    keeps "R_z = 0.25 MN" on one line."""
    def value(number):
        return with_unit(f"{number:.4g}", unit).replace(" ", NBSP)

    resultant = contact_resultant(summary, k)
    if resultant is not None:
        along, length = resultant
        text = f", contact resultant R_{AXIS_NAMES[k]}{NBSP}={NBSP}{value(along)}"
        if abs(length - abs(along)) > 1e-3 * length:  # tangential forces too
            text += f" (|R|{NBSP}={NBSP}{value(length)})"
        return text
    force = summary.get("contact_force")
    if isinstance(force, (int, float)):
        return ", contact force " + value(force)
    return ""


def figure_pressure_map(summary, contact, units, measure):
    """The contact surface seen along view_axis, its faces that face the obstacle coloured by
    the pressure (the farthest drawn first, so that the nearest show)."""
    import numpy as np

    view = surface_view(contact)
    i, j, a, b = view.i, view.j, view.a, view.b
    p = contact["pressure"]
    k = power_of_ten(p)
    scale = 10.0 ** k
    fig = new_figure(7.5, 6.5)
    ax = fig.add_axes([0.1, 0.1, 0.7, 0.8])
    cax = fig.add_axes([0.85, 0.1, 0.03, 0.8])
    top = max(float(np.nanmax(p)), 0.0) / scale
    limits = {"cmap": "viridis", "vmin": 0.0, "vmax": top if top > 0 else 1.0}
    if view.pieces is not None:
        from matplotlib.collections import PolyCollection

        polygons, colours = pieces_coloured(view, p / scale)
        # Not antialiased: neighbouring pieces meet without a seam.
        image = PolyCollection(polygons, array=colours, cmap=limits["cmap"],
                               antialiased=False, linewidths=0.0, rasterized=True)
        image.set_clim(limits["vmin"], limits["vmax"])
        ax.add_collection(image)
        ax.set_xlim(*padded(float(a[view.seen].min()), float(a[view.seen].max()), 0.03))
        ax.set_ylim(*padded(float(b[view.seen].min()), float(b[view.seen].max()), 0.03))
    else:  # older results without contact.vtu: the nodes' triangulation
        image = ax.tripcolor(surface_triangulation(a, b), p / scale, shading="gouraud",
                             rasterized=True, **limits)
    zone = contact_zone(contact, i, j, view.seen)
    touching = (p > 0) & view.seen
    marked = zone is not None and np.count_nonzero(touching) <= 5000
    if marked:
        ax.plot(a[touching], b[touching], ".", color="white", ms=1.5, alpha=0.6)
    ax.set_aspect("equal")
    ax.set_xlabel(axis_label(AXIS_NAMES[i], units.length))
    ax.set_ylabel(axis_label(AXIS_NAMES[j], units.length))
    zoomed = zoom_onto_zone(ax, zone, view)
    colorbar = fig.colorbar(image, cax=cax)
    colorbar.set_label(axis_label("contact pressure", units.stress, k), fontsize=TEXT_SIZE)
    subtitle = f"Contact pressure over the contact surface, seen along {AXIS_NAMES[view.k]}"
    subtitle += " (zoomed onto the contact zone)" if zoomed else ""
    if zone is None:
        subtitle += " (no contact)"
    subtitle += resultant_text(summary, view.k, force_unit(summary))
    if marked:  # said here, not in a legend over the map
        subtitle += (f"; white dots: the {int(np.count_nonzero(touching))} nodes in contact, of "
                     f"{int(np.count_nonzero(view.seen))}")
    title = wrapped(title_of(summary) + "\n" + subtitle, 7.5)
    ax.set_title(title, fontsize=TEXT_SIZE, y=1.0)
    place_map(fig, ax, measure, title, cax)
    # Centred over the figure, not over the map beside the colour bar: its lines, wrapped to
    # the figure's width, would stick out on the left.
    box = ax.get_position()
    ax.title.set_x((0.5 - box.x0) / box.width)
    return fig, describe_limits(ax)


def hertz_parameters(summary, radius=None, symmetry=1):
    """(R, E*, a, p0) of Hertz's contact of a sphere of radius R with a flat elastic body or of
    an elastic sphere with a rigid plane (E* = E / (1 - nu^2), the partner rigid) under the
    computed contact force F: a = (3 F R / (4 E*))^(1/3), p0 = 3 F / (2 pi a^2). R is `radius`
    if given, else that of a rigid sphere obstacle (a disc in 3D, the body outside it); None
    where neither applies (another obstacle, several contact boundaries, no force). A model of
    1/`symmetry` of the body (symmetry planes held by rollers) carries 1/symmetry of the force."""
    problem = summary.get("problem", {})
    contact = problem.get("contact")
    material = problem.get("material", {})
    if radius is None:
        if not (isinstance(contact, dict) and contact.get("obstacle") == "disc" and
                not contact.get("inside", False)):
            return None
        radius = contact.get("radius")
    E, nu = material.get("E"), material.get("nu")
    force = summary.get("contact_force")
    if not all(isinstance(v, (int, float)) for v in (radius, E, nu, force)):
        return None
    force *= symmetry
    if radius <= 0 or E <= 0 or force <= 0 or problem.get("region"):
        return None
    e_star = E / (1.0 - nu * nu)
    a = (3.0 * force * radius / (4.0 * e_star)) ** (1.0 / 3.0)
    p0 = 3.0 * force / (2.0 * math.pi * a * a)
    return radius, e_star, a, p0


def held_planes(summary):
    """[axis]: the axes along which a clamp (or a prescribed displacement of 0) holds one
    component alone: a roller, as on a symmetry plane x = const (components = ["x"])."""
    problem = summary.get("problem", {})
    axes = []
    for clamp in problem.get("clamp", []) if isinstance(problem.get("clamp"), list) else []:
        held = clamp.get("components") if isinstance(clamp, dict) else None
        if isinstance(held, list) and len(held) == 1 and held[0] in AXIS_NAMES:
            axes.append(AXIS_NAMES.index(held[0]))
    displacements = problem.get("displacement")
    for entry in displacements if isinstance(displacements, list) else []:
        given = [c for c in AXIS_NAMES if isinstance(entry, dict) and c in entry]
        if len(given) == 1:
            try:
                if float(entry[given[0]]) == 0.0:
                    axes.append(AXIS_NAMES.index(given[0]))
            except (TypeError, ValueError):  # an expression: not a symmetry plane
                pass
    return sorted(set(axes))


def symmetry_planes(summary, contact, view):
    """[(m, c)]: the symmetry planes that cut the contact zone, as the in-plane coordinate m
    (0: a, 1: b) and its value c. A model of a part of a body cut by its symmetry planes holds
    each by a roller (held_planes); such a plane is a flat end of the contact part, where every
    node keeps its coordinate (its displacement along the axis 0: contact.vtu's, else
    contact.csv's) and which the contact zone reaches. Where both ends qualify, neither is
    taken."""
    import numpy as np

    faces = contact.get("faces")
    u = faces.get("displacement") if faces else None
    if u is None:  # contact.csv's, to rounding
        u = contact.get("u")
    touching = (contact["pressure"] > 0) & view.seen
    if u is None or not np.any(touching):
        return []
    points = np.stack([contact[name] for name in AXIS_NAMES], axis=1)
    size = float(np.max(np.ptp(points, axis=0)))
    largest = float(np.max(np.abs(u))) if u.size else 0.0
    planes = []
    for axis in held_planes(summary):
        if axis == view.k:
            continue
        x = points[:, axis]
        found = []
        for c in (float(x.min()), float(x.max())):
            on = np.abs(x - c) <= 1e-9 * size
            if (np.count_nonzero(on) >= 2 and np.all(np.abs(u[on, axis]) <= 1e-12 * largest)
                    and np.any(on & touching)):
                found.append(0.0 if abs(c) <= 1e-9 * size else c)  # a mesh's 4.5e-33: 0
        if len(found) == 1:
            planes.append((0 if axis == view.i else 1, found[0]))
    return planes


def mirrored(a, b, p, planes):
    """(a, b, p, copies): the nodes with their mirror images across the symmetry planes
    [(m, c)], the images of nodes on a plane left out; copies: how many images each row is
    (0: the node itself)."""
    import numpy as np

    copies = np.zeros(len(a), dtype=int)
    size = max(float(np.ptp(a)), float(np.ptp(b)), 1e-300) if len(a) else 1.0
    for m, c in planes:
        coordinate = a if m == 0 else b
        off = np.abs(coordinate - c) > 1e-9 * size
        image = 2.0 * c - coordinate[off]
        a = np.concatenate([a, image if m == 0 else a[off]])
        b = np.concatenate([b, b[off] if m == 0 else image])
        p = np.concatenate([p, p[off]])
        copies = np.concatenate([copies, copies[off] + 1])
    return a, b, p, copies


def zone_shape(a, b, p, spacing):
    """(centre, direction, line): the pressure-weighted centre of the touching nodes, and
    whether they lie along a line (a cylinder on a plane), three times longer than wide (the
    width at least a node spacing), and its direction (a unit vector in the plane, along an
    axis when within about 6 degrees of one); None without contact."""
    import numpy as np

    touching = p > 0
    if not np.any(touching):
        return None
    w = p[touching]
    xy = np.stack([a[touching], b[touching]], axis=1)
    centre = (w @ xy) / np.sum(w)
    d = xy - centre
    spread = (d * w[:, None]).T @ d / np.sum(w)
    _, vectors = np.linalg.eigh(spread)
    direction = vectors[:, 1]  # the largest eigenvalue's
    if np.max(np.abs(direction)) > 0.995:
        direction = np.where(np.abs(direction) == np.max(np.abs(direction)), 1.0, 0.0)
    across = np.array([-direction[1], direction[0]])
    length = float(np.ptp(d @ direction))
    width = max(float(np.ptp(d @ across)), spacing)
    line = np.count_nonzero(touching) >= 3 and length >= 3.0 * width
    return centre, direction, bool(line)


def offset_text(name, value):
    """"x − 0.5" (or "x" for 0, "x + 0.5" for -0.5)."""
    if value == 0:
        return name
    return f"{name} − {value:.4g}" if value > 0 else f"{name} + {-value:.4g}"


def figure_pressure_profile(summary, contact, units, measure, hertz_radius=None, symmetry=1):
    """The pressure through the centre of the contact zone: across the line of a line contact,
    else along the first in-plane axis, with every node at its distance from the line or the
    centre. A part of a body cut by symmetry planes (symmetry_planes) is seen whole, its nodes
    mirrored across them: the centre lies on them."""
    import numpy as np

    view = surface_view(contact)
    i, j = view.i, view.j
    planes = symmetry_planes(summary, contact, view)
    # The faces seen: the nodes of side walls would stand at the patch's rim with no pressure.
    seen = view.seen
    a, b, p, copies = mirrored(view.a[seen], view.b[seen], contact["pressure"][seen], planes)
    k = power_of_ten(p)
    scale = 10.0 ** k
    h = view.spacing
    fig = new_figure(8, 4.5)
    ax = fig.add_axes([0.1, 0.1, 0.8, 0.8])
    shape = zone_shape(a, b, p, h)
    line_contact = shape is not None and shape[2]
    if shape is None:
        centre, direction = np.array([float(np.mean(a)), float(np.mean(b))]), np.array([1., 0.])
    else:
        centre, direction = shape[0], (shape[1] if line_contact else np.array([1.0, 0.0]))
    if shape is not None and symmetry > 1 and not planes:
        # --symmetry without the rollers' planes found (results of an older signorini): the
        # centre of the whole zone, where the pressure peaks, not at the part's mean.
        top = int(np.argmax(p))
        centre = np.array([float(a[top]), float(b[top])])
    for m, c in planes:  # exactly on the planes
        centre[m] = c
    across = np.array([-direction[1], direction[0]]) if line_contact else direction
    if line_contact and np.min(across) < 0 and np.max(np.abs(across)) == 1.0:
        across = -across  # along an axis, that axis's way
    d = np.stack([a - centre[0], b - centre[1]], axis=1)
    mirror_note = (", and mirrored across " + " and ".join(
        f"{AXIS_NAMES[(i, j)[m]]} = {c:.4g}" for m, c in planes) if planes else "")
    count = int(np.count_nonzero(copies == 0))
    names = (AXIS_NAMES[i], AXIS_NAMES[j])
    if line_contact:
        # A line contact: the pressure across the line, every node at its distance from the
        # line's axis (a radial distance from a point would spread the line's points over its
        # whole length).
        signed = d @ across
        along = d @ direction
        ax.plot(signed, p / scale, ".", color="0.65", ms=2.5,
                label=f"every contact node at its distance from the line ({count}"
                      f"{mirror_note})")
        section = np.abs(along) <= 0.51 * h if h > 0 else np.ones(len(p), dtype=bool)
        order = np.argsort(signed[section])
        ruled = [m for m in range(2) if direction[m] == 1.0]  # the line along an axis
        if ruled:
            m = ruled[0]
            where = f"the section {names[m]} = {centre[m]:.4g}"
            xlabel = (f"{offset_text(names[1 - m], centre[1 - m])} (distance from the line of "
                      f"contact, which runs along {names[m]})")
        else:
            where = "the section through the middle"
            xlabel = "distance from the line of contact, across it"
        ax.plot(signed[section][order], p[section][order] / scale, "o-", color="tab:red", ms=3,
                lw=1.4, label=f"nodes within half a spacing of {where} across the line")
    else:
        r = np.hypot(d[:, 0], d[:, 1])
        signed = np.where(d[:, 0] < 0, -r, r)
        # Every node at its distance from the centre, on the side of its first in-plane
        # coordinate (for a round contact zone, the profile folded onto one line).
        ax.plot(signed, p / scale, ".", color="0.65", ms=2.5,
                label=f"every contact node at ± its distance from the centre ({count}"
                      f"{mirror_note})")
        # The nodes on the line through the centre along the first in-plane axis.
        section = np.abs(d[:, 1]) <= 0.51 * h if h > 0 else np.ones(len(p), dtype=bool)
        order = np.argsort(d[section, 0])
        ax.plot(d[section, 0][order], p[section][order] / scale, "o-", color="tab:red", ms=3,
                lw=1.4, label=f"nodes within half a spacing of the line {names[1]} = "
                              f"{centre[1]:.4g}")
        xlabel = (f"{offset_text(names[0], centre[0])} (distance from the centre of the contact "
                  "zone)")
    # Hertz's profile is a sphere's, not a line contact's.
    hertz = None if line_contact else hertz_parameters(summary, hertz_radius, symmetry)
    description = ""
    if hertz is not None:
        radius, e_star, ra, p0 = hertz
        s = np.linspace(-ra, ra, 201)
        ax.plot(s, p0 * np.sqrt(np.maximum(1.0 - (s / ra) ** 2, 0.0)) / scale, "--",
                color="black", lw=1.2,
                label=(f"Hertz, same force (R = {radius:.4g}, E* = {e_star:.4g}"
                       + (f", the model {symmetry} times" if symmetry != 1 else "") + "): "
                       f"a = {ra:.4g}, p0 = {p0:.4g}"))
        description = f"; hertz: a {ra:.6g}, p0 {p0:.6g}"
    ax.axhline(0.0, color="0.6", lw=0.8, gid="reference")
    ax.set_xlabel(axis_label(xlabel, units.length))
    ax.set_ylabel(axis_label("contact pressure", units.stress, k))
    if shape is not None:
        extent = max(np.max(np.abs(signed[p > 0])), h)
        if hertz is not None:
            extent = max(extent, hertz[2])
        ax.set_xlim(-1.6 * extent, 1.6 * extent)
    top = max(float(np.nanmax(p)), hertz[3] if hertz else 0.0, 0.0) / scale
    # Room above the curves for the legend (a line a row).
    rows = len(ax.get_legend_handles_labels()[1])
    ax.set_ylim(-0.02 * max(top, 1e-300), (1.12 + 0.09 * rows) * top if top > 0 else 1.0)
    subtitle = ("Contact pressure across the line of contact, through its middle" if line_contact
                else "Contact pressure through the centre of the contact zone")
    if planes:
        subtitle += " (on the symmetry plane" + ("s" if len(planes) > 1 else "") + ")"
    if shape is None:
        subtitle += " (no contact)"
    title = wrapped(title_of(summary) + "\n" + subtitle, 8)
    ax.set_title(title, fontsize=TEXT_SIZE, y=1.0)
    ax.grid(True, alpha=0.3)
    place_single(fig, ax, measure, title)
    legend_off_the_curves(ax, relayout=lambda: place_single(fig, ax, measure, title),
                          fontsize=LEGEND_SIZE)
    return fig, describe_limits(ax, scale) + description


# Drawing and writing -----------------------------------------------------------------------


def png_chunk(kind, data):
    import zlib

    return (len(data).to_bytes(4, "big") + kind + data
            + zlib.crc32(kind + data).to_bytes(4, "big"))


def write_png(fig, path, metadata):
    """The figure drawn by Agg at DPI, written as an 8-bit RGB PNG (the PNG specification, ISO/IEC
    15948). Not through Pillow, as matplotlib does: Pillow copies the picture, keeps its alpha
    channel (always opaque here) and tries five row filters on every row; rows left unfiltered
    and compressed quickly make files about 10 % larger, written three to four times faster
    (a third of the time of a figure went into writing its PNG)."""
    import zlib

    import numpy as np

    fig.set_dpi(DPI)
    fig.canvas.draw()
    rgba = np.asarray(fig.canvas.buffer_rgba())
    h, w, _ = rgba.shape
    rows = np.empty((h, 1 + 3 * w), np.uint8)
    rows[:, 0] = 0  # filter type 0 (None) on each row
    rows[:, 1:] = rgba[..., :3].reshape(h, 3 * w)
    text = b"".join(png_chunk(b"tEXt", k.encode("latin-1") + b"\0" + v.encode("latin-1", "replace"))
                    for k, v in metadata.items())
    dots_per_metre = round(DPI / 0.0254).to_bytes(4, "big")
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n"
                + png_chunk(b"IHDR", w.to_bytes(4, "big") + h.to_bytes(4, "big") + bytes([8, 2, 0, 0, 0]))
                + png_chunk(b"pHYs", dots_per_metre + dots_per_metre + b"\x01")
                + text
                + png_chunk(b"IDAT", zlib.compress(rows, 1))  # the array, not a copy
                + png_chunk(b"IEND", b""))


def formats_of(text):
    """The list of formats in `text` ("png,svg"), each once, in the order given."""
    formats = []
    for fmt in text.split(","):
        fmt = fmt.strip().lower()
        if fmt not in FORMATS:
            raise UsageError(f"--format {text}: '{fmt}' is not a format of the figures; expected "
                             "png, svg or pdf, or several separated by commas (png,svg)")
        if fmt not in formats:
            formats.append(fmt)
    return formats


def draw_and_save(outdir, name, make, written, formats):
    """Draws one figure and writes it in each of `formats` under a temporary name, appending
    (temporary, final) to `written` before each file is begun."""
    fig, description = make()
    for fmt in formats:
        final = os.path.join(outdir, f"{name}.{fmt}")
        tmp = os.path.join(outdir, f".{name}.{fmt}.tmp.{os.getpid()}")
        written.append((tmp, final))
        metadata = {"Title": name, "Description": description}
        if fmt == "png":
            write_png(fig, tmp, metadata)
        elif fmt == "svg":
            metadata["Date"] = None  # the same file for the same results
            fig.savefig(tmp, format=fmt, dpi=DPI, metadata=metadata)
        else:  # PDF's information dictionary has a Subject, not a Description
            fig.savefig(tmp, format=fmt, dpi=DPI, metadata={
                "Title": name, "Subject": description, "CreationDate": None})
    # A figure is a web of references that only the garbage collector frees: now, so that the
    # next figure reuses its memory.
    del fig
    import gc

    gc.collect()


def draw(outdir, next_figure, scale, written, formats, warnings=True, hertz=(None, 1),
         steps=()):
    """Reads the results and draws the figures that `next_figure()` names, until it returns
    None, into temporary files (listed in `written`); returns the names drawn. `steps`: the load
    steps whose contact figures are drawn too."""
    import_plotting()
    summary = read_summary(outdir)
    units = units_of_summary(summary, warnings)
    contact = read_contact_csv(outdir)
    measure = Measure()
    if "z" in contact:  # 3D: the contact surface
        contact["faces"] = contact_faces(outdir, contact, warnings)
        makers = {
            "contact_pressure_map": lambda: figure_pressure_map(summary, contact, units, measure),
            "contact_pressure": lambda: figure_pressure_profile(summary, contact, units, measure,
                                                                *hertz),
        }
        if "state" in contact:
            makers["contact_friction_map"] = lambda: figure_friction_map(summary, contact, units,
                                                                         measure)
    else:
        along_boundary(contact, units)
        makers = {
            "contact_displacement": lambda: figure_displacement(summary, contact, units, measure),
            "contact_pressure": lambda: figure_pressure(summary, contact, units, measure),
            "deformed_von_mises": lambda: figure_deformed(
                summary, read_solution(outdir), contact, scale, units,
                measure),
        }
        if "state" in contact:
            makers["contact_friction"] = lambda: figure_friction(summary, contact, units, measure)
    makers["convergence"] = lambda: figure_convergence(summary, measure)
    three = "z" in contact
    for k in steps:  # each step's contact.csv, read when its figure is drawn
        makers[step_figure(step_base(3 if three else 2, "state" in contact), k)] = \
            lambda k=k: figure_of_step(outdir, summary, k, three, units, measure)
    drawn = []
    while (name := next_figure()) is not None:
        drawn.append(name)
        draw_and_save(outdir, name, makers[name], written, formats)
    return drawn


def along_boundary(contact, units):
    """2D: what the figures along the contact boundary share, added to `contact`."""
    contact["t"], contact["t_label"] = boundary_coordinate(contact, units)
    contact["parts"] = boundary_parts(contact)
    contact["intervals"] = [iv for _, rows in contact["parts"]
                            for iv in contact_intervals(contact["t"][rows],
                                                        contact["pressure"][rows] > 0)]


def figure_of_step(outdir, summary, k, three, units, measure):
    """Load step k's figure of the contact (step_base) from its steps/contact_NNNN.csv."""
    contact = read_contact_csv(outdir, step_csv(k))
    view = step_view(summary, k)
    friction = "state" in contact
    if three:  # the faces of contact.vtu, the last step's, join the same nodes
        contact["faces"] = contact_faces(outdir, contact, warnings=False)
        return (figure_friction_map if friction else figure_pressure_map)(view, contact, units,
                                                                           measure)
    along_boundary(contact, units)
    return (figure_friction if friction else figure_pressure)(view, contact, units, measure)


def cores():
    try:
        return len(os.sched_getaffinity(0))
    except (AttributeError, OSError):
        return os.cpu_count() or 1


# The figures, the longest to draw first: with two processes taking them in turn, neither waits
# long for the other at the end.
ORDER = ["deformed_von_mises", "convergence", "contact_displacement", "contact_pressure"]
ORDER_3D = ["contact_pressure_map", "convergence", "contact_pressure"]


def step_base(dimension, friction):
    """The figure drawn for each load step that --steps chooses."""
    if dimension == 3:
        return "contact_friction_map" if friction else "contact_pressure_map"
    return "contact_friction" if friction else "contact_pressure"


def figure_names(dimension, friction=False, steps=()):
    """The figures, in the order of docs/output.md."""
    names = list(FIGURES_3D if dimension == 3 else FIGURES)
    if friction:
        names.append(step_base(dimension, True))
    return names + [step_figure(step_base(dimension, friction), k) for k in steps]


def order_of(dimension, friction=False, steps=()):
    first = ORDER_3D if dimension == 3 else ORDER
    return first + [n for n in figure_names(dimension, friction, steps) if n not in first]


class Helper:
    """A second process (fork, before numpy and matplotlib are imported: the two import them at
    the same time) that draws figures too. The two take the names of the figures from a pipe,
    one at a time, so that a process that is faster (or started sooner) draws more; the helper
    reports the files it wrote, or its error, through another pipe."""

    def __init__(self, outdir, scale, formats, order, hertz=(None, 1), steps=()):
        self.outdir = outdir
        self.formats = formats
        self.order = order
        queue_read, queue_write = os.pipe()
        os.write(queue_write, bytes(range(len(order))))
        os.close(queue_write)  # read to the end: no figure left
        report_read, report_write = os.pipe()
        sys.stdout.flush()
        sys.stderr.flush()
        self.pid = os.fork()
        if self.pid == 0:
            os.close(report_read)
            self.run(queue_read, report_write, outdir, scale, formats, order, hertz,
                     steps)  # does not return
        os.close(report_write)
        self.queue = queue_read
        self.report = report_read

    def next_figure(self):
        """The next figure to draw, or None: reads one byte (atomic: each name goes to one of
        the processes)."""
        index = os.read(self.queue, 1)
        return self.order[index[0]] if index else None

    @staticmethod
    def run(queue, report_end, outdir, scale, formats, order, hertz, steps):
        status, written = 0, []

        def next_figure():
            index = os.read(queue, 1)
            return order[index[0]] if index else None

        try:
            drawn = draw(outdir, next_figure, scale, written, formats, warnings=False,
                         hertz=hertz, steps=steps)
            report = {"drawn": drawn}
        except UsageError as e:
            status, report = 2, {"usage": str(e)}
        except BaseException as e:  # noqa: BLE001 - the parent says it
            status, report = 1, {"bug": f"{type(e).__name__}: {e}"}
            if os.environ.get("SIGNORINI_DEBUG"):
                import traceback

                traceback.print_exc()
        try:
            with os.fdopen(report_end, "w") as pipe:
                pipe.write(json.dumps(report))
        finally:
            os._exit(status)

    def temporaries(self, names):
        """The files the helper writes for the figures `names`."""
        return [(os.path.join(self.outdir, f".{name}.{fmt}.tmp.{self.pid}"),
                 os.path.join(self.outdir, f"{name}.{fmt}"))
                for name in names for fmt in self.formats]

    def finish(self):
        """Waits for the helper; returns the names of the figures it drew, or raises its error."""
        os.close(self.queue)
        with os.fdopen(self.report) as pipe:
            text = pipe.read()
        _, status = os.waitpid(self.pid, 0)
        try:
            report = json.loads(text)
        except ValueError:
            report = {}
        if "usage" in report:
            raise UsageError(report["usage"])
        if "bug" in report:
            raise RuntimeError(report["bug"])
        if "drawn" not in report or not os.WIFEXITED(status) or os.WEXITSTATUS(status) != 0:
            how = (f"signal {os.WTERMSIG(status)}" if os.WIFSIGNALED(status) else
                   f"exit status {os.WEXITSTATUS(status)}")
            raise RuntimeError(f"the second process drawing the figures ended ({how}) without "
                               "saying what it drew")
        return report["drawn"]

    def stop(self):
        """Ends the helper (after an error here)."""
        import signal

        for fd in (self.queue, self.report):
            try:
                os.close(fd)
            except OSError:
                pass
        try:
            os.kill(self.pid, signal.SIGTERM)
            os.waitpid(self.pid, 0)
        except (ChildProcessError, ProcessLookupError):
            pass


def save_all(outdir, scale, quiet, formats, hertz=(None, 1), steps=()):
    """Every file is written under a temporary name first and renamed at the end, so that a
    failure leaves no half-written picture and keeps the pictures of an earlier run. With two
    cores or more, two processes draw the figures (about half of the time)."""
    dimension = contact_dimension(outdir)
    friction = contact_friction(outdir)
    order = order_of(dimension, friction, steps)
    helper = None
    if cores() >= 2 and hasattr(os, "fork"):
        helper = Helper(outdir, scale, formats, order, hertz, steps)
    written, mine = [], []
    try:
        if helper is None:
            figures = iter(order)
            draw(outdir, lambda: next(figures, None), scale, written, formats, hertz=hertz,
                 steps=steps)
        else:
            mine = draw(outdir, helper.next_figure, scale, written, formats, hertz=hertz,
                        steps=steps)
            waiting, helper = helper, None
            try:
                theirs = waiting.finish()
            except BaseException:  # what it wrote before its error goes
                written += waiting.temporaries([n for n in order if n not in mine])
                raise
            written += waiting.temporaries(theirs)
        for tmp, final in written:
            os.replace(tmp, final)
    except OSError as e:
        raise UsageError(f"cannot write the figures into '{outdir}': {e}")
    finally:
        if helper is not None:  # an error here: the helper's work is of no use
            helper.stop()
            written += helper.temporaries([n for n in order if n not in mine])
        for tmp, _ in written:
            if os.path.exists(tmp):
                os.unlink(tmp)
    if not quiet:
        print("figures: " + ", ".join(os.path.join(outdir, f"{n}.{fmt}")
                                      for n in figure_names(dimension, friction, steps)
                                      for fmt in formats))


def chosen_steps(outdir, text):
    """The load steps of --steps ("1,3" or "all"; "" none), each checked to be one of the
    history's with its contact.csv in steps/."""
    text = text.replace(" ", "")
    if not text:
        return []
    steps = read_summary(outdir).get("load_steps")
    count = len(steps) if isinstance(steps, list) else 0
    if count == 0:
        raise UsageError(f"--steps {text}: '{outdir}' has no loading history (summary.json has "
                         "no load_steps)")
    if text == "all":
        chosen = list(range(1, count + 1))
    else:
        try:
            chosen = [int(k) for k in text.split(",")]
        except ValueError:
            raise UsageError(f"--steps {text}: expected step numbers separated by commas, or all")
    for k in chosen:
        if not 1 <= k <= count:
            raise UsageError(f"--steps {text}: step {k} is not one of the history's, 1 to {count}")
        if not os.path.exists(os.path.join(outdir, step_csv(k))):
            raise UsageError(f"'{os.path.join(outdir, step_csv(k))}' not found")
    return sorted(set(chosen))


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("outdir", nargs="?", help="output folder of signorini solve")
    parser.add_argument("--scale", type=float, default=None,
                        help="magnification of the displacement in the deformed-body figure "
                             "(default: chosen so that the largest is about 10%% of the body)")
    parser.add_argument("--format", default=DEFAULT_FORMATS,
                        help="the formats of the figures: png, svg, pdf, or several separated by "
                             f"commas (default: {DEFAULT_FORMATS})")
    parser.add_argument("--hertz-radius", type=float, default=None, metavar="R",
                        help="3D: draw Hertz's pressure profile for a sphere of radius R (the "
                             "body's, pressed onto a rigid plane; default: the radius of a rigid "
                             "sphere obstacle, if there is one)")
    parser.add_argument("--symmetry", type=int, default=1, metavar="N",
                        help="3D: the model is 1/N of the body (symmetry planes held by rollers: "
                             "2, 4 or 8); Hertz's profile takes N times its contact force")
    parser.add_argument("--steps", default="", metavar="LIST",
                        help="with a loading history: also draw the contact figure of these load "
                             "steps (numbers separated by commas, or 'all'), from steps/")
    parser.add_argument("--quiet", action="store_true", help="print nothing but errors")
    parser.add_argument("--check", action="store_true",
                        help="only check that numpy and matplotlib are installed")
    args = parser.parse_args(argv)
    try:
        formats = formats_of(args.format)
        check_plotting()
        if args.check:
            return 0
        if not args.outdir:
            raise UsageError("expected the output folder of signorini solve")
        if args.scale is not None and not (math.isfinite(args.scale) and args.scale > 0):
            raise UsageError(f"--scale {args.scale}: expected a positive number")
        if not os.path.isdir(args.outdir):
            raise UsageError(f"'{args.outdir}' is not a folder")
        if args.hertz_radius is not None and not (math.isfinite(args.hertz_radius) and
                                                  args.hertz_radius > 0):
            raise UsageError(f"--hertz-radius {args.hertz_radius}: expected a positive number")
        if args.symmetry < 1:
            raise UsageError(f"--symmetry {args.symmetry}: expected a whole number >= 1")
        check_results(args.outdir)
        steps = chosen_steps(args.outdir, args.steps)
        save_all(args.outdir, args.scale, args.quiet, formats, (args.hertz_radius, args.symmetry),
                 steps)
    except UsageError as e:
        fail(2, e)
    return 0


def run():
    """The command line (tools/plot_results.py): main() with its exit status, and a bug said in
    one line."""
    try:
        status = main(sys.argv[1:])
        # Every file is written and closed: the interpreter's clean-up of matplotlib's thousands
        # of objects (a twentieth of a second) is skipped.
        sys.stdout.flush()
        sys.stderr.flush()
        os._exit(status)
    except SystemExit:
        raise
    except BaseException as e:  # a bug: say so in one line, the traceback on request
        if os.environ.get("SIGNORINI_DEBUG"):
            raise
        fail(1, f"plot script failed: {type(e).__name__}: {e} (set SIGNORINI_DEBUG=1 for a "
                f"traceback)")


if __name__ == "__main__":
    run()
