#include "dem/dem_method.hpp"

#include <stdexcept>

#include <fmt/format.h>

#include "core/error.hpp"
#include "dem/dem_solver.hpp"
#include "dem/insertion.hpp"
#include "particles/health.hpp"

namespace partimix::dem {
namespace {

double kinetic_energy_per_grain(const ParticleStore& store) {
  double sum = 0.0;
  for (std::size_t i = 0; i < store.size(); ++i)
    sum += 0.5 * store.mass()[i] * store.velocity()[i].squaredNorm();
  return sum / static_cast<double>(store.size());
}

// Steps with the walls held still until the grains' mean kinetic energy falls below the fill's
// threshold (checked every 100 steps, after at least 0.01 s) or the fill's settle time passes.
// Every 100 steps the monitor hears of it and may stop it, and a grain gone wrong (a blow-up)
// stops it with the reason at dem.fill.
void settle(const io::Case& the_case, const GrainFill& fill, DemSolver& solver,
            const ParticleStore& store, PhaseMonitor* monitor, std::vector<std::string>& warnings) {
  solver.freeze_walls(true);
  double energy = kinetic_energy_per_grain(store);
  std::size_t steps = 0;
  while (solver.time() < fill.settle_time) {
    solver.step(solver.stable_dt());
    if (++steps % 100 != 0)
      continue;
    if (const auto bad = find_bad_particle(store, solver.domain())) {
      throw io::case_error(the_case, "dem.fill",
                           fmt::format("the grains blew up while settling, at t = {:.6g} s: {}",
                                       solver.time(), *bad));
    }
    if (monitor != nullptr) {
      monitor->update("dem: settling the grains", solver.time(), fill.settle_time, steps,
                      store.size());
      if (monitor->stop_requested())
        throw Interrupted(
            fmt::format("interrupted while settling the grains, at t = {:.6g} s "
                        "of settle_time = {:.6g} s",
                        solver.time(), fill.settle_time));
    }
    energy = kinetic_energy_per_grain(store);
    if (energy < fill.settle_energy && solver.time() > 0.01)
      break;
  }
  if (energy >= fill.settle_energy && fill.settle_time > 0.0) {
    warnings.push_back(fmt::format(
        "{}: dem.fill: the grains did not settle within settle_time = {} s (kinetic energy {:.3g} "
        "J per grain, threshold {:.3g} J); the run starts from a bed still in motion",
        the_case.file, fill.settle_time, energy, fill.settle_energy));
  }
  solver.record_settling(solver.time(), energy);
  solver.freeze_walls(false);
  solver.reset_time();
}

// Species 1 on the side of the split plane its normal points to, 0 elsewhere.
void split_species(const DemSection& section, DemSolver& solver, const ParticleStore& store) {
  if (section.config.species.size() < 2)
    return;
  const GrainFill& fill = *section.fill;
  for (std::size_t i = 0; i < store.size(); ++i) {
    const bool tracer = (store.position()[i] - fill.split_point).dot(fill.split_normal) > 0.0;
    solver.set_species(i, tracer ? 1 : 0);
  }
}

// The grains of the section: filled at random into the fill region, or as the case lists them.
Grains grains_of(const io::Case& the_case, const DemSection& section) {
  Grains grains = section.grains;
  if (section.fill) {
    try {
      grains = insert_random(*section.fill->region, section.fill->insertion);
    } catch (const std::runtime_error& error) {
      throw io::case_error(the_case, "dem.fill", error.what());
    }
  }
  for (std::size_t i = 0; i < grains.position.size(); ++i) {
    const Vec3& x = grains.position[i];
    if (!the_case.domain.contains(x)) {
      throw io::case_error(
          the_case, section.fill ? "dem.fill.region" : section.grains_key,
          fmt::format("grain {} at ({:.6g}, {:.6g}, {:.6g}) lies outside the domain", i, x.x(),
                      x.y(), x.z()));
    }
  }
  return grains;
}

}  // namespace

std::shared_ptr<io::MethodSection> DemMethod::read(io::Reader& root,
                                                   const io::Case& the_case) const {
  return read_dem_section(root, the_case);
}

// For a restore, the grains are inserted (their number and radii define the fields) but not
// settled: the checkpoint holds where they settled and how they moved since. Grains the case
// lists are not settled at all: they start as given.
io::MethodInstance DemMethod::build(const io::Case& the_case, const io::MethodSpec& spec,
                                    const io::BuildOptions& options) const {
  const DemSection& dem = dynamic_cast<const DemSection&>(*spec.section);
  io::MethodInstance instance;
  instance.store = std::make_unique<ParticleStore>();
  const Grains grains = grains_of(the_case, dem);
  std::unique_ptr<DemSolver> solver;
  try {
    solver = std::make_unique<DemSolver>(*instance.store, the_case.domain, dem.config,
                                         the_case.gravity, grains);
  } catch (const InputError& error) {
    throw io::case_error(the_case, error.location().key_path, error.message());
  }
  if (!options.for_restore && dem.fill) {
    settle(the_case, *dem.fill, *solver, *instance.store, options.monitor, instance.warnings);
    split_species(dem, *solver, *instance.store);
  }
  instance.solver = std::move(solver);
  return instance;
}

}  // namespace partimix::dem
