#pragma once
// Linear-elastic isotropic solid: the material of the rod (rod paper
// Section 4.1) and of the continuum cube, and the wave speeds that follow.
//   c0 = sqrt(E / rho)                                   (1D bar)
//   cP = sqrt(E (1 - nu) / (rho (1 + nu) (1 - 2 nu)))    rod paper Eq. (3)
//   cS = sqrt(E / (2 rho (1 + nu)))                      rod paper Eq. (3)
//   cR: root of the Rayleigh equation (surface wave, the large-ka limit of L(0,1))
namespace mesowave::wave {

struct IsotropicMaterial {
  double E_Pa = 0;
  double nu = 0;
  double rho_kg_m3 = 0;
};

/// InputError unless E > 0, rho > 0 and -1 < nu < 0.5 (finite).
void validate(const IsotropicMaterial& material);

struct WaveSpeeds {
  double c0 = 0;  ///< bar velocity sqrt(E/rho)
  double cP = 0;  ///< longitudinal (dilatational) bulk wave
  double cS = 0;  ///< shear bulk wave
  double cR = 0;  ///< Rayleigh surface wave
};

WaveSpeeds wave_speeds(const IsotropicMaterial& material);

/// Lame constants [Pa].
double lame_lambda(const IsotropicMaterial& material);
double lame_mu(const IsotropicMaterial& material);

/// Rayleigh speed ratio cR / cS for Poisson ratio nu: the root in (0, 1) of
/// eta^6 - 8 eta^4 + (24 - 16 / kappa^2) eta^2 - 16 (1 - 1 / kappa^2) = 0,
/// kappa = cP / cS (the rationalised Rayleigh equation).
double rayleigh_ratio(double nu);

}  // namespace mesowave::wave
