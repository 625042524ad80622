#include "mesowave/dem/loading/extensometer.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "mesowave/core/check.hpp"
#include "mesowave/core/error.hpp"
#include "mesowave/core/format.hpp"
#include "mesowave/core/units.hpp"
#include "mesowave/dem/scene/plugins.hpp"

namespace mesowave::dem {
namespace {

Vec3 mean_centre(const SphereStatics& statics, const std::vector<std::size_t>& group) {
  Vec3 c{};
  for (std::size_t k : group) c += statics.reference_position(k);
  return (1.0 / double(group.size())) * c;
}

}  // namespace

Extensometer::Extensometer(std::string name, const SphereStatics& statics, std::vector<std::size_t> end_a,
                           std::vector<std::size_t> end_b, const Vec3& axis, std::string axis_name,
                           std::int64_t interval_steps)
    : Sensor(std::move(name), interval_steps), axis_name_(std::move(axis_name)), a_(std::move(end_a)),
      b_(std::move(end_b)), axis_(axis) {
  const std::string who = "extensometer " + this->name();
  if (a_.empty() || b_.empty()) throw InputError(who + ": an end holds no sphere");
  for (std::size_t k : a_)
    if (std::find(b_.begin(), b_.end(), k) != b_.end())
      throw InputError(who + ": both ends hold the same sphere; make the gauge length longer or the pads smaller");
  const Vec3 ca = mean_centre(statics, a_), cb = mean_centre(statics, b_);
  gauge_m_ = dot(cb - ca, axis_);
  midpoint_ = 0.5 * (ca + cb);
  if (!(std::abs(gauge_m_) >= statics.radius(a_[0])))
    throw InputError(who + ": the ends are " + format_number(gauge_m_ * 1e3) +
                     " mm apart along the axis; an extensometer needs them at least a sphere radius apart");
}

double Extensometer::mean_displacement(const Model& model, const std::vector<std::size_t>& group) const {
  double sum = 0;
  for (std::size_t k : group) sum += dot(model.displacement(k), axis_);
  return sum / double(group.size());
}

double Extensometer::sample(const Model& model) const {
  return (mean_displacement(model, b_) - mean_displacement(model, a_)) / gauge_m_;
}

signal::Signal Extensometer::signal(double dt_s) const {
  // After step n the displacement is x_{n+1} - x_0: t0 = dt.
  return recorded("strain", "1", axis_name_, dt_s, dt_s, std::array<double, 3>{midpoint_.x, midpoint_.y, midpoint_.z});
}

std::string Extensometer::description() const {
  return "extensometer along " + axis_name_ + ", gauge length " + format_number(std::abs(gauge_m_) * 1e3) +
         " mm between " + std::to_string(a_.size()) + " and " + std::to_string(b_.size()) + " spheres, " + every();
}

signal::Signal BrokenBondCounter::signal(double dt_s) const {
  return recorded("broken_bonds", "1", "count", 0.0, dt_s);  // bonds break while the forces at x_n are computed
}

std::string BrokenBondCounter::description() const {
  return "broken bonds, " + every();
}


namespace {

// An extensometer: two pads on one face, gauge_mm apart along component and
// centred on centre_mm, or the two end spheres of a line.
void read_extensometer(SceneKeys& k, SensorSpec& spec, const std::string&, const std::vector<ActuatorSpec>&) {
  spec.component = k.text("component", "");
  static const std::set<std::string> axes = {"x", "y", "z", "line"};
  if (!axes.count(spec.component))
    throw InputError(k.where() + ": an extensometer needs component = \"x\", \"y\", \"z\" or \"line\" (its gauge axis)");
  if (k.has("between")) {
    const toml::array* a = k.get("between")->as_array();
    if (!a || a->size() != 2 || !(*a)[0].value<std::string>() || !(*a)[1].value<std::string>())
      throw InputError(k.where() + ".between must be [\"first\", \"last\"] (the end spheres of a line)");
    for (int e = 0; e < 2; ++e) {
      const std::string which = *(*a)[std::size_t(e)].value<std::string>();
      if (which != "first" && which != "last")
        throw InputError(k.where() + ".between: \"" + which + "\" must be \"first\" or \"last\"");
      spec.ends[e].kind = SphereTarget::Kind::end;
      spec.ends[e].last = which == "last";
    }
    if (spec.ends[0].last == spec.ends[1].last) throw InputError(k.where() + ".between names one sphere twice");
    return;
  }
  const SphereTarget centre = read_target(k);
  if (centre.kind != SphereTarget::Kind::patch)
    throw InputError(k.where() + ": an extensometer sits on a face (face, centre_mm, gauge_mm, patch_mm) or between the "
                     "ends of a line (between = [\"first\", \"last\"])");
  if (spec.component == "line") throw InputError(k.where() + ": component \"line\" needs between = [\"first\", \"last\"]");
  if (centre.patch.face.curved) throw InputError(k.where() + ": an extensometer sits on a flat face, not on the curved one");
  const int axis = spec.component[0] - 'x';
  if (axis == centre.patch.face.axis)
    throw InputError(k.where() + ": component " + spec.component + " is normal to face " + centre.patch.face.name() +
                     "; a face's extensometer measures along the face");
  // The pads sit gauge/2 either side of the centre, in the centre's own terms.
  const bool relative = centre.patch.relative;
  const char* key = relative ? "gauge_rel" : "gauge_mm";
  if (k.has(relative ? "gauge_mm" : "gauge_rel"))
    throw InputError(k.where() + ": centre_" + (relative ? "rel takes gauge_rel" : "mm takes gauge_mm") +
                     " (both in the same terms)");
  const double gauge = require_positive(k.where() + "." + key, k.required_number(key), relative ? "" : "mm") *
                       (relative ? 1.0 : units::mm);
  for (int e = 0; e < 2; ++e) {
    spec.ends[e] = centre;
    (relative ? spec.ends[e].patch.centre_rel : spec.ends[e].patch.centre_m)[axis] += (e == 0 ? -0.5 : 0.5) * gauge;
  }
}

}  // namespace

void register_extensometer(Plugins& p) {
  p.sensors.add({
      .name = "strain",
      .quantities = {"strain"},
      .summary = "an extensometer: the strain between two pads on a face, or between the two ends of a line",
      .keys = {{"component", "", 0, 0, "x | y | z | line: the gauge axis"},
               {"gauge_mm", "mm", 0, 1e12, "pad spacing (or gauge_rel with centre_rel)"},
               {"sample_interval_ns", "ns", 0, 1e12, "time between samples (every step)"}},
      .parse = read_extensometer,
      .targets = [](const SensorSpec& spec) {
        return std::vector<std::pair<const SphereTarget*, std::string>>{{&spec.ends[0], " (first pad)"},
                                                                        {&spec.ends[1], " (second pad)"}};
      },
      .make = [](const SensorSite& site, Placement& where) -> std::unique_ptr<Sensor> {
        const SensorSpec& sensor = site.spec;
        const Vec3 axis = direction_vector(sensor.component, sensor.target, "sensor " + sensor.name, site.line);
        where.kind = "strain";
        where.spheres = packing_indices(site.statics, site.groups[0]);
        where.direction = axis;
        where.spheres_b = packing_indices(site.statics, site.groups[1]);
        return std::make_unique<Extensometer>(sensor.name, site.statics, site.groups[0], site.groups[1], axis,
                                              sensor.component, site.every);
      },
  });
  p.sensors.add({
      .name = "broken_bonds",
      .quantities = {"broken_bonds"},
      .summary = "the number of broken bonds",
      .keys = {{"sample_interval_ns", "ns", 0, 1e12, "time between samples (every step)"}},
      .parse = [](SceneKeys&, SensorSpec&, const std::string&, const std::vector<ActuatorSpec>&) {},
      .targets = [](const SensorSpec&) { return std::vector<std::pair<const SphereTarget*, std::string>>{}; },
      .make = [](const SensorSite& site, Placement& where) -> std::unique_ptr<Sensor> {
        where.kind = "broken bonds";
        return std::make_unique<BrokenBondCounter>(site.spec.name, site.every);
      },
  });
}

}  // namespace mesowave::dem
