// mw-fem - explicit linear-elastic continuum reference (the rod paper's
// Abaqus/Explicit role, Section 4.3.1): a Hann-burst force on a rod or a box,
// signals at chosen points in the mesowave signal file layout; a study's experiment
// (--experiment, experiment/experiment.hpp) places the transducers. Examples: --help.
#include "mesowave/app/tool.hpp"
#include "mesowave/fem/command.hpp"

using namespace mesowave;

int main(int argc, char** argv) {
  app::Tool tool(
      "mw-fem",
      "Explicit finite-element reference for wave signals: linear elastic, lumped mass, central differences,\n"
      "Rayleigh mass-proportional damping (M a = F - K u - alpha M v, beta = 0), a force F(t) = five-cycle Hann burst.\n"
      "rod: a solid rod along z (end faces z = 0 and z = L), axisymmetric ring elements (default; cheap) or 3D\n"
      "  hexahedra; force at the centre of the z = 0 end (or a traction patch), default sensor S at the centre of the\n"
      "  far end, as in the rod paper. box: a block of identical hexahedra (the concrete cube), force normal to the face\n"
      "  the source point lies on, sensors anywhere (component 'normal' = the outward normal of their face, as in mw-dem).\n"
      "cylinder: an --experiment's cylinder as axisymmetric rings (the actuator on the axis of its z- end).\n"
      "Elements: fully integrated trilinear hexahedra (2x2x2 Gauss) or bilinear rings; stiffness precomputed per element\n"
      "shape. The stable step comes from a rigorous eigenvalue bound of the mesh; a --dt-us above it is refused.\n\n"
      "  mw-fem rod --E-GPa 208.72 --nu 0.3 --density-kg-m3 7850.66 --radius-mm 5.1 --length-mm 1000 --mesh-mm 1 "
      "--frequency-kHz 100 --alpha-damping 2000 --signals rod.h5\n"
      "  mw-fem rod --experiment lab-data/steel-rod/experiment.toml --patch-radius-mm 0 --alpha-damping 2000 --signals rod.h5\n"
      "  mw-fem box --E-GPa 36.67 --nu 0.162 --density-kg-m3 2129.56 --size-mm 50 --mesh-mm 1 --source-mm 25,25,0 "
      "--sensor B=25,25,50 --sensor C=0,25,25 --frequency-kHz 100 --signals cube.h5\n"
      "  mw-fem --from results/concrete-cube/upv.json box --experiment lab-data/concrete-cube/experiment.toml --signals c.h5\n"
      "    (E_d, nu_d and the density from mw-upv; the cube, transducers, burst and record from the experiment)\n"
      "  mw-fem --from results/concrete-cube/upv.json box --experiment lab-data/concrete-cube/experiment.toml "
      "--frequencies-kHz 100,150,200 --signals-pattern 'fem-{f}kHz.h5' --out-pattern 'fem-{f}kHz.json'\n"
      "    (every frequency from one unit-impulse run of the mesh: the step is linear and time-invariant, so each\n"
      "    signal is the burst convolved with the impulse response - exact to round-off; fem/superposition.hpp)");
  auto& cli = tool.cli();
  cli.require_subcommand(1);
  fem::FemCommandLine values;
  auto* rod = cli.add_subcommand("rod", "Solid rod along z, force at the end z = 0");
  fem::add_common_options(*rod, values);
  fem::add_rod_options(*rod, values);
  auto* box = cli.add_subcommand("box", "Block [0,X] x [0,Y] x [0,Z], force normal to a face");
  fem::add_common_options(*box, values);
  fem::add_box_options(*box, values);
  auto* cylinder = cli.add_subcommand("cylinder", "An --experiment's cylinder: axisymmetric rings, the actuator on the axis "
                                      "of its z- end, sensors on the ends and the curved face");
  fem::add_common_options(*cylinder, values);

  return tool.run(argc, argv, [&](app::Run& run) {
    const auto body = rod->parsed() ? fem::FemBody::rod : box->parsed() ? fem::FemBody::box : fem::FemBody::cylinder;
    fem::run_fem_command(values, body, run);
  });
}
