#pragma once
// The materials and settings of the multi-material SPH scheme (docs/multi-material-sph.md, "The
// scheme"; docs/case-reference.md, "sph.materials"), as read from `sph.multi_material` and
// `sph.materials`: each material an equation of state, a viscosity, thermal properties, and
// optionally a surface tension and an elastic-plastic solid's strength.
#include <optional>
#include <string>
#include <vector>

#include "materials/johnson_cook.hpp"
#include "materials/thermal_eos.hpp"

namespace partimix::sph {

// An elastic-plastic solid: Hooke's law in the Jaumann rate, Johnson-Cook strength and damage.
struct SolidSpec {
  double shear_modulus = 0.0;                     // G [Pa]
  materials::JohnsonCookParameters johnson_cook;  // eqs. 11-13 of the seed
  double artificial_stress = 0.3;                 // epsilon of Monaghan's artificial stress
  // Bonded through the reference configuration (sph/multi_material/total_lagrangian.hpp)
  // instead of updated Lagrangian pairs.
  bool total_lagrangian = false;
  double hourglass = 0.1;  // alpha of the total Lagrangian hourglass penalty
};

struct MaterialSpec {
  std::string name;
  materials::ThermalEosConfig eos;
  // The initial state: exactly one of density [kg/m^3] and pressure [Pa] (absolute), the other
  // following from the equation of state at the initial temperature.
  std::optional<double> density;
  std::optional<double> pressure;
  double temperature = 293.15;  // initial T [K]
  // Holds `temperature` throughout: a temperature (Dirichlet) boundary, as a body of infinite heat
  // capacity (docs/multi-material-sph.md, "Heat conduction").
  bool fixed_temperature = false;
  double specific_heat = 0.0;    // c_v [J/(kg K)], > 0
  double viscosity = 0.0;        // dynamic viscosity [Pa s]
  double conductivity = 0.0;     // k [W/(m K)]
  double surface_tension = 0.0;  // sigma [N/m] on its boundary with the other materials
  double heat_source = 0.0;      // volumetric heating [W/m^3]
  // q'' [W/m^2] through the surfaces of its bodies (sph/multi_material/surface_heating.hpp).
  double surface_heat_flux = 0.0;
  std::optional<SolidSpec> solid;  // absent: a fluid
};

// The ambient round the particles: the pressure their free surface sits at, and the heat it
// gives through that surface, h (T_ambient - T) per unit area.
struct Ambient {
  double pressure = 0.0;                   // p_a [Pa], absolute
  double temperature = 293.15;             // T_a [K]
  double heat_transfer_coefficient = 0.0;  // h [W/(m^2 K)]; 0: no heat through the surface
};

struct MultiMaterialSettings {
  std::vector<MaterialSpec> materials;
  std::string density = "continuity";  // continuity | summation
  double eta = 1.5;                    // h = eta (m / rho)^(1/d)
  double alpha = 1.0;                  // Monaghan's artificial viscosity
  double beta = 2.0;
  // p_b [Pa], added to every pressure in the momentum equation (Adami, Hu & Adams 2010): it
  // keeps pressures positive against the tensile instability where there is no free surface
  // (a periodic box), and would push a free surface out.
  double background_pressure = 0.0;
  Ambient ambient;
};

}  // namespace partimix::sph
