#include "sph/multi_material/materials_section.hpp"

#include <algorithm>
#include <limits>
#include <optional>
#include <string>
#include <utility>

#include <fmt/format.h>

namespace partimix::sph {
namespace {

using io::kNonNegative;
using io::kPositive;
using io::Reader;
using materials::JohnsonCookParameters;
using materials::ThermalEosConfig;
using EosKeyReader = void (*)(Reader&, ThermalEosConfig&);

void read_tait(Reader& eos, ThermalEosConfig& config) {
  config.reference_density = eos.required<double>("reference_density", kPositive);
  config.sound_speed = eos.required<double>("sound_speed", kPositive);
  config.gamma = eos.optional<double>("gamma", config.gamma, kPositive);
}

void read_ideal_gas(Reader& eos, ThermalEosConfig& config) {
  config.molar_mass = eos.required<double>("molar_mass", kPositive);
}

void read_redlich_kwong(Reader& eos, ThermalEosConfig& config) {
  read_ideal_gas(eos, config);
  config.a = eos.required<double>("a", kPositive);
  config.b = eos.required<double>("b", kPositive);
}

// The models of materials/thermal_eos.hpp, each with the reader of its own keys.
const std::vector<std::pair<std::string, EosKeyReader>> kEosModels{
    {"tait", read_tait}, {"ideal_gas", read_ideal_gas}, {"redlich_kwong", read_redlich_kwong}};

std::vector<std::string> eos_model_names() {
  std::vector<std::string> names;
  for (const auto& model : kEosModels) {
    names.push_back(model.first);
  }
  return names;
}

ThermalEosConfig read_eos(Reader& material) {
  Reader section = material.map("eos");
  ThermalEosConfig config;
  config.model = section.required_choice("model", eos_model_names());
  for (const auto& [name, read_keys] : kEosModels) {
    if (name == config.model) {
      read_keys(section, config);
    }
  }
  section.done();
  return config;
}

// Exactly one of density and pressure; a Tait liquid given neither starts at its reference
// density.
void read_initial_state(Reader& material, MaterialSpec& spec) {
  const bool density = material.contains("density");
  if (material.contains("pressure")) {
    if (density) {
      throw material.error("pressure", "give either 'density' or 'pressure', not both");
    }
    spec.pressure = material.required<double>("pressure", kPositive);
    return;
  }
  if (!density && spec.eos.model != "tait") {
    throw material.error("density",
                         fmt::format("missing required key 'density' or 'pressure' (the initial "
                                     "state of a material of eos model {})",
                                     spec.eos.model));
  }
  spec.density = material.optional<double>("density", spec.eos.reference_density, kPositive);
}

// A solid without `johnson_cook` is elastic: it never yields (A infinite) nor fails (D1
// infinite); its infinite melting temperature keeps T* = 0, so that the flow stress is never
// infinity times a vanishing thermal factor.
JohnsonCookParameters elastic() {
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  JohnsonCookParameters p;
  p.A = kInfinity;
  p.D1 = kInfinity;
  p.melt_temperature = kInfinity;
  return p;
}

void read_strength(Reader& section, JohnsonCookParameters& p) {
  p.A = section.optional<double>("A", p.A, kNonNegative);
  p.B = section.optional<double>("B", p.B, kNonNegative);
  p.n = section.optional<double>("n", p.n, kPositive);
  p.C = section.optional<double>("C", p.C);
  p.m = section.optional<double>("m", p.m, kPositive);
  p.reference_strain_rate =
      section.optional<double>("reference_strain_rate", p.reference_strain_rate, kPositive);
  p.room_temperature = section.optional<double>("room_temperature", p.room_temperature, kPositive);
  p.melt_temperature = section.optional<double>("melt_temperature", p.melt_temperature);
  if (!(p.melt_temperature > p.room_temperature)) {
    throw section.error("melt_temperature", fmt::format("must be > room_temperature ({}), got {}",
                                                        p.room_temperature, p.melt_temperature));
  }
}

void read_failure(Reader& section, JohnsonCookParameters& p) {
  p.D1 = section.optional<double>("D1", p.D1);
  p.D2 = section.optional<double>("D2", p.D2);
  p.D3 = section.optional<double>("D3", p.D3);
  p.D4 = section.optional<double>("D4", p.D4);
  p.D5 = section.optional<double>("D5", p.D5);
  p.damage_threshold =
      section.optional<double>("damage_threshold", p.damage_threshold, kNonNegative);
  p.critical_damage = section.optional<double>("critical_damage", p.critical_damage, kPositive);
  if (p.critical_damage > 1.0) {
    throw section.error("critical_damage", fmt::format("must be <= 1, got {}", p.critical_damage));
  }
}

JohnsonCookParameters read_johnson_cook(Reader& solid) {
  if (!solid.contains("johnson_cook")) {
    return elastic();
  }
  Reader section = solid.map("johnson_cook");
  JohnsonCookParameters p;
  read_strength(section, p);
  read_failure(section, p);
  section.done();
  return p;
}

std::optional<SolidSpec> read_solid(Reader& material) {
  if (!material.contains("solid")) {
    return std::nullopt;
  }
  Reader section = material.map("solid");
  SolidSpec solid;
  solid.shear_modulus = section.required<double>("shear_modulus", kPositive);
  solid.artificial_stress =
      section.optional<double>("artificial_stress", solid.artificial_stress, kNonNegative);
  const std::string formulation = section.choice("formulation", "updated_lagrangian",
                                                 {"updated_lagrangian", "total_lagrangian"});
  solid.total_lagrangian = formulation == "total_lagrangian";
  solid.hourglass = section.optional<double>("hourglass", solid.hourglass, kNonNegative);
  solid.johnson_cook = read_johnson_cook(section);
  section.done();
  return solid;
}

MaterialSpec read_material(Reader& item) {
  MaterialSpec spec;
  spec.name = item.required<std::string>("name");
  if (spec.name.empty()) {
    throw item.error("name", "must not be empty");
  }
  spec.eos = read_eos(item);
  read_initial_state(item, spec);
  spec.temperature = item.optional<double>("temperature", spec.temperature, kPositive);
  spec.specific_heat = item.required<double>("specific_heat", kPositive);
  spec.viscosity = item.optional<double>("viscosity", spec.viscosity, kNonNegative);
  spec.conductivity = item.optional<double>("conductivity", spec.conductivity, kNonNegative);
  spec.surface_tension =
      item.optional<double>("surface_tension", spec.surface_tension, kNonNegative);
  spec.heat_source = item.optional<double>("heat_source", spec.heat_source);
  spec.surface_heat_flux = item.optional<double>("surface_heat_flux", spec.surface_heat_flux);
  spec.fixed_temperature = item.optional<bool>("fixed_temperature", spec.fixed_temperature);
  if (spec.fixed_temperature && (spec.heat_source != 0.0 || spec.surface_heat_flux != 0.0)) {
    throw item.error("fixed_temperature",
                     "a material whose temperature is fixed takes no heat_source or "
                     "surface_heat_flux");
  }
  spec.solid = read_solid(item);
  item.done();
  return spec;
}

void check_unique_name(const Reader& item, const std::string& name,
                       const std::vector<MaterialSpec>& earlier) {
  for (std::size_t j = 0; j < earlier.size(); ++j) {
    if (earlier[j].name == name) {
      throw item.error("name", fmt::format("'{}' is already the name of sph.materials[{}]; each "
                                           "material needs a name of its own",
                                           name, j));
    }
  }
}

std::vector<MaterialSpec> read_materials(Reader& sph) {
  std::vector<MaterialSpec> materials;
  for (Reader& item : sph.list("materials")) {
    MaterialSpec material = read_material(item);
    check_unique_name(item, material.name, materials);
    materials.push_back(std::move(material));
  }
  return materials;
}

void read_artificial_viscosity(Reader& scheme, MultiMaterialSettings& settings) {
  Reader section = scheme.optional_map("artificial_viscosity");
  settings.alpha = section.optional<double>("alpha", settings.alpha, kNonNegative);
  settings.beta = section.optional<double>("beta", settings.beta, kNonNegative);
  section.done();
}

Ambient read_ambient(Reader& scheme) {
  Reader section = scheme.optional_map("ambient");
  Ambient ambient;
  ambient.pressure = section.optional<double>("pressure", ambient.pressure, kNonNegative);
  ambient.temperature = section.optional<double>("temperature", ambient.temperature, kPositive);
  ambient.heat_transfer_coefficient = section.optional<double>(
      "heat_transfer_coefficient", ambient.heat_transfer_coefficient, kNonNegative);
  section.done();
  return ambient;
}

void read_scheme_settings(Reader& sph, MultiMaterialSettings& settings) {
  Reader section = sph.optional_map("multi_material");
  settings.density = section.choice("density", settings.density, {"continuity", "summation"});
  settings.eta = section.optional<double>("eta", settings.eta, kPositive);
  read_artificial_viscosity(section, settings);
  settings.background_pressure =
      section.optional<double>("background_pressure", settings.background_pressure, kNonNegative);
  settings.ambient = read_ambient(section);
  section.done();
}

}  // namespace

MultiMaterialSettings read_multi_material(Reader& sph) {
  MultiMaterialSettings settings;
  settings.materials = read_materials(sph);
  read_scheme_settings(sph, settings);
  return settings;
}

int read_region_material(Reader& region, const std::vector<MaterialSpec>& materials) {
  std::vector<std::string> names;
  for (const MaterialSpec& material : materials) {
    names.push_back(material.name);
  }
  const std::string name = region.required_choice("material", names);
  return static_cast<int>(std::find(names.begin(), names.end(), name) - names.begin());
}

}  // namespace partimix::sph
