#pragma once
// A complete description of a contact problem, independent of any file format: what a problem
// file says, in library terms. input/problem_file.hpp builds one from TOML; C++ users fill it in
// directly.

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "signorini/contact/contact_solver_options.hpp"
#include "signorini/fem/elasticity_assembly.hpp"
#include "signorini/fem/load_assembly.hpp"
#include "signorini/fem/vector_field.hpp"
#include "signorini/interface/rigid_obstacle.hpp"
#include "signorini/mesh/box_mesh.hpp"
#include "signorini/mesh/mesh.hpp"
#include "signorini/mesh/rectangle_mesh.hpp"

namespace signorini {

/// u_k = 0 on a boundary part for the components marked true (method.md section 1, Gamma_D).
struct ClampSpec {
  std::string boundary;
  std::array<bool, 3> components{true, true, true};
  /// A pinned node instead of a whole part: the node nearest to this point (on `boundary` when
  /// that is given too), as a point load is placed.
  std::optional<Point> at = std::nullopt;
  /// What the reactions call it: the boundary, or "at (x, y)" for a pinned node.
  [[nodiscard]] std::string name() const;
};

/// u_k = value_k(x) on a boundary part for the components given (a prescribed displacement, a
/// nonzero clamp), or u . n = normal(x) along the part's outward normal n (method.md section 1,
/// Gamma_D with nonzero data). A [[clamp]] wins over a [[displacement]] at a dof both hold; among
/// displacements the first entry wins.
struct DisplacementSpec {
  std::string boundary;
  /// One field per component (x, y, z); empty: that component is free.
  std::array<ScalarField, 3> values;
  std::array<std::string, 3> texts;  ///< how each was given ("-0.01", "0.001*x"), for reports
  /// The normal component alone (empty: not prescribed); it excludes `values`. Along the
  /// nodal outward normal n: on a side parallel to an axis that component, elsewhere in local
  /// axes (n, t) per node (DofMap::set_frame); a node with one component held already gets the
  /// other from u . n, a corner of two normal entries both.
  ScalarField normal;
  std::string normal_text;
  /// Its own load factors, one per step of the loading history (ProblemSpec::load_factors);
  /// empty: it follows the history's.
  std::vector<double> factors = {};
};

/// A pressure p(x) normal to a boundary part: the traction -p n, n the outward unit normal at
/// each quadrature point (so along curved quadratic edges it follows the curve); p > 0 pushes
/// into the body.
struct PressureSpec {
  std::string boundary;
  ScalarField p;
  std::string text;                  ///< how p was given, for reports
  std::vector<double> factors = {};  ///< as DisplacementSpec::factors
};

/// sigma(u) n = p on a boundary part (Gamma_N), or on the part of it inside `region`.
struct TractionSpec {
  std::string boundary;
  VectorField p;
  std::string description;           ///< how p was given (e.g. the expressions), for reports
  CoordinateBox region;              ///< unbounded: the whole boundary part
  std::vector<double> factors = {};  ///< as DisplacementSpec::factors
};

/// A force at one mesh node: the node nearest to `at` (on `boundary` if it is not empty). In 2D
/// a force per unit thickness, as the tractions are per unit area.
struct PointLoadSpec {
  Point at = Point::Zero();
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  std::string boundary;
  std::vector<double> factors = {};  ///< as DisplacementSpec::factors
};

/// The friction law of a contact boundary (docs/method.md, "Friction").
enum class FrictionModel { None, Tresca, Coulomb };

inline constexpr EnumNames<FrictionModel, 3> kFrictionModelNames{{
    {FrictionModel::None, "none"},
    {FrictionModel::Tresca, "tresca"},
    {FrictionModel::Coulomb, "coulomb"},
}};

/// Possible contact with the rigid foundation on a boundary part (Gamma_K), initial gap g(x).
struct ContactSpec {
  std::string boundary;
  /// The initial gap g(x) along the normal, for obstacle.shape = Gap (the paper's).
  ScalarField gap = [](const Point&) { return 0.0; };
  std::string description = "0";
  /// The rigid partner: a gap formula (`gap` above), a half-plane or a disc.
  RigidObstacle obstacle;
  /// The body's outward normal at a point of the boundary, where its geometry is known (a
  /// sphere, a cylinder: any length, normalised at each node); empty: the normals averaged from
  /// the facets (docs/method.md section 3).
  VectorField surface_normal;
  std::vector<std::string> surface_normal_text;  ///< as the file gave it
  /// Friction on this boundary: none (the paper's), Tresca's with the slip bound s(x) (a
  /// stress, >= 0), or Coulomb's with the coefficient mu (>= 0).
  FrictionModel friction = FrictionModel::None;
  ScalarField slip_bound = [](const Point&) { return 0.0; };
  std::string slip_bound_text = "0";
  double mu = 0.0;
};

/// A region of the mesh (a Gmsh physical surface, by name) with a material of its own.
struct RegionMaterialSpec {
  std::string region;
  IsotropicMaterial material;
};

/// Where the mesh comes from: the structured rectangle (2D), a Gmsh file (2D or 3D), the
/// structured box (3D), or a mesh the program gives (ProblemSpec::given_mesh: arrays from Python
/// or C++, mesh/mesh_arrays.hpp), which no problem file can name.
enum class MeshType { Rectangle, Gmsh, Box, Given };

/// The mesh types a problem file's [mesh] type may name.
inline constexpr EnumNames<MeshType, 3> kMeshTypeNames{{
    {MeshType::Rectangle, "rectangle"},
    {MeshType::Gmsh, "gmsh"},
    {MeshType::Box, "box"},
}};

/// The structured meshes, made from a few numbers (the keys of [mesh]).
constexpr bool is_structured(MeshType t) {
  return t == MeshType::Rectangle || t == MeshType::Box;
}

/// The dimension that a key of a problem file implies: a point or vector of 3 numbers, component
/// z or a cylinder a 3D problem; x_range a 2D one. A file on a Gmsh mesh cannot know the mesh's
/// dimension before the mesh is read, so its reader records the first key that implies one
/// (later keys must agree with it), and build_model checks it against the mesh, in one line
/// naming the key. (With a rectangle or a box the reader checks every key itself.)
struct ImpliedDimension {
  int dimension = 0;    ///< 2 or 3; 0: no key implied one
  std::string key;      ///< "traction[0].p"
  std::string given;    ///< what the key gives: "3 components"
  std::string instead;  ///< what a problem of the other dimension expects: "2 components (x, y)"
};

struct ProblemSpec {
  std::string name = "problem";
  /// The units the numbers are in, for labels only (e.g. "m-MPa"; empty: not said). The solver
  /// needs none: any consistent set works (method.md section 7).
  std::string units;
  /// [mesh] type: the structured rectangle of `mesh`, or a Gmsh file (`mesh_file`).
  MeshType mesh_type = MeshType::Rectangle;
  RectangleMeshOptions mesh;  ///< the rectangle (mesh_type = Rectangle)
  BoxMeshOptions box;         ///< the box (mesh_type = Box), a 3D mesh
  /// The .msh file (or a .geo file, meshed by the gmsh program) for mesh_type = Gmsh; the
  /// problem-file reader makes a relative path relative to the problem file's folder.
  std::string mesh_file;
  /// The mesh for mesh_type = Given (read_problem_file's `mesh`, or set in C++).
  std::shared_ptr<const Mesh> given_mesh;
  /// What a problem file's keys say the dimension is, for build_model to check against the
  /// mesh (ImpliedDimension). Empty in specs built in C++.
  ImpliedDimension implied_dimension;
  ElasticityOptions elasticity;  ///< `material` is that of every cell not in region_materials
  std::vector<RegionMaterialSpec> region_materials;
  int boundary_gauss_points = 2;  ///< Gauss points per boundary facet for tractions
  std::vector<ClampSpec> clamps;
  std::vector<DisplacementSpec> displacements;
  std::vector<TractionSpec> tractions;
  std::vector<PressureSpec> pressures;
  std::vector<PointLoadSpec> point_loads;
  VectorField body_force;  ///< empty: no body force
  std::string body_force_description;
  std::vector<double> body_force_factors;  ///< as DisplacementSpec::factors
  /// The contact boundaries, each with its obstacle (at least one); their nodes form one
  /// contact set, in this order.
  std::vector<ContactSpec> contacts;
  /// [loading]: the load factors of a loading history, each applied to every load and
  /// prescribed displacement (not to the gaps), solved in turn and each step warm-started from
  /// the last (friction's answer depends on the path). Empty: one solve at factor 1. A load or
  /// displacement entry with `factors` of its own (as many) follows those instead: a body
  /// pressed first and then sheared.
  std::vector<double> load_factors;
  ContactSolverOptions solver;
};

/// The paper's benchmark (Section 5, method.md section 5) on an nx x ny mesh.
ProblemSpec paper_benchmark(Index nx = 60, Index ny = 20);

}  // namespace signorini
