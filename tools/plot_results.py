#!/usr/bin/env python3
"""Draws the figures of a signorini run from its output folder (docs/output.md).

    python3 tools/plot_results.py OUTDIR [--scale S] [--quiet]
    python3 tools/plot_results.py --check        # are numpy and matplotlib there? (exit 0 or 2)

`signorini plot OUTDIR` and `signorini solve ... --plot` run this script. It reads
OUTDIR/summary.json, contact.csv and solution.vtu and writes, as PNG and SVG:

    contact_displacement   normal and tangential displacement along the contact boundary
    contact_pressure       the contact pressure along the contact boundary, where the body touches
    deformed_von_mises     the deformed body x + s u(x) coloured by the von Mises stress
    convergence            the Uzawa residual per iteration and GNM iterations per Uzawa step

Units are those of the paper's examples (metres and MPa). Exit status: 0 written, 2 a missing
package or an unusable output folder (one line on stderr), 1 anything else.
"""

import argparse
import csv
import json
import math
import os
import sys
import textwrap
import xml.etree.ElementTree as ET

FIGURES = ["contact_displacement", "contact_pressure", "deformed_von_mises", "convergence"]
FORMATS = ["png", "svg"]


class UsageError(Exception):
    """A problem the user can fix (exit status 2): a missing file, a missing package."""


def fail(status, message):
    sys.stderr.write("signorini: error: " + " ".join(str(message).split("\n")) + "\n")
    sys.exit(status)


def import_plotting():
    try:
        import numpy  # noqa: F401
        import matplotlib

        matplotlib.use("Agg")  # files only, no display needed
        # Text in the SVG files stays text (searchable, editable), not glyph outlines.
        matplotlib.rcParams["svg.fonttype"] = "none"
        import matplotlib.pyplot  # noqa: F401
    except ImportError as e:
        raise UsageError(
            f"plotting needs numpy and matplotlib for {sys.executable} ({e}); on Debian: "
            "apt-get install python3-matplotlib"
        )


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


def read_contact_csv(outdir):
    import numpy as np

    path = os.path.join(outdir, "contact.csv")
    try:
        with open(path, newline="", encoding="utf-8") as f:
            rows = list(csv.DictReader(f))
        columns = {k: np.array([float(r[k]) for r in rows]) for k in
                   ("x", "y", "u_n", "u_t", "pressure", "gap")}
    except FileNotFoundError:
        raise UsageError(f"'{path}' not found: is '{outdir}' the output folder of signorini solve?")
    except (OSError, KeyError, TypeError, ValueError) as e:
        raise UsageError(f"cannot read '{path}': expected the columns x,y,u_n,u_t,pressure,gap ({e})")
    if len(rows) == 0:
        raise UsageError(f"'{path}' has no contact nodes")
    return columns


VTK_TYPES = {"Float64": "f8", "Float32": "f4", "Int64": "i8", "Int32": "i4", "UInt64": "u8",
             "UInt32": "u4", "UInt8": "u1", "Int8": "i1"}


def read_vtu(path):
    """The points, cells and point data of a .vtu written by signorini (raw appended data)."""
    import numpy as np

    try:
        with open(path, "rb") as f:
            raw = f.read()
    except FileNotFoundError:
        raise UsageError(f"'{path}' not found (results of an older signorini? run solve again)")
    except OSError as e:
        raise UsageError(f"cannot read '{path}': {e}")
    try:
        start = raw.find(b"<AppendedData")
        if start < 0:
            raise ValueError("no <AppendedData> block")
        underscore = raw.index(b"_", raw.index(b">", start))
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
    largest = float(np.max(np.linalg.norm(displacement, axis=1))) if len(displacement) else 0.0
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


def unit_label(quantity, k, unit):
    return f"{quantity} ({unit})" if k == 0 else f"{quantity} ($10^{{{k}}}$ {unit})"


