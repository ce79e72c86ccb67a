#pragma once
// Every key of a problem file (docs/problem-format.md), table by table, declared once
// (core/option_table.hpp): the tables of ProblemSpec's own sections here, [solver] and
// [solver.linear] beside their structs. The reader, the unknown-key check, the effective
// settings, summary.json and the generated tables of the docs all take their keys from these.

#include <string>
#include <utility>
#include <vector>

#include "signorini/core/option_table.hpp"
#include "signorini/problem/problem_spec.hpp"

namespace signorini {

/// name, units (and the sections, which are tables of their own).
[[nodiscard]] const OptionTable<ProblemSpec>& top_level_options();
[[nodiscard]] const OptionTable<ProblemSpec>& mesh_options();
[[nodiscard]] const OptionTable<ProblemSpec>& material_options();
/// Whether mesh.cell is a cell of the mesh type (a hexahedron or tetrahedron for a box, a
/// quadrilateral or triangle for a rectangle): mesh.cell takes the names of both.
[[nodiscard]] bool cell_fits_mesh(const ProblemSpec& spec);
/// The dimension of the problem as its file states it: 2 for a rectangle, 3 for a box, for a
/// Gmsh mesh what its keys imply (0: nothing yet; the mesh decides when it is read).
[[nodiscard]] int stated_dimension(const ProblemSpec& spec);
[[nodiscard]] const OptionTable<ProblemSpec>& fem_options();
// Sections of formulas and lists, read by their own readers (input/problem_file.cpp): their keys
// and docs are declared here all the same, so that the unknown-key check and the docs know them.
[[nodiscard]] const OptionTable<ProblemSpec>& region_options();
[[nodiscard]] const OptionTable<ProblemSpec>& clamp_options();
[[nodiscard]] const OptionTable<ProblemSpec>& displacement_options();
[[nodiscard]] const OptionTable<ProblemSpec>& traction_options();
[[nodiscard]] const OptionTable<ProblemSpec>& pressure_options();
[[nodiscard]] const OptionTable<ProblemSpec>& point_load_options();
[[nodiscard]] const OptionTable<ProblemSpec>& body_force_options();
[[nodiscard]] const OptionTable<ProblemSpec>& contact_options();

/// Every table of a problem file, in the order of the file and the docs, [solver] and
/// [solver.linear] included. A table's subtables are the tables whose path extends its own.
[[nodiscard]] const std::vector<const OptionTableInfo*>& problem_schema();

/// The keys and values of [contact] as a file gives them: the boundary, then `gap` (the text
/// `gap_text`) or the obstacle's shape and geometry, points and vectors with `dim` coordinates
/// (a cylinder's with 3). The effective settings and summary.json write these.
[[nodiscard]] std::vector<std::pair<std::string, OptionValue>> contact_values(
    const ContactSpec& contact, const std::string& gap_text, int dim);
/// The keys and values of one [[displacement]]: the boundary, then `normal` or the components
/// given (x, y, z), as texts.
[[nodiscard]] std::vector<std::pair<std::string, OptionValue>> displacement_values(
    const DisplacementSpec& displacement);
/// The keys and values of one [[pressure]]: the boundary and p (its text).
[[nodiscard]] std::vector<std::pair<std::string, OptionValue>> pressure_values(
    const PressureSpec& pressure);
/// The keys and values of one [[region]]: name, E, nu.
[[nodiscard]] std::vector<std::pair<std::string, OptionValue>> region_values(
    const RegionMaterialSpec& region);

/// The value of every option that a table reaches in `spec` and that applies there (not mesh.nx
/// for a Gmsh mesh) ("solver.linear.type", "cg"), in
/// the order of problem_schema(): what two specs are compared by.
[[nodiscard]] std::vector<std::pair<std::string, OptionValue>> option_values(
    const ProblemSpec& spec);

}  // namespace signorini
