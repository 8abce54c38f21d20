#include "analysis/analysis.hpp"
#include "analysis/angle_of_repose.hpp"
#include "analysis/body_loads.hpp"
#include "analysis/droplet.hpp"
#include "analysis/drum_discharge.hpp"
#include "analysis/drum_segregation.hpp"
#include "analysis/front_position.hpp"
#include "analysis/height_profile.hpp"
#include "analysis/mass_flux.hpp"
#include "analysis/mass_in_region.hpp"
#include "analysis/mixing.hpp"
#include "analysis/orientation_order.hpp"
#include "analysis/packing_fraction.hpp"
#include "analysis/power_number.hpp"
#include "analysis/velocity_profile.hpp"

namespace partimix::analysis {

const Registry<Analysis, const AnalysisOptions&>& analysis_registry() {
  static const Registry<Analysis, const AnalysisOptions&> registry = [] {
    Registry<Analysis, const AnalysisOptions&> r;
    r.add("front_position",
          [](const AnalysisOptions& o) { return std::make_unique<FrontPosition>(o.axis); });
    r.add("body_loads",
          [](const AnalysisOptions& o) { return std::make_unique<BodyLoads>(o.body); });
    r.add("mixing", [](const AnalysisOptions& o) { return std::make_unique<Mixing>(o.mixing); });
    r.add("power_number",
          [](const AnalysisOptions& o) { return std::make_unique<PowerNumber>(o); });
    r.add("packing_fraction",
          [](const AnalysisOptions& o) { return std::make_unique<PackingFraction>(o.packing); });
    r.add("velocity_profile",
          [](const AnalysisOptions& o) { return std::make_unique<VelocityProfile>(o.profile); });
    r.add("mass_flux", [](const AnalysisOptions& o) { return std::make_unique<MassFlux>(o.flux); });
    r.add("angle_of_repose",
          [](const AnalysisOptions& o) { return std::make_unique<AngleOfRepose>(o.repose); });
    r.add("mass_in_region",
          [](const AnalysisOptions& o) { return std::make_unique<MassInRegion>(o.region_mass); });
    r.add("height_profile",
          [](const AnalysisOptions& o) { return std::make_unique<HeightProfile>(o.height); });
    r.add("orientation_order", [](const AnalysisOptions& o) {
      return std::make_unique<OrientationOrder>(o.orientation);
    });
    r.add("drum_segregation", [](const AnalysisOptions& o) {
      return std::make_unique<DrumSegregation>(o.drum_measures);
    });
    r.add("drum_discharge", [](const AnalysisOptions& o) {
      return std::make_unique<DrumDischarge>(o.drum_measures);
    });
    r.add("droplet", [](const AnalysisOptions& o) { return std::make_unique<Droplet>(o.droplet); });
    return r;
  }();
  return registry;
}

}  // namespace partimix::analysis
