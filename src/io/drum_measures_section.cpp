#include "io/drum_measures_section.hpp"

#include <cmath>

#include <fmt/format.h>

namespace partimix::io {
namespace {

constexpr int kMostSlices = 1000;

// The drum's measurements take places along its axis and from it, which only a rotation about
// that axis keeps.
void check_turns_about_its_axis(const Reader& item, const WallSpec& wall,
                                const geometry::TruckDrumShape& drum) {
  const geometry::MotionConfig& motion = wall.motion;
  if (motion.type == "fixed")
    return;
  const Vec3 along =
      drum.to_drum(motion.axis_point + motion.axis) - drum.to_drum(motion.axis_point);
  const Vec3 at = drum.to_drum(motion.axis_point);
  const double length = drum.drum().length();
  const bool about_axis = motion.type == "rotation" && std::hypot(along.x(), along.y()) < 1e-9 &&
                          std::hypot(at.x(), at.y()) < 1e-9 * length;
  if (!about_axis)
    throw item.error("wall",
                     "the truck drum's motion must be a rotation about its own axis "
                     "(walls[].motion.axis and axis_point on the drum's axis)");
}

}  // namespace

void read_drum_measures(Reader& item, AnalysisSpec& analysis, const Case& the_case) {
  analysis::DrumMeasures& options = analysis.drum_measures;
  const int wall = item.required<int>("wall", at_least(0));
  if (static_cast<std::size_t>(wall) >= the_case.walls.size())
    throw item.error("wall", fmt::format("there is no wall {} (the case has {} walls, counted "
                                         "from 0)",
                                         wall, the_case.walls.size()));
  const WallSpec& spec = the_case.walls[static_cast<std::size_t>(wall)];
  options.drum = std::dynamic_pointer_cast<const geometry::TruckDrumShape>(spec.shape);
  if (!options.drum)
    throw item.error("wall", fmt::format("wall {} is not a truck_drum", wall));
  check_turns_about_its_axis(item, spec, *options.drum);
  options.coarse_species = item.optional<int>("coarse_species", 0, at_least(0));
  if (analysis.type == "drum_segregation") {
    options.bins = item.optional<int>("bins", options.bins, at_least(2));
    if (options.bins > kMostSlices)
      throw item.error("bins", fmt::format("at most {} bins", kMostSlices));
    options.threshold = item.optional<double>("threshold", options.threshold, kPositive);
    if (const std::optional<double> until = item.automatic<double>("mixing_until", kNonNegative))
      options.mixing_until = *until;
    if (const std::optional<double> from = item.automatic<double>("average_from", kNonNegative)) {
      if (!(*from <= options.mixing_until))
        throw item.error("average_from", "average_from must not be later than mixing_until");
      options.average_from = *from;
    }
    return;
  }
  options.fit_from = item.optional<double>("fit_from", options.fit_from, kNonNegative);
  if (const std::optional<double> until = item.automatic<double>("fit_until", kPositive)) {
    if (!(*until > options.fit_from))
      throw item.error("fit_until", "fit_until must be later than fit_from");
    options.fit_until = *until;
  }
}

}  // namespace partimix::io
