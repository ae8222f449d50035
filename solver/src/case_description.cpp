#include "lituya/solver/case_description.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>
#include <utility>

#include "lituya/common/input_error.hpp"

namespace lituya::solver {

namespace {
constexpr double kPi = 3.14159265358979323846;

toml::array to_array(const std::vector<std::string>& v) {
  toml::array a;
  for (const auto& s : v) a.push_back(s);
  return a;
}
}  // namespace

namespace {

// The keys of a water material: eqs. (7), (8) and (17) need rho_w, K_w and mu.
Material read_water(const TomlTable& t, Material m) {
  for (const char* k :
       {"solid_density", "porosity", "youngs_modulus", "poisson_ratio", "friction_angle",
        "dilatancy_angle", "cohesion", "tensile_strength", "grain_diameter", "max_porosity"})
    if (t.has(k))
      t.fail(std::string("'") + k + "' is a soil parameter; material '" + m.name +
                 "' is water (keys: density, bulk_modulus, viscosity)",
             k);
  for (const char* k : {"density", "bulk_modulus", "viscosity"})
    if (!t.has(k))
      t.fail("water material '" + m.name + "' is missing '" + k +
             "' (water needs density in kg/m3, bulk_modulus in Pa and viscosity in Pa s)");
  m.liquid_density = t.number_in("density", 1e-6, 1e6);
  m.bulk_modulus = t.number_in("bulk_modulus", 1e-3, 1e15);
  m.viscosity = t.number_in("viscosity", 0.0, 1e9);
  t.finish();
  return m;
}

}  // namespace

Material read_material(const TomlTable& t) {
  Material m;
  // Material names reach regions, post.toml, sweep keys and messages, and may name files
  // later (per-material output): the same safe alphabet as stage names, so a material named
  // "" or "a\nb" is refused at the line that names it instead of breaking something later.
  m.name = t.safe_name("name");
  std::string model = t.choice("model", {"mohr-coulomb", "linear-elastic", "water"});
  if (model == "water") {
    m.model = MaterialModel::kWater;
    return read_water(t, m);
  }
  for (const char* k : {"density", "bulk_modulus", "viscosity"})
    if (t.has(k))
      t.fail(std::string("'") + k + "' is a water parameter; material '" + m.name + "' is " +
                 model + " (a soil's grain density is 'solid_density')",
             k);
  m.model = model == "mohr-coulomb" ? MaterialModel::kMohrCoulomb : MaterialModel::kLinearElastic;
  m.solid_density = t.number_in("solid_density", 1e-6, 1e6);
  if (!t.has("porosity")) t.fail("material '" + m.name + "' is missing 'porosity' (in (0, 1))");
  m.porosity = t.number("porosity");
  if (!(m.porosity > 0 && m.porosity < 1))
    t.fail("'porosity' of material '" + m.name + "' must lie in (0, 1)", "porosity");
  m.youngs_modulus = t.number_in("youngs_modulus", 1e-9, 1e15);
  m.poisson_ratio = t.number_in("poisson_ratio", 0.0, 0.4999);
  if (m.model == MaterialModel::kMohrCoulomb) {
    m.friction_angle = t.number_in("friction_angle", 0.0, 89.0);
    m.dilatancy_angle = t.number_in_or("dilatancy_angle", 0.0, m.friction_angle, 0.0);
    m.cohesion = t.number_in_or("cohesion", 0.0, 1e15, 0.0);
    const double tan_phi = std::tan(m.friction_angle * kPi / 180.0);
    const double apex = tan_phi > 0 ? m.cohesion / tan_phi : 1e300;
    m.tensile_strength = t.number_in_or("tensile_strength", 0.0, apex * (1 + 1e-12), apex);
  } else {
    for (const char* k : {"friction_angle", "dilatancy_angle", "cohesion", "tensile_strength"})
      if (t.has(k))
        t.fail(std::string("'") + k + "' is a Mohr-Coulomb parameter; material '" + m.name +
                   "' is linear-elastic",
               k);
  }
  m.grain_diameter = t.number_in_or("grain_diameter", 1e-9, 10.0, 0.0);
  if (t.has("max_porosity")) {
    m.max_porosity = t.number("max_porosity");
    if (!(m.max_porosity > m.porosity && m.max_porosity <= 1))
      t.fail("'max_porosity' (n_max) of material '" + m.name +
                 "' must lie above its initial porosity " + std::to_string(m.porosity) +
                 " and at most 1",
             "max_porosity");
  }
  t.finish();
  return m;
}

BoundaryCondition read_boundary(const TomlTable& t, int dimension) {
  BoundaryCondition b;
  b.group = t.string("group");
  b.name = t.string_or("name", b.group);
  std::string type = t.choice("type", {"fixed", "roller", "contact", "fixity", "traction"});
  b.type = type == "fixed"     ? BoundaryType::kFixed
           : type == "roller"  ? BoundaryType::kRoller
           : type == "contact" ? BoundaryType::kContact
           : type == "fixity"  ? BoundaryType::kFixity
                               : BoundaryType::kTraction;
  if (b.type == BoundaryType::kTraction) {
    b.traction = t.numbers("traction");
    if (static_cast<int>(b.traction.size()) != dimension)
      t.fail("'traction' must have " + std::to_string(dimension) + " components (Pa)", "traction");
    b.ramp_time = t.number_in_or("ramp_time", 0.0, 1e9, 0.0);
    b.phase = t.choice_or("phase", {"solid", "liquid"}, "solid") == "solid"
                  ? BoundaryPhase::kSolid
                  : BoundaryPhase::kLiquid;
  } else {
    for (const char* k : {"traction", "ramp_time"})
      if (t.has(k)) t.fail(std::string("'") + k + "' applies only to type = \"traction\"", k);
    const std::string phase = t.choice_or("phase", {"both", "solid", "liquid"}, "both");
    b.phase = phase == "both"    ? BoundaryPhase::kBoth
              : phase == "solid" ? BoundaryPhase::kSolid
                                 : BoundaryPhase::kLiquid;
  }
  if (b.type == BoundaryType::kContact) {
    if (t.has("rough") && t.has("friction"))
      t.fail(
          "give either 'friction' (a Coulomb coefficient) or 'rough' (the soil whose strength "
          "sets it), not both",
          "rough");
    b.friction = t.number_in_or("friction", 0.0, 10.0, 0.0);
    b.rough = t.string_or("rough", "");
  } else {
    for (const char* k : {"friction", "rough"})
      if (t.has(k)) t.fail(std::string("'") + k + "' applies only to type = \"contact\"", k);
  }
  if (b.type == BoundaryType::kFixity) {
    for (const std::string& d : t.strings("directions")) {
      int axis = d == "x" ? 0 : d == "y" ? 1 : d == "z" ? 2 : -1;
      if (axis < 0 || axis >= dimension)
        t.fail("direction \"" + d + "\" is not one of the " + std::to_string(dimension) +
                   "D axes (\"x\", \"y\"" + (dimension == 3 ? ", \"z\")" : ")"),
               "directions");
      b.directions.push_back(axis);
    }
    if (b.directions.empty()) t.fail("'directions' must name at least one axis", "directions");
  } else if (t.has("directions")) {
    t.fail("'directions' applies only to type = \"fixity\"", "directions");
  }
  t.finish();
  return b;
}

Stage read_stage(const TomlTable& t) {
  Stage s;
  // The output writer names files after the stage (<stage>_points.pvd): checked here, for
  // scene.toml and for a hand-edited stages.toml alike, and not at the first write.
  s.name = t.safe_name("name");
  std::string type = t.choice("type", {"quasi-static", "dynamic"});
  s.type = type == "quasi-static" ? StageType::kQuasiStatic : StageType::kDynamic;
  s.duration = t.number_in("duration", 1e-12, 1e9);
  s.courant = t.number_in_or("courant", 1e-6, 1.0, 0.5);
  s.damping = t.number_in_or("damping", 0.0, 0.99, s.type == StageType::kQuasiStatic ? 0.7 : 0.0);
  s.output_interval = t.number_in_or("output_interval", 0.0, 1e9, 0.0);
  s.boundaries = t.strings_or("boundaries", {});
  if (s.type == StageType::kQuasiStatic) {
    s.kinetic_energy_ratio = t.number_in_or("kinetic_energy_ratio", 0.0, 1.0, 0.0);
    s.reset_displacement = t.boolean_or("reset_displacement", true);
  } else {
    for (const char* k : {"kinetic_energy_ratio", "reset_displacement"})
      if (t.has(k)) t.fail(std::string("'") + k + "' applies only to type = \"quasi-static\"", k);
    s.reset_displacement = false;
  }
  t.finish();
  return s;
}

SolverSettings read_solver_settings(const TomlTable& t) {
  SolverSettings s;
  s.scheme = t.choice_or("scheme", {"musl", "usl"}, "musl") == "musl" ? TransferScheme::kMUSL
                                                                      : TransferScheme::kUSL;
  if (t.has("flip_fraction")) s.flip_fraction = t.number_in_or("flip_fraction", 0.0, 1.0, 0.0);
  for (auto [key, time] : {std::pair{"pic_damping_time", &s.pic_damping_time},
                           std::pair{"liquid_pic_damping_time", &s.liquid_pic_damping_time}}) {
    if (!t.has(key)) continue;
    if (s.flip_fraction)
      t.fail(std::string("give either 'flip_fraction' (a share per step) or '") + key +
                 "' (a damping time in seconds), not both",
             key);
    *time = t.number_in_or(key, 1e-12, 1e9, 1.0);
  }
  if (t.has("liquid_xpic_order")) {
    const long long order = t.integer_or("liquid_xpic_order", 1);
    if (order < 1 || order > 8)
      t.fail("'liquid_xpic_order' must be an integer in [1, 8] (1 = the plain PIC blend)",
             "liquid_xpic_order");
    s.liquid_xpic_order = static_cast<int>(order);
  }
  s.max_velocity = t.number_in_or("max_velocity", 1e-9, 1e9, s.max_velocity);
  s.volumetric_smoothing = t.boolean_or("volumetric_smoothing", s.volumetric_smoothing);
  if (t.has("pressure_projection_interval") && t.has("pressure_projection_time"))
    t.fail(
        "give either 'pressure_projection_interval' (steps) or 'pressure_projection_time' "
        "(seconds), not both",
        "pressure_projection_time");
  if (t.has("pressure_projection_interval")) {
    const long long interval = t.integer_or("pressure_projection_interval", 0);
    if (interval < 0 || interval > 1000000)
      t.fail("'pressure_projection_interval' must be a number of steps in [0, 1000000] (0 = off)",
             "pressure_projection_interval");
    s.pressure_projection_interval = static_cast<int>(interval);
  }
  if (t.has("pressure_projection_time"))
    s.pressure_projection_time = t.number_in_or("pressure_projection_time", 1e-12, 1e9, 1.0);
  s.pore_volume_projection = t.boolean_or("pore_volume_projection", s.pore_volume_projection);
  s.liquid_pressure = t.choice_or("liquid_pressure", {"points", "nodal_fit"}, "points") == "points"
                          ? LiquidPressure::kPoints
                          : LiquidPressure::kNodalFit;
  s.pore_pressure_cell_measure =
      t.choice_or("pore_pressure_cell_measure", {"soil", "water"}, "soil") == "soil"
          ? PorePressureMeasure::kSoil
          : PorePressureMeasure::kWater;
  s.free_water_cell_volume = t.boolean_or("free_water_cell_volume", s.free_water_cell_volume);
  s.crossed_pressure_filter = t.boolean_or("crossed_pressure_filter", s.crossed_pressure_filter);
  s.liquid_advection = t.choice_or("liquid_advection", {"velocity", "flux"}, "velocity") == "flux"
                           ? LiquidAdvection::kFlux
                           : LiquidAdvection::kVelocity;
  s.liquid_landing = t.choice_or("liquid_landing", {"merge", "keep_velocity"}, "merge") == "merge"
                         ? LiquidLanding::kMerge
                         : LiquidLanding::kKeepVelocity;
  s.liquid_bulk_viscosity =
      t.number_in_or("liquid_bulk_viscosity", 0.0, 1.0, s.liquid_bulk_viscosity);
  // Fractions of a minute are allowed: tests checkpoint a run of seconds.
  s.checkpoint_interval_minutes =
      t.number_in_or("checkpoint_interval_minutes", 0.0, 1e7, s.checkpoint_interval_minutes);
  t.finish();
  return s;
}

bool OutputSettings::writes(const std::vector<std::string>& fields,
                            const std::string& field) const {
  return std::find(fields.begin(), fields.end(), field) != fields.end();
}

namespace {
// A field list of [output]: every name must be one the point set (or grid) has, once. The
// message lists the known names, so a typo is fixed at once.
std::vector<std::string> read_field_list(const TomlTable& t, const std::string& key,
                                         const std::string& what,
                                         const std::vector<std::string>& known) {
  if (!t.has(key)) return known;
  std::vector<std::string> fields = t.strings(key);
  std::string list;
  for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
  for (std::size_t i = 0; i < fields.size(); ++i) {
    if (std::find(known.begin(), known.end(), fields[i]) == known.end())
      t.fail("unknown " + what + " field \"" + fields[i] + "\" in '" + key + "' (known: " + list +
                 (what == "grid" ? "" : "; the point 'id' is always written") + ")",
             key);
    if (std::find(fields.begin(), fields.begin() + i, fields[i]) != fields.begin() + i)
      t.fail("'" + key + "' lists \"" + fields[i] + "\" twice", key);
  }
  return fields;
}
}  // namespace

OutputSettings read_output_settings(const TomlTable& t) {
  OutputSettings o;
  o.point_fields = read_field_list(t, "point_fields", "solid point", kSolidPointFields);
  o.liquid_fields = read_field_list(t, "liquid_fields", "liquid point", kLiquidPointFields);
  o.grid_fields = read_field_list(t, "grid_fields", "grid", kGridFields);
  o.grid = t.boolean_or("grid", true);
  o.compress = t.choice_or("compression", {"zlib", "none"}, "zlib") == "zlib";
  t.finish();
  return o;
}

bool Probe::records(const std::string& field) const {
  return std::find(fields.begin(), fields.end(), field) != fields.end();
}

Probe read_probe(const TomlTable& t, int dimension, bool has_water) {
  Probe p;
  p.name = t.safe_name("name");
  const int given = static_cast<int>(t.has("position")) + static_cast<int>(t.has("solid_point")) +
                    static_cast<int>(t.has("liquid_point"));
  if (given != 1)
    t.fail("probe '" + p.name +
               "' needs exactly one of 'position' (a fixed place, m), 'solid_point' or "
               "'liquid_point' (the id of a point, counting from 0, that the probe rides on)",
           given == 0 ? "name" : (t.has("solid_point") ? "solid_point" : "liquid_point"));
  if (t.has("position")) {
    p.position = t.numbers("position");
    if (static_cast<int>(p.position.size()) != dimension)
      t.fail("'position' of probe '" + p.name + "' must have " + std::to_string(dimension) +
                 " components (m)",
             "position");
    for (double x : p.position)
      if (!std::isfinite(x))
        t.fail("'position' of probe '" + p.name + "' is not finite", "position");
  } else {
    const char* key = t.has("solid_point") ? "solid_point" : "liquid_point";
    p.follows = t.has("solid_point") ? Probe::Follows::kSolidPoint : Probe::Follows::kLiquidPoint;
    p.point_id = t.integer(key);
    if (p.point_id < 0)
      t.fail(std::string("'") + key + "' is a point id, counting from 0 (ParaView's 'id' field)",
             key);
    if (p.follows == Probe::Follows::kLiquidPoint && !has_water)
      t.fail("probe '" + p.name + "' rides on a liquid point, but the scene has no water", key);
  }
  if (t.has("fields")) {
    p.fields = t.strings("fields");
    std::string known;
    for (const auto& f : kProbeFields) known += (known.empty() ? "" : ", ") + f;
    if (p.fields.empty()) t.fail("'fields' of probe '" + p.name + "' is empty", "fields");
    for (std::size_t i = 0; i < p.fields.size(); ++i) {
      const std::string& f = p.fields[i];
      if (std::find(kProbeFields.begin(), kProbeFields.end(), f) == kProbeFields.end())
        t.fail("unknown probe field \"" + f + "\" (known: " + known + ")", "fields");
      if (std::find(p.fields.begin(), p.fields.begin() + static_cast<std::ptrdiff_t>(i), f) !=
          p.fields.begin() + static_cast<std::ptrdiff_t>(i))
        t.fail("'fields' lists \"" + f + "\" twice", "fields");
      if (!has_water && (f == "pore_pressure" || f == "liquid_velocity"))
        t.fail("probe field \"" + f + "\" needs water, and the scene has none", "fields");
    }
  } else if (!has_water) {
    p.fields = {"effective_stress", "velocity", "porosity"};
  }
  p.interval = t.number_in_or("interval", 1e-12, 1e9, 0.0);
  t.finish();
  return p;
}

double Sponge::rate_at(double x) const {
  // Position in the zone, 0 at x_start and 1 at x_end, whichever way the zone faces.
  const double s = std::clamp((x - x_start) / (x_end - x_start), 0.0, 1.0);
  return damping_rate * s * s;
}

Sponge read_sponge(const TomlTable& t, bool rate_required) {
  Sponge s;
  s.x_start = t.number("x_start");
  s.x_end = t.number("x_end");
  if (!(s.x_end != s.x_start))
    t.fail(
        "the sponge zone has no length: 'x_end' must differ from 'x_start' (x_end is the far "
        "end of the tank, where the damping is strongest; it may lie below x_start for a "
        "sponge at the -x end)",
        "x_end");
  if (rate_required && !t.has("damping_rate")) t.fail("the [[sponge]] has no 'damping_rate' (1/s)");
  // Above 1e6 1/s the zone is a wall for any wave a tank carries; a bound catches a unit slip.
  s.damping_rate = t.number_in_or("damping_rate", 1e-9, 1e6, 0.0);
  t.finish();
  return s;
}

void check_probe_names(const std::vector<Probe>& probes,
                       const std::vector<TomlTable>& probe_tables) {
  std::set<std::string> names;
  for (std::size_t i = 0; i < probes.size(); ++i)
    if (!names.insert(probes[i].name).second)
      probe_tables[i].fail("two [[probe]] entries are named '" + probes[i].name +
                               "' (each writes output/probes/<name>.csv)",
                           "name");
}

toml::table to_toml(const Material& m) {
  if (m.is_liquid())
    return toml::table{{"name", m.name},
                       {"model", "water"},
                       {"density", m.liquid_density},
                       {"bulk_modulus", m.bulk_modulus},
                       {"viscosity", m.viscosity}};
  toml::table t{
      {"name", m.name},
      {"model", m.model == MaterialModel::kMohrCoulomb ? "mohr-coulomb" : "linear-elastic"},
      {"solid_density", m.solid_density},
      {"porosity", m.porosity},
      {"youngs_modulus", m.youngs_modulus},
      {"poisson_ratio", m.poisson_ratio}};
  if (m.model == MaterialModel::kMohrCoulomb) {
    t.insert("friction_angle", m.friction_angle);
    t.insert("dilatancy_angle", m.dilatancy_angle);
    t.insert("cohesion", m.cohesion);
    if (m.tensile_strength < 1e299) t.insert("tensile_strength", m.tensile_strength);
  }
  if (m.grain_diameter > 0) t.insert("grain_diameter", m.grain_diameter);
  if (m.max_porosity < 1) t.insert("max_porosity", m.max_porosity);
  return t;
}

toml::table to_toml(const BoundaryCondition& b) {
  static const char* names[] = {"fixed", "roller", "contact", "fixity", "traction"};
  static const char* phases[] = {"both", "solid", "liquid"};
  toml::table t{{"name", b.name}, {"group", b.group}, {"type", names[static_cast<int>(b.type)]}};
  if (b.type == BoundaryType::kTraction) {
    toml::array a;
    for (double v : b.traction) a.push_back(v);
    t.insert("traction", a);
    if (b.ramp_time > 0) t.insert("ramp_time", b.ramp_time);
  }
  if (b.phase != BoundaryPhase::kBoth) t.insert("phase", phases[static_cast<int>(b.phase)]);
  if (b.type == BoundaryType::kContact) t.insert("friction", b.friction);
  if (b.type == BoundaryType::kFixity) {
    toml::array a;
    for (int d : b.directions) a.push_back(std::string(1, "xyz"[d]));
    t.insert("directions", a);
  }
  return t;
}

toml::table to_toml(const Stage& s) {
  toml::table t{{"name", s.name},
                {"type", s.type == StageType::kQuasiStatic ? "quasi-static" : "dynamic"},
                {"duration", s.duration},
                {"courant", s.courant},
                {"damping", s.damping},
                {"output_interval", s.output_interval},
                {"boundaries", to_array(s.boundaries)}};
  if (s.type == StageType::kQuasiStatic) {
    t.insert("kinetic_energy_ratio", s.kinetic_energy_ratio);
    t.insert("reset_displacement", s.reset_displacement);
  }
  return t;
}

toml::table to_toml(const SolverSettings& s) {
  toml::table t{{"scheme", s.scheme == TransferScheme::kMUSL ? "musl" : "usl"},

                {"max_velocity", s.max_velocity},
                {"volumetric_smoothing", s.volumetric_smoothing},
                {"pore_volume_projection", s.pore_volume_projection},
                {"free_water_cell_volume", s.free_water_cell_volume},
                {"crossed_pressure_filter", s.crossed_pressure_filter},
                {"liquid_bulk_viscosity", s.liquid_bulk_viscosity},
                {"checkpoint_interval_minutes", s.checkpoint_interval_minutes}};
  // Only the blend settings the scene gave: absent ones keep their automatic defaults.
  if (s.flip_fraction) t.insert("flip_fraction", *s.flip_fraction);
  if (s.pic_damping_time) t.insert("pic_damping_time", *s.pic_damping_time);
  if (s.liquid_pic_damping_time) t.insert("liquid_pic_damping_time", *s.liquid_pic_damping_time);
  if (s.liquid_xpic_order != 1) t.insert("liquid_xpic_order", s.liquid_xpic_order);
  if (s.pressure_projection_interval)
    t.insert("pressure_projection_interval", *s.pressure_projection_interval);
  if (s.pressure_projection_time) t.insert("pressure_projection_time", *s.pressure_projection_time);
  if (s.liquid_pressure == LiquidPressure::kNodalFit) t.insert("liquid_pressure", "nodal_fit");
  if (s.pore_pressure_cell_measure == PorePressureMeasure::kWater)
    t.insert("pore_pressure_cell_measure", "water");
  if (s.liquid_advection == LiquidAdvection::kFlux) t.insert("liquid_advection", "flux");
  if (s.liquid_landing == LiquidLanding::kKeepVelocity) t.insert("liquid_landing", "keep_velocity");
  return t;
}

toml::table to_toml(const OutputSettings& o) {
  return toml::table{{"point_fields", to_array(o.point_fields)},
                     {"liquid_fields", to_array(o.liquid_fields)},
                     {"grid_fields", to_array(o.grid_fields)},
                     {"grid", o.grid},
                     {"compression", o.compress ? "zlib" : "none"}};
}

toml::table to_toml(const Probe& p) {
  toml::table t{{"name", p.name}};
  if (p.follows == Probe::Follows::kPosition) {
    toml::array a;
    for (double x : p.position) a.push_back(x);
    t.insert("position", a);
  } else {
    t.insert(p.follows == Probe::Follows::kSolidPoint ? "solid_point" : "liquid_point",
             static_cast<int64_t>(p.point_id));
  }
  t.insert("fields", to_array(p.fields));
  if (p.interval > 0) t.insert("interval", p.interval);
  return t;
}

toml::table to_toml(const Sponge& s) {
  return toml::table{{"x_start", s.x_start}, {"x_end", s.x_end}, {"damping_rate", s.damping_rate}};
}

void check_stage_boundaries(const std::vector<Stage>& stages,
                            const std::vector<BoundaryCondition>& boundaries,
                            const std::vector<TomlTable>& stage_tables) {
  std::set<std::string> names, stage_names;
  for (const auto& b : boundaries)
    if (!names.insert(b.name).second)
      throw InputError(stage_tables.empty() ? "" : stage_tables[0].file(), 0,
                       "two [[boundary]] entries are named '" + b.name + "'");
  for (size_t i = 0; i < stages.size(); ++i) {
    if (!stage_names.insert(stages[i].name).second)
      stage_tables[i].fail("two [[stage]] entries are named '" + stages[i].name + "'", "name");
    for (const auto& used : stages[i].boundaries)
      if (!names.count(used))
        stage_tables[i].fail("stage '" + stages[i].name + "' uses boundary '" + used +
                                 "', which no [[boundary]] defines",
                             "boundaries");
  }
}

CaseDescription read_case(const std::string& case_folder) {
  namespace fs = std::filesystem;
  CaseDescription c;
  c.folder = case_folder;
  const fs::path stages_path = fs::path(case_folder) / "stages.toml";
  if (!fs::exists(stages_path))
    throw InputError(stages_path.string(), 0,
                     "not found: is this a case folder written by `lituya pre`?");
  TomlDocument doc(stages_path);
  TomlTable root = doc.root();
  TomlDocument::check_header(root, "lituya-stages", 1);
  c.dimension = static_cast<int>(root.integer("dimension"));
  if (c.dimension != 2 && c.dimension != 3) root.fail("'dimension' must be 2 or 3", "dimension");
  c.gravity = root.numbers("gravity");
  if (static_cast<int>(c.gravity.size()) != c.dimension)
    root.fail("'gravity' must have " + std::to_string(c.dimension) + " components", "gravity");
  c.geometry_file = (fs::path(case_folder) / root.string("geometry")).string();
  c.points_file = (fs::path(case_folder) / root.string("points")).string();
  c.materials_file = (fs::path(case_folder) / root.string("materials")).string();
  if (root.has("liquid_points"))
    c.liquid_points_file = (fs::path(case_folder) / root.string("liquid_points")).string();
  for (const TomlTable& g : root.tables("group")) {
    Group group{g.string("name"), static_cast<int>(g.integer("dimension"))};
    g.finish();
    c.groups.push_back(group);
  }
  if (auto s = root.optional_table("solver")) c.solver = read_solver_settings(*s);
  if (auto o = root.optional_table("output")) c.output = read_output_settings(*o);
  for (const TomlTable& b : root.tables("boundary")) {
    c.boundaries.push_back(read_boundary(b, c.dimension));
    // `rough` names a material of the scene; pre resolves it to the number.
    if (!c.boundaries.back().rough.empty())
      b.fail("'rough' belongs in scene.toml: lituya pre writes the wall's 'friction' here",
             "rough");
    bool found = false;
    for (const auto& g : c.groups)
      found = found || (g.name == c.boundaries.back().group && g.dimension == c.dimension - 1);
    if (!found)
      b.fail("boundary group '" + c.boundaries.back().group + "' is not a physical group of " +
                 "dimension " + std::to_string(c.dimension - 1) + " in this case",
             "group");
  }
  std::vector<TomlTable> stage_tables = root.tables("stage");
  for (const TomlTable& s : stage_tables) c.stages.push_back(read_stage(s));
  if (c.stages.empty()) root.fail("no [[stage]] given: nothing to run");
  check_stage_boundaries(c.stages, c.boundaries, stage_tables);
  const std::vector<TomlTable> probe_tables = root.tables("probe");
  for (const TomlTable& p : probe_tables)
    c.probes.push_back(read_probe(p, c.dimension, !c.liquid_points_file.empty()));
  check_probe_names(c.probes, probe_tables);
  for (const TomlTable& s : root.tables("sponge")) {
    if (c.liquid_points_file.empty())
      s.fail("a [[sponge]] damps water, and this case has none (no liquid_points)");
    c.sponges.push_back(read_sponge(s, true));
  }
  root.finish();

  TomlDocument mdoc(c.materials_file);
  TomlTable mroot = mdoc.root();
  TomlDocument::check_header(mroot, "lituya-materials", 1);
  for (const TomlTable& m : mroot.tables("material")) c.materials.push_back(read_material(m));
  if (c.materials.empty()) mroot.fail("no [[material]] given");
  mroot.finish();
  return c;
}

}  // namespace lituya::solver
