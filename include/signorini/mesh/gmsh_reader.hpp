#pragma once
// Meshes from Gmsh's .msh files, formats 4.1 and 2.2, ASCII and binary, read by our own code (Gmsh
// is GPL: the library is never linked; the `gmsh` program may make the files).
//
// What becomes what (the highest element dimension in the file decides between 2D and 3D):
//   - 2D elements (3- and 6-node triangles, 4-, 8- and 9-node quadrilaterals, mixed) are the
//     cells, whether or not they are in a physical group; a cell in a physical surface gets that
//     group's name as its region (the first group, if it is in several), others region "";
//   - 2- and 3-node lines in a physical curve become a boundary part of that name, each line
//     matched to the edge of the cell it bounds (and oriented with the cell: outward normal);
//     lines in no physical group are ignored, as are points;
//   - where there are 3D elements (4- and 10-node tetrahedra, 8- and 27-node hexahedra, mixed),
//     the mesh is 3D: they are the cells, with regions from physical volumes; triangles and
//     quadrilaterals in a physical surface become its boundary part, each matched to the face of
//     a cell with the same corners (and oriented with the cell); 2D elements in no physical group
//     and lines are ignored;
//   - a physical group without a name in $PhysicalNames is named by its number ("3");
//   - nodes are numbered 0, 1, ... in the order of their tags, leaving out nodes no cell uses;
//   - cells that Gmsh made clockwise (a surface whose normal points to -z) are turned
//     counterclockwise, the node order mirrored; a cell that is folded (det J of both signs) is
//     left as it is and refused by the assembly, named by its element tag. 3D cells must have
//     det J > 0 at every corner (Gmsh writes them so).
// Errors (InputError) name the file and the line (ASCII) or byte offset (binary), or the element
// tag: an unsupported element type, a node used but not defined, a line that is not an edge of
// any cell, a surface element that is not a face of any cell, a non-planar 2D mesh, a 3D cell
// inverted or degenerate, a truncated file or section.

#include <filesystem>
#include <string>

#include "signorini/mesh/mesh.hpp"

namespace signorini {

/// Reads a .msh file. Throws InputError as above.
Mesh read_gmsh_mesh(const std::filesystem::path& file);
/// The same from the text of a file (`name` for messages).
Mesh parse_gmsh_mesh(const std::string& content, const std::string& name);

/// A mesh file as [mesh] file names it: a .geo file is meshed by the `gmsh` program (`gmsh -3`:
/// volumes where the geometry has them, else its surfaces; found on PATH; a clear InputError where
/// it is not installed or fails) into a temporary .msh, which is read and removed; any other file
/// is read as a .msh.
Mesh read_mesh_file(const std::filesystem::path& file);

}  // namespace signorini
