#pragma once
// Critical time step of the explicit (leapfrog) integration for the actual
// packing. Three numbers, from cheapest to sharpest:
//  - the concrete paper's estimate dt = min_i R_i sqrt(rho/E) (Section 4.2;
//    Yade's PWaveTimeStep computes the same);
//  - a stiffness bound 2/sqrt(lambda_G), lambda_G the largest absolute row sum
//    (Gershgorin) of M^-1/2 K M^-1/2 over all six DOFs of every sphere: never
//    above the true limit (in the spirit of Yade's GlobalStiffnessTimeStepper);
//  - the eigenvalue limit 2/sqrt(lambda_max), lambda_max of M^-1/2 K M^-1/2 by
//    Lanczos iteration plus its residual bound.
// Leapfrog is stable for dt < 2/sqrt(lambda_max) (undamped); local damping
// scales an acceleration by up to (1 + alpha_d), so the step refused is the one
// above 2/sqrt((1 + alpha_d) lambda_max).
#include "mesowave/core/lanczos.hpp"  // largest_eigenvalue: the Lanczos iteration
#include "mesowave/dem/engine/model.hpp"

namespace mesowave::dem {

struct CriticalTimeStep {
  double paper_estimate_s = 0;   ///< min R sqrt(rho/E)
  double stiffness_bound_s = 0;  ///< 2 / sqrt(Gershgorin bound): a safe step
  double eigenvalue_s = 0;       ///< 2 / sqrt(lambda_max): the undamped stability limit
  double lambda_max = 0;         ///< largest eigenvalue of M^-1/2 K M^-1/2 [1/s^2], walls included
  double boundary_lambda = 0;    ///< what walls add to it at most (largest k_w / m) [1/s^2]
  double limit_s = 0;            ///< eigenvalue_s / sqrt(1 + alpha_d): larger steps are refused
  int lanczos_iterations = 0;
};

/// `min_radius_m`, `density`, `E_dem_Pa` feed the paper's estimate.
CriticalTimeStep critical_time_step(const Model& model, double min_radius_m, double density_kg_m3, double E_dem_Pa,
                                    double damping);

}  // namespace mesowave::dem

