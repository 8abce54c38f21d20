#pragma once
// Rheology: the apparent viscosity eta_a(gamma_dot) of a generalised Newtonian fluid
// (docs/rheology.md; the seed's eqs. 4-6). Models are chosen by name (`fluid.rheology.model`):
// newtonian, power_law, herschel_bulkley, bingham, cross, carreau. Yield-stress models are
// regularised (Papanastasiou exponential or a bi-viscous cap), and every model is bounded by
// [viscosity_min, viscosity_max] so that the viscous time-step limit stays finite. Shared by the
// methods (DESIGN.md, "Layers": src/materials): SPH today, grid fluids and MPM next.
#include <limits>
#include <memory>
#include <string>

#include "core/registry.hpp"

namespace partimix::materials {

struct RheologyConfig {
  std::string model = "newtonian";
  double viscosity = 0.0;                 // newtonian: mu [Pa s]
  double consistency = 0.0;               // power_law, herschel_bulkley: K [Pa s^n]
  double flow_index = 1.0;                // power_law, herschel_bulkley, cross, carreau: n [-]
  double yield_stress = 0.0;              // herschel_bulkley, bingham: tau0 [Pa]
  double plastic_viscosity = 0.0;         // bingham: mu_p [Pa s]
  double zero_shear_viscosity = 0.0;      // cross, carreau: eta0 [Pa s]
  double infinite_shear_viscosity = 0.0;  // cross, carreau: eta_inf [Pa s]
  double time_constant = 0.0;             // cross, carreau: lambda [s]
  double yasuda_exponent = 2.0;           // carreau: a [-] (2: Carreau)
  std::string regularisation = "papanastasiou";  // yield stress: papanastasiou | biviscous
  double papanastasiou_exponent = 1000.0;        // m [s]
  double viscosity_min = 0.0;                    // [Pa s]
  double viscosity_max = std::numeric_limits<double>::infinity();  // [Pa s]
};

class Rheology {
 public:
  virtual ~Rheology() = default;
  // The model's apparent viscosity [Pa s] at shear rate gamma_dot >= 0 [1/s], regularised but
  // before the bounds.
  virtual double apparent_viscosity(double shear_rate) const = 0;
};

// Models by name, built from the configuration.
const Registry<Rheology, const RheologyConfig&>& rheology_registry();

// The bounded apparent viscosity: clamp(model(gamma_dot), viscosity_min, viscosity_max).
class BoundedRheology {
 public:
  explicit BoundedRheology(const RheologyConfig& config);
  double viscosity(double shear_rate) const;

 private:
  std::unique_ptr<Rheology> model_;
  double min_;
  double max_;
};

}  // namespace partimix::materials
