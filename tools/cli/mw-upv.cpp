// mw-upv - flowchart step 3 (dynamic route): elastic constants from the
// ultrasonic pulse velocity test, concrete paper Eqs. (8)-(10).
//
//   mw-upv --path-mm 150 --t-p-us 35 --t-s-us 55.1 --density-kg-m3 2129.56
//   mw-upv --path-mm 150 --t-p-us 35 --nu-assumed 0.2 --density-kg-m3 2129.56
//
// With both times of flight the Poisson ratio is measured (Eq. 10) and E_d
// follows from the shear wave (Eq. 9). With the P wave alone the Poisson ratio
// must be assumed (ASTM C597: E_d = rho v_p^2 (1+nu)(1-2nu)/(1-nu)); the
// result records that it was.
#include <optional>

#include "mesowave/app/tool.hpp"
#include "mesowave/core/check.hpp"
#include "mesowave/core/units.hpp"
#include "mesowave/lab/pulse_velocity.hpp"

using namespace mesowave;

int main(int argc, char** argv) {
  app::Tool tool("mw-upv",
                 "Dynamic modulus E_d and Poisson ratio nu_d from the ultrasonic pulse velocity test (concrete paper "
                 "Eqs. 8-10): v = path / time of flight; nu_d = (0.5 r^2 - 1)/(r^2 - 1) with r = v_p/v_s; "
                 "E_d = 2 rho v_s^2 (1 + nu_d). With --nu-assumed and no --t-s-us, the ASTM C597 P-wave relation.\n\n"
                 "  mw-upv --path-mm 150 --t-p-us 35 --t-s-us 55.1 --density-kg-m3 2129.56\n"
                 "  mw-upv --from lab-data/concrete-cube/upv.toml --from results/concrete-cube/density.json");
  double path_mm = 0, t_p_us = 0, density = 0;
  std::optional<double> t_s_us, nu_assumed;
  std::filesystem::path out;
  auto& cli = tool.cli();
  cli.add_option("--path-mm", path_mm, "Distance between the transducers [mm]")->required();
  cli.add_option("--t-p-us", t_p_us, "Time of flight of the P (longitudinal) wave [us]")->required();
  cli.add_option("--t-s-us", t_s_us, "Time of flight of the S (shear) wave [us]");
  cli.add_option("--density-kg-m3", density, "Density of the specimen [kg/m3] (e.g. from mw-specimen)")->required();
  cli.add_option("--nu-assumed", nu_assumed, "Poisson ratio to assume when only the P wave was measured");
  app::add_out_option(cli, out);

  return tool.run(argc, argv, [&](app::Run& run) {
    require_positive("--path-mm", path_mm, "mm");
    require_positive("--t-p-us", t_p_us, "us");
    require_positive("--density-kg-m3", density, "kg/m3");
    if (t_s_us) require_positive("--t-s-us", *t_s_us, "us");
    if (t_s_us && nu_assumed) throw InputError("give either --t-s-us (nu_d measured) or --nu-assumed, not both");
    if (!t_s_us && !nu_assumed) throw InputError("need --t-s-us, or --nu-assumed for a P-wave-only test");

    const auto m = t_s_us ? lab::dynamic_moduli_from_p_and_s(path_mm * units::mm, t_p_us * units::us,
                                                             *t_s_us * units::us, density)
                          : lab::dynamic_moduli_from_p_only(path_mm * units::mm, t_p_us * units::us, density,
                                                            *nu_assumed);
    nlohmann::ordered_json result;
    result["path_mm"] = path_mm;
    result["t_p_us"] = t_p_us;
    if (t_s_us) result["t_s_us"] = *t_s_us;
    result["density_kg_m3"] = density;
    result["v_p_m_s"] = m.v_p_m_s;
    result["v_s_m_s"] = m.v_s_m_s;
    result["nu_d"] = m.nu_d;
    result["nu_d_source"] = t_s_us ? "measured: Eq. (10) from v_p/v_s" : "assumed (--nu-assumed)";
    result["E_d_GPa"] = m.E_d_Pa / units::GPa;
    result["G_d_GPa"] = m.G_d_Pa / units::GPa;
    result["method"] = t_s_us ? "Eqs. (9)-(10): E_d = 2 rho v_s^2 (1 + nu_d)"
                              : "ASTM C597: E_d = rho v_p^2 (1 + nu)(1 - 2 nu)/(1 - nu)";
    run.metric("v_p", m.v_p_m_s, "m/s");
    if (t_s_us) run.metric("v_s", m.v_s_m_s, "m/s");
    run.metric("nu_d", m.nu_d, "");
    run.metric("E_d", m.E_d_Pa / units::GPa, "GPa");
    run.emit_json(result, out);
  });
}
