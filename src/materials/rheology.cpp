#include "materials/rheology.hpp"

#include <algorithm>
#include <stdexcept>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "materials/rheology/bingham.hpp"
#include "materials/rheology/carreau.hpp"
#include "materials/rheology/cross.hpp"
#include "materials/rheology/herschel_bulkley.hpp"
#include "materials/rheology/newtonian.hpp"
#include "materials/rheology/power_law.hpp"
#include "materials/rheology/yield_regularisation.hpp"

namespace partimix::materials {
namespace {

YieldRegularisation yield_of(const RheologyConfig& c) {
  return {c.yield_stress, c.regularisation, c.papanastasiou_exponent};
}

std::unique_ptr<Rheology> create_model(const RheologyConfig& config) {
  std::unique_ptr<Rheology> model = rheology_registry().create(config.model, config);
  if (!model) {
    throw std::invalid_argument(fmt::format("unknown rheology '{}'; expected one of: {}",
                                            config.model,
                                            fmt::join(rheology_registry().names(), ", ")));
  }
  return model;
}

}  // namespace

const Registry<Rheology, const RheologyConfig&>& rheology_registry() {
  static const Registry<Rheology, const RheologyConfig&> registry = [] {
    Registry<Rheology, const RheologyConfig&> r;
    r.add("newtonian",
          [](const RheologyConfig& c) { return std::make_unique<Newtonian>(c.viscosity); });
    r.add("power_law", [](const RheologyConfig& c) {
      return std::make_unique<PowerLaw>(c.consistency, c.flow_index);
    });
    r.add("herschel_bulkley", [](const RheologyConfig& c) {
      return std::make_unique<HerschelBulkley>(yield_of(c), c.consistency, c.flow_index);
    });
    r.add("bingham", [](const RheologyConfig& c) {
      return std::make_unique<Bingham>(yield_of(c), c.plastic_viscosity);
    });
    r.add("cross", [](const RheologyConfig& c) {
      return std::make_unique<Cross>(c.zero_shear_viscosity, c.infinite_shear_viscosity,
                                     c.time_constant, c.flow_index);
    });
    r.add("carreau", [](const RheologyConfig& c) {
      return std::make_unique<CarreauYasuda>(c.zero_shear_viscosity, c.infinite_shear_viscosity,
                                             c.time_constant, c.flow_index, c.yasuda_exponent);
    });
    return r;
  }();
  return registry;
}

BoundedRheology::BoundedRheology(const RheologyConfig& config)
    : model_(create_model(config)), min_(config.viscosity_min), max_(config.viscosity_max) {
  if (!(min_ >= 0.0 && max_ >= min_)) {
    throw std::invalid_argument(fmt::format(
        "rheology bounds must satisfy 0 <= viscosity_min <= viscosity_max, got [{}, {}]", min_,
        max_));
  }
}

// Infinite model values (a power law at rest, an unregularised yield stress) clamp to max_.
double BoundedRheology::viscosity(double shear_rate) const {
  return std::clamp(model_->apparent_viscosity(shear_rate), min_, max_);
}

}  // namespace partimix::materials
