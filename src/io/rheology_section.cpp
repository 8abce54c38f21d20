#include "io/rheology_section.hpp"

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

namespace partimix::io {
namespace {

using Config = materials::RheologyConfig;
using KeyReader = void (*)(Reader&, Config&);

bool has_yield_stress(const std::string& model) {
  return model == "herschel_bulkley" || model == "bingham";
}

void read_newtonian(Reader& section, Config& config) {
  config.viscosity = section.required<double>("viscosity", kNonNegative);
}

void read_power_law(Reader& section, Config& config) {
  config.consistency = section.required<double>("consistency", kPositive);
  config.flow_index = section.required<double>("flow_index", kPositive);
}

void read_herschel_bulkley(Reader& section, Config& config) {
  config.yield_stress = section.required<double>("yield_stress", kNonNegative);
  read_power_law(section, config);
}

void read_bingham(Reader& section, Config& config) {
  config.yield_stress = section.required<double>("yield_stress", kNonNegative);
  config.plastic_viscosity = section.required<double>("plastic_viscosity", kPositive);
}

void read_cross(Reader& section, Config& config) {
  config.zero_shear_viscosity = section.required<double>("zero_shear_viscosity", kPositive);
  config.infinite_shear_viscosity =
      section.required<double>("infinite_shear_viscosity", kNonNegative);
  if (!(config.infinite_shear_viscosity < config.zero_shear_viscosity)) {
    throw section.error("infinite_shear_viscosity",
                        fmt::format("must be < zero_shear_viscosity ({}), got {}",
                                    config.zero_shear_viscosity, config.infinite_shear_viscosity));
  }
  config.time_constant = section.required<double>("time_constant", kPositive);
  config.flow_index = section.required<double>("flow_index", kPositive);
}

void read_carreau(Reader& section, Config& config) {
  read_cross(section, config);
  config.yasuda_exponent =
      section.optional<double>("yasuda_exponent", config.yasuda_exponent, kPositive);
}

// The models in the order of docs/case-reference.md, each with the reader of its own keys.
const std::vector<std::pair<std::string, KeyReader>> kModels{
    {"newtonian", read_newtonian},
    {"power_law", read_power_law},
    {"herschel_bulkley", read_herschel_bulkley},
    {"bingham", read_bingham},
    {"cross", read_cross},
    {"carreau", read_carreau}};

std::vector<std::string> model_names() {
  std::vector<std::string> names;
  for (const auto& model : kModels) {
    names.push_back(model.first);
  }
  return names;
}

void read_model_keys(Reader& section, Config& config) {
  for (const auto& [name, read_keys] : kModels) {
    if (name == config.model) {
      read_keys(section, config);
    }
  }
}

void read_regularisation(Reader& section, Config& config) {
  config.regularisation =
      section.choice("regularisation", config.regularisation, {"papanastasiou", "biviscous"});
  if (config.regularisation == "papanastasiou") {
    config.papanastasiou_exponent = section.optional<double>(
        "papanastasiou_exponent", config.papanastasiou_exponent, kPositive);
  }
}

// Why the model's viscosity has no finite upper bound; empty when it has one.
std::string unbounded_because(const Config& config) {
  const bool power_law = config.model == "power_law" || config.model == "herschel_bulkley";
  if (has_yield_stress(config.model) && config.regularisation == "biviscous") {
    return "with regularisation biviscous, tau0 / shear rate grows without bound as the shear "
           "rate goes to 0";
  }
  if (power_law && config.flow_index < 1.0) {
    return fmt::format(
        "with flow_index {} < 1, the viscosity grows without bound as the shear "
        "rate goes to 0",
        config.flow_index);
  }
  if ((power_law || config.model == "carreau") && config.flow_index > 1.0) {
    return fmt::format(
        "with flow_index {} > 1 (shear thickening), the viscosity grows without "
        "bound with the shear rate",
        config.flow_index);
  }
  return "";
}

// viscosity_max "auto" (the default) leaves the model uncapped, which only a bounded model may.
void read_bounds(Reader& section, Config& config) {
  config.viscosity_min =
      section.optional<double>("viscosity_min", config.viscosity_min, kNonNegative);
  const std::optional<double> cap = section.automatic<double>("viscosity_max");
  if (!cap) {
    const std::string reason = unbounded_because(config);
    if (!reason.empty()) {
      throw section.error("viscosity_max",
                          fmt::format("required for model {}: {}; the cap keeps the viscous "
                                      "time step finite",
                                      config.model, reason));
    }
    return;
  }
  if (!(*cap > config.viscosity_min)) {
    throw section.error("viscosity_max", fmt::format("must be > viscosity_min ({}), got {}",
                                                     config.viscosity_min, *cap));
  }
  config.viscosity_max = *cap;
}

Config read_rheology_map(Reader& fluid) {
  Reader section = fluid.map("rheology");
  Config config;
  config.model = section.required_choice("model", model_names());
  read_model_keys(section, config);
  if (has_yield_stress(config.model)) {
    read_regularisation(section, config);
  }
  read_bounds(section, config);
  section.done();
  return config;
}

}  // namespace

materials::RheologyConfig read_fluid_rheology(Reader& fluid) {
  const bool viscosity = fluid.contains("viscosity");
  if (fluid.contains("rheology")) {
    if (viscosity) {
      throw fluid.error("rheology",
                        "give either 'viscosity' (a Newtonian fluid) or 'rheology', not both");
    }
    return read_rheology_map(fluid);
  }
  if (!viscosity) {
    throw fluid.error("viscosity",
                      "missing required key 'viscosity' (a Newtonian fluid) or 'rheology' (any "
                      "model)");
  }
  Config config;
  read_newtonian(fluid, config);
  return config;
}

}  // namespace partimix::io
