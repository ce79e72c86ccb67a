#pragma once
// Isotropic linear elasticity (method.md section 1) and its 2D reductions.

#include <Eigen/Core>

#include "signorini/core/enum_names.hpp"

namespace signorini {

/// How a 2D problem stands for a 3D body: plane strain (eps_zz = 0, a long body; the paper's
/// convention, see method.md "Conventions") or plane stress (sigma_zz = 0, a thin plate).
enum class PlaneModel { PlaneStrain, PlaneStress };

inline constexpr EnumNames<PlaneModel, 2> kPlaneModelNames{{
    {PlaneModel::PlaneStrain, "plane_strain"},
    {PlaneModel::PlaneStress, "plane_stress"},
}};

struct IsotropicMaterial {
  double E = 21.19e4;  ///< Young's modulus (MPa in the paper's units), > 0
  double nu = 0.277;   ///< Poisson's ratio, in (-1, 0.5)
};

/// Throws InputError unless E > 0 and -1 < nu < 0.5 (both finite).
void validate(const IsotropicMaterial& material);

/// The 3x3 matrix D with (s_xx, s_yy, s_xy) = D (e_xx, e_yy, 2 e_xy).
Eigen::Matrix3d plane_elasticity_matrix(const IsotropicMaterial& material, PlaneModel model);

/// The 6x6 matrix D of a 3D body with (s_xx, s_yy, s_zz, s_yz, s_xz, s_xy) = D (e_xx, e_yy, e_zz,
/// 2 e_yz, 2 e_xz, 2 e_xy) (Voigt order): Hooke's law sigma = lambda tr(e) I + 2 mu e.
Eigen::Matrix<double, 6, 6> elasticity_matrix_3d(const IsotropicMaterial& material);

}  // namespace signorini
