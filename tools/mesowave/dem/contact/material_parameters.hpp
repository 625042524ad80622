#pragma once
// The one table of the DEM material parameters: each parameter's scene key
// (the unit in its name), the paper's symbol, its range, mw-dem's option that
// overrides it and its key in the run report. The scene parser
// (scene.cpp), mw-dem's and mw-calibrate's options and the run report
// (run_report.cpp) all read this table, so a parameter has one name
// everywhere: the contact modulus is E_dem (E_dem_GPa in files, --E-dem-GPa on
// the command line, E_dem_Pa in code and in the run report).
// A contact law's own parameters (cohesive_moment's alpha_kr ...) are listed
// by the law (plugins.hpp ContactLaw::parameters).
#include <string>
#include <vector>

#include "mesowave/dem/contact/material.hpp"

namespace mesowave::dem {

struct MaterialParameter {
  std::string key;         ///< scene [material] key: E_dem_GPa
  std::string symbol;      ///< the papers' symbol: E_dem
  std::string unit;        ///< of the key's value: GPa
  bool positive = false;   ///< the range: > 0 (and finite), else [min, max]
  double min = 0, max = 0;
  std::string option;      ///< mw-dem's overriding option (--E-dem-GPa); "" if none
  std::string report_key;  ///< the run report's key (SI): E_dem_Pa
  std::string meaning;     ///< one line, with its equation
  double CohesiveFrictionalMaterial::*field = nullptr;  ///< where it lives (SI)
  double (*to_si)(double) = nullptr;                    ///< the key's unit to SI
};

/// Every shared [material] parameter, in the order of the scene files and the run report.
const std::vector<MaterialParameter>& material_parameters();
/// The entry of `key`; InputError naming `who` for an unknown key.
const MaterialParameter& material_parameter(const std::string& key, const std::string& who = "material key");

}  // namespace mesowave::dem
