// mw-estatic - flowchart step 3: static modulus of elasticity from the dynamic
// one by the empirical relations of concrete paper Eqs. (11)-(13), and, given a
// measured static modulus, the relative error of each: the paper's Table 1.
//
//   mw-estatic --E-d-GPa 36.68 --density-kg-m3 2129.56 --E-st-measured-GPa 27.42
//              --table table1.csv --out table1.json
#include <cmath>
#include <optional>

#include "mesowave/app/tool.hpp"
#include "mesowave/core/check.hpp"
#include "mesowave/core/format.hpp"
#include "mesowave/core/units.hpp"
#include "mesowave/io/csv.hpp"
#include "mesowave/lab/static_modulus.hpp"

using namespace mesowave;

int main(int argc, char** argv) {
  app::Tool tool("mw-estatic",
                 "Static modulus E_st from the dynamic modulus E_d (concrete paper Eqs. 11-13, Table 1): Lydon and "
                 "Balendran 0.83 E_d; BS 8110 Part 2 1.25 E_d - 19 GPa; Popovics 446.09 E_d^1.4 / rho; and their "
                 "mean. With --E-st-measured-GPa, the relative error of each against the static test.\n\n"
                 "  mw-estatic --E-d-GPa 36.68 --density-kg-m3 2129.56 --E-st-measured-GPa 27.42 --table table1.csv\n"
                 "  mw-estatic --from results/concrete-cube/upv.json --from lab-data/concrete-cube/static-test.toml");
  double E_d_GPa = 0, density = 0;
  std::optional<double> E_st_measured_GPa;
  std::filesystem::path out, table;
  auto& cli = tool.cli();
  cli.add_option("--E-d-GPa", E_d_GPa, "Dynamic modulus of elasticity [GPa] (e.g. from mw-upv)")->required();
  cli.add_option("--density-kg-m3", density, "Density [kg/m3] (Popovics' relation uses it)")->required();
  cli.add_option("--E-st-measured-GPa", E_st_measured_GPa, "Static modulus from a compression test [GPa]");
  cli.add_option("--table", table, "Write Table 1 as CSV: method, equation, formula, E_st_GPa, rel_error_pct, "
                                   "abs_rel_error_pct")
      ->type_name("FILE");
  app::add_out_option(cli, out);

  return tool.run(argc, argv, [&](app::Run& run) {
    require_positive("--E-d-GPa", E_d_GPa, "GPa");
    require_positive("--density-kg-m3", density, "kg/m3");
    if (E_st_measured_GPa) require_positive("--E-st-measured-GPa", *E_st_measured_GPa, "GPa");

    const auto estimates = lab::estimate_static_moduli(E_d_GPa * units::GPa, density);
    nlohmann::ordered_json result;
    result["E_d_GPa"] = E_d_GPa;
    result["density_kg_m3"] = density;
    if (E_st_measured_GPa) result["E_st_measured_GPa"] = *E_st_measured_GPa;
    std::vector<std::vector<std::string>> rows;
    for (const auto& e : estimates) {
      const std::string key = e.conversion ? e.conversion->key : "mean";
      const double E_st_GPa = e.E_st_Pa / units::GPa;
      result["E_st_" + key + "_GPa"] = E_st_GPa;
      run.metric("E_st_" + key, E_st_GPa, "GPa");
      std::vector<std::string> row = {e.conversion ? e.conversion->name : "mean of the three",
                                      e.conversion ? e.conversion->equation : "",
                                      e.conversion ? e.conversion->formula : "", format_fixed(E_st_GPa, 6)};
      if (E_st_measured_GPa) {
        const double error_pct = 100.0 * lab::relative_error(E_st_GPa, *E_st_measured_GPa);
        result["rel_error_" + key + "_pct"] = error_pct;
        run.metric("rel_error_" + key, error_pct, "%");
        row.push_back(format_fixed(error_pct, 5));
        row.push_back(format_fixed(std::abs(error_pct), 5));
      } else {
        row.insert(row.end(), {"", ""});
      }
      rows.push_back(row);
    }
    if (E_st_measured_GPa) rows.push_back({"static test", "", "measured", format_fixed(*E_st_measured_GPa, 6), "", ""});
    if (!table.empty())
      run.write_text(table, io::to_csv({"method", "equation", "formula", "E_st_GPa", "rel_error_pct", "abs_rel_error_pct"},
                                       rows));
    run.emit_json(result, out);
  });
}