def boundary_coordinate(contact):
    """The abscissa of the contact-boundary plots: x or y if the boundary is straight along it,
    else the arc length from the first contact node."""
    import numpy as np

    x, y = contact["x"], contact["y"]
    if np.ptp(y) <= 1e-9 * max(np.ptp(x), 1e-300):
        return x, "x (m)"
    if np.ptp(x) <= 1e-9 * max(np.ptp(y), 1e-300):
        return y, "y (m)"
    s = np.concatenate([[0.0], np.cumsum(np.hypot(np.diff(x), np.diff(y)))])
    return s, "arc length along the contact boundary (m)"


def contact_intervals(t, active):
    """[(t_begin, t_end)] of the runs of active nodes, extended half a spacing either side so that
    a single active node still shows."""
    intervals = []
    n = len(t)
    j = 0
    while j < n:
        if not active[j]:
            j += 1
            continue
        k = j
        while k + 1 < n and active[k + 1]:
            k += 1
        lo = t[j] - 0.5 * (t[j] - t[j - 1]) if j > 0 else t[j]
        hi = t[k] + 0.5 * (t[k + 1] - t[k]) if k + 1 < n else t[k]
        intervals.append((min(lo, hi), max(lo, hi)))
        j = k + 1
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
    text = f"{name}: {mesh.get('nx', '?')} × {mesh.get('ny', '?')} mesh"
    if "n_dofs" in summary:
        text += f" ({summary['n_dofs']} unknowns)"
    text += f", {summary.get('method', '?')}"
    if not summary.get("converged", True):
        text += f" — NOT CONVERGED ({summary.get('termination', '?')})"
    return text


# The figures -------------------------------------------------------------------------------


def figure_displacement(plt, summary, contact):
    import numpy as np

    t, xlabel = boundary_coordinate(contact)
    values = np.concatenate([contact["u_n"], contact["u_t"], contact["gap"]])
    k = power_of_ten(values)
    scale = 10.0 ** k
    fig, ax = plt.subplots(figsize=(8, 4.5), layout="constrained")
    shade_contact(ax, contact_intervals(t, contact["pressure"] > 0))
    ax.axhline(0.0, color="0.6", lw=0.8)
    has_gap = bool(np.any(contact["gap"] != 0.0))
    ax.plot(t, contact["u_n"] / scale, color="tab:blue", lw=1.6,
            label=r"normal $u_\nu = u\cdot\nu$ ($\nu$: outward normal)" if has_gap else
            r"normal $u_\nu = u\cdot\nu$ ($\nu$ outward: $u_\nu < 0$ lifts off)")
    ax.plot(t, contact["u_t"] / scale, color="tab:green", lw=1.6,
            label=r"tangential $u_\tau = u\cdot\tau$")
    if has_gap:
        ax.plot(t, contact["gap"] / scale, color="k", lw=1.0, ls="--",
                label=r"gap $g$ (the bound: $u_\nu \leq g$)")
    ax.set_xlabel(xlabel)
    ax.set_ylabel(unit_label("displacement", k, "m"))
    ax.set_title(wrapped(title_of(summary) + "\nDisplacement along the contact boundary", 8),
                 fontsize=10)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8, loc="best")
    return fig


def figure_pressure(plt, summary, contact):
    import numpy as np

    t, xlabel = boundary_coordinate(contact)
    p = contact["pressure"]
    fig, ax = plt.subplots(figsize=(8, 4.5), layout="constrained")
    intervals = contact_intervals(t, p > 0)
    shade_contact(ax, intervals)
    ax.plot(t, p, color="tab:red", lw=1.6, label=r"contact pressure $l = -\sigma_\nu$")
    touching = p > 0
    if np.any(touching):
        ax.plot(t[touching], p[touching], "o", color="tab:red", ms=2.5,
                label=f"nodes in contact: {int(np.count_nonzero(touching))} of {len(p)}")
    ax.axhline(0.0, color="0.6", lw=0.8)
    ax.set_xlabel(xlabel)
    ax.set_ylabel("contact pressure (MPa)")
    ax.set_ylim(bottom=min(0.0, float(np.nanmin(p))) - 0.02 * max(float(np.nanmax(p)), 1e-300))
    where = ", ".join(f"{lo:.3g} to {hi:.3g} m" for lo, hi in intervals[:4])
    if len(intervals) > 4:
        where += ", ..."
    subtitle = "Contact pressure along the contact boundary"
    subtitle += f" (touching: {where})" if intervals else " (no contact)"
    ax.set_title(wrapped(title_of(summary) + "\n" + subtitle, 8), fontsize=10)
    force = summary.get("contact_force")
    if isinstance(force, (int, float)):
        ax.plot([], [], " ", label=f"total contact force {force:.4g} MN/m")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8, loc="best")
    return fig


def triangles_of(vtu):
    """Triangles of the cells (quads split along a diagonal) and the boundary edges."""
    import numpy as np

    conn, offsets, types = vtu["connectivity"], vtu["offsets"], vtu["types"]
    if len(types) and np.all(types == 9):  # quadrilaterals
        q = conn.reshape(-1, 4)
        tri = np.vstack([q[:, [0, 1, 2]], q[:, [0, 2, 3]]])
        edges = np.vstack([q[:, [0, 1]], q[:, [1, 2]], q[:, [2, 3]], q[:, [3, 0]]])
    elif len(types) and np.all(types == 5):  # triangles
        tri = conn.reshape(-1, 3)
        edges = np.vstack([tri[:, [0, 1]], tri[:, [1, 2]], tri[:, [2, 0]]])
    else:
        tri_list, edge_list = [], []
        begin = 0
        for end, kind in zip(offsets, types):
            c = conn[begin:end]
            begin = end
            if kind in (5, 9):
                tri_list += [[c[0], c[i], c[i + 1]] for i in range(1, len(c) - 1)]
                edge_list += [[c[i], c[(i + 1) % len(c)]] for i in range(len(c))]
        if not tri_list:
            raise UsageError("solution.vtu has no triangles or quadrilaterals to draw")
        tri, edges = np.array(tri_list), np.array(edge_list)
    # An edge of one cell only is on the boundary.
    key = np.sort(edges, axis=1)
    _, index, count = np.unique(key, axis=0, return_index=True, return_counts=True)
    return tri, chains_of(edges[index[count == 1]])


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


def figure_deformed(plt, summary, vtu, boundary_vtu, scale):
    import numpy as np
    from matplotlib.collections import LineCollection
    from matplotlib.tri import Triangulation

    points = vtu["points"][:, :2]
    data = vtu["point_data"]
    for name in ("displacement", "von_mises"):
        if name not in data:
            raise UsageError(f"solution.vtu has no point data '{name}'")
    u = data["displacement"][:, :2]
    vm = data["von_mises"]
    s = magnification(points, u) if scale is None else scale
    deformed = points + s * u
    tri, boundary = triangles_of(vtu)

    # The rigid foundation at x + s g nu along the contact boundary: the gap is magnified as the
    # displacement is, so that the nodes in contact lie on it.
    foundation, foundation_label = None, ""
    if boundary_vtu is not None:
        bd = boundary_vtu["point_data"]
        if "gap" in bd and "normal" in bd:
            g = bd["gap"]
            foundation = boundary_vtu["points"][:, :2] + s * g[:, None] * bd["normal"][:, :2]
            foundation_label = "rigid foundation" + (f" (gap magnified {s:g} times)"
                                                     if np.any(g) else "")

    drawn = np.vstack([points, deformed] + ([foundation] if foundation is not None else []))
    extent = points.max(axis=0) - points.min(axis=0)
    margin = 0.04 * max(extent)
    lo = drawn.min(axis=0) - margin
    hi = drawn.max(axis=0) + margin
    # The figure takes the shape of the drawing: axes of at most 7.5 x 6.5 inches, plus room for
    # the title, the legend, the labels and the colour bar.
    aspect = float((hi[1] - lo[1]) / (hi[0] - lo[0]))
    axes_width = min(7.5, 6.5 / aspect)
    width = max(8.0, axes_width + 2.6)  # room for the title of a tall body
    fig, ax = plt.subplots(figsize=(width, axes_width * aspect + 2.4), layout="constrained")
    mesh = Triangulation(deformed[:, 0], deformed[:, 1], tri)
    # Rasterised in the SVG too: 10^5 shaded triangles as vectors would make a file of 100 MB.
    # A stress singularity (a corner where a clamp meets a load) can exceed the rest of the body
    # many times over at one node; the colour scale then ends at the 99.9th percentile, so that
    # the body is not drawn in one colour, and the colour bar says so.
    top = float(np.nanmax(vm))
    clip = float(np.nanpercentile(vm, 99.9))
    clipped = top > 1.1 * clip
    image = ax.tripcolor(mesh, vm, shading="gouraud", cmap="viridis", rasterized=True,
                         vmin=float(np.nanmin(vm)), vmax=clip if clipped else top)
    ax.add_collection(LineCollection([points[c] for c in boundary], colors="0.3",
                                     linewidths=0.9, linestyles=(0, (4, 3)),
                                     label="undeformed body"))
    ax.add_collection(LineCollection([deformed[c] for c in boundary], colors="k",
                                     linewidths=0.6))

    if foundation is not None:
        ax.plot(foundation[:, 0], foundation[:, 1], color="tab:brown", lw=3, alpha=0.8,
                solid_capstyle="butt", label=foundation_label, zorder=0)
    active = data.get("contact_active")
    if active is not None and np.any(active):
        ax.plot(deformed[active == 1, 0], deformed[active == 1, 1], "o", ms=1.8,
                color="tab:orange", label="nodes in contact", zorder=3)

    ax.set_aspect("equal")
    ax.set_xlim(lo[0], hi[0])
    ax.set_ylim(lo[1], hi[1])
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    bar = fig.colorbar(image, ax=ax, shrink=0.9, extend="max" if clipped else "neither")
    bar.set_label("von Mises stress (MPa)")
    if clipped:
        at = int(np.nanargmax(vm))
        ax.plot(deformed[at, 0], deformed[at, 1], "x", color="tab:red", ms=8, mew=2, zorder=4,
                label=f"max {top:.3g} MPa at ({points[at, 0]:.3g}, {points[at, 1]:.3g}), "
                      "above the colour scale")
    fig.suptitle(wrapped(title_of(summary) + f"\nDeformed body x + s·u(x), displacements "
                         f"magnified s = {s:g} times, coloured by the von Mises stress", width),
                 fontsize=10)
    # Above the drawing, where it cannot hide a part of the body.
    ax.legend(fontsize=8, loc="lower center", bbox_to_anchor=(0.5, 1.0), frameon=False,
              ncol=4 if width >= 10 else 2)
    return fig, s


def figure_convergence(plt, summary):
    import numpy as np
    from matplotlib.ticker import MaxNLocator

    method = summary.get("method", "uzawa_gnm")
    changes = np.array([np.nan if v is None else v for v in summary.get("dual_changes", [])],
                       dtype=float)
    steps = np.arange(1, len(changes) + 1)
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.2), layout="constrained")
    outer = "Newton iteration" if method == "semismooth_newton" else "Uzawa iteration k"

    shown = np.isfinite(changes) & (changes > 0)
    if np.any(shown):
        left.semilogy(steps[shown], changes[shown], "o-", color="tab:blue", ms=4,
                      label=r"$\Vert l^k - l^{k-1}\Vert \,/\, \Vert l^k\Vert$")
    tol = summary.get("problem", {}).get("solver", {}).get("uzawa_tolerance")
    if method != "semismooth_newton" and isinstance(tol, (int, float)) and tol > 0:
        left.axhline(tol, color="tab:red", ls="--", lw=1, label=f"tolerance {tol:g}")
    left.set_xlabel(outer)
    left.set_ylabel("relative change of the contact pressure")
    left.set_title("Uzawa residual" if method != "semismooth_newton" else
                   "Change of the contact pressure (the method stops\nwhen the active set repeats)",
                   fontsize=10)
    left.grid(True, which="both", alpha=0.3)
    if len(steps) <= 30:
        left.set_xticks(steps)
    if left.get_legend_handles_labels()[0]:
        left.legend(fontsize=8)

    if method == "uzawa_gnm":
        gnm = np.array(summary.get("gnm_iterations", []), dtype=float)
        bars = right.bar(np.arange(1, len(gnm) + 1), gnm, color="tab:green")
        if len(gnm) <= 40:
            right.bar_label(bars, fmt="%d", fontsize=8)
            right.set_xticks(np.arange(1, len(gnm) + 1))
        right.set_ylabel("GNM iterations")
        right.set_title("Generalised Newton iterations per Uzawa step", fontsize=10)
        right.set_ylim(0, max(gnm.max() if len(gnm) else 1, 1) * 1.15)
    else:
        active = np.array(summary.get("active_set_sizes", []), dtype=float)
        right.plot(np.arange(1, len(active) + 1), active, "o-" if len(active) <= 50 else "-",
                   color="tab:green", ms=4)
        right.set_ylabel("nodes in the active set")
        right.set_title("Active set size per iteration", fontsize=10)
        right.yaxis.set_major_locator(MaxNLocator(integer=True))
    right.set_xlabel(outer)
    right.grid(True, axis="y", alpha=0.3)
    fig.suptitle(wrapped(title_of(summary) + f"\nConvergence: {summary.get('message', '')}", 11),
                 fontsize=10)
    return fig


# Main --------------------------------------------------------------------------------------


def save_all(outdir, figures, quiet):
    """Every file is written under a temporary name first and renamed at the end, so that a
    failure leaves no half-written picture and keeps the pictures of an earlier run."""
    import matplotlib.pyplot as plt

    temporaries = []
    try:
        for name, fig in figures:
            for fmt in FORMATS:
                final = os.path.join(outdir, f"{name}.{fmt}")
                tmp = os.path.join(outdir, f".{name}.{fmt}.tmp.{os.getpid()}")
                temporaries.append((tmp, final))
                fig.savefig(tmp, format=fmt, dpi=150)
            plt.close(fig)
        for tmp, final in temporaries:
            os.replace(tmp, final)
    except OSError as e:
        raise UsageError(f"cannot write the figures into '{outdir}': {e}")
    finally:
        for tmp, _ in temporaries:
            if os.path.exists(tmp):
                os.unlink(tmp)
    if not quiet:
        print("figures: " + ", ".join(os.path.join(outdir, f"{n}.{{png,svg}}") for n, _ in figures))


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("outdir", nargs="?", help="output folder of signorini solve")
    parser.add_argument("--scale", type=float, default=None,
                        help="magnification of the displacement in the deformed-body figure "
                             "(default: chosen so that the largest is about 10%% of the body)")
    parser.add_argument("--quiet", action="store_true", help="print nothing but errors")
    parser.add_argument("--check", action="store_true",
                        help="only check that numpy and matplotlib can be imported")
    args = parser.parse_args(argv)
    try:
        import_plotting()
        if args.check:
            return 0
        if not args.outdir:
            raise UsageError("expected the output folder of signorini solve")
        if args.scale is not None and not (math.isfinite(args.scale) and args.scale > 0):
            raise UsageError(f"--scale {args.scale}: expected a positive number")
        if not os.path.isdir(args.outdir):
            raise UsageError(f"'{args.outdir}' is not a folder")
        import matplotlib.pyplot as plt

        summary = read_summary(args.outdir)
        contact = read_contact_csv(args.outdir)
        vtu = read_vtu(os.path.join(args.outdir, "solution.vtu"))
        boundary_vtu = read_vtu(os.path.join(args.outdir, "contact.vtu"))
        figures = [("contact_displacement", figure_displacement(plt, summary, contact)),
                   ("contact_pressure", figure_pressure(plt, summary, contact))]
        fig, _ = figure_deformed(plt, summary, vtu, boundary_vtu, args.scale)
        figures.append(("deformed_von_mises", fig))
        figures.append(("convergence", figure_convergence(plt, summary)))
        save_all(args.outdir, figures, args.quiet)
    except UsageError as e:
        fail(2, e)
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main(sys.argv[1:]))
    except SystemExit:
        raise
    except BaseException as e:  # a bug: say so in one line, the traceback on request
        if os.environ.get("SIGNORINI_DEBUG"):
            raise
        fail(1, f"plot script failed: {type(e).__name__}: {e} (set SIGNORINI_DEBUG=1 for a "
                f"traceback)")
