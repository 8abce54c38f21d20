#include "dem/dem_method.hpp"

#include <stdexcept>

#include <fmt/format.h>

#include "core/error.hpp"
#include "dem/dem_solver.hpp"
#include "dem/insertion.hpp"

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
void settle(const io::Case& the_case, const GrainFill& fill, DemSolver& solver,
            const ParticleStore& store, std::vector<std::string>& warnings) {
  solver.freeze_walls(true);
  double energy = kinetic_energy_per_grain(store);
  long steps = 0;
  while (solver.time() < fill.settle_time) {
    solver.step(solver.stable_dt());
    if (++steps % 100 != 0)
      continue;
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
  const GrainFill& fill = section.fill;
  for (std::size_t i = 0; i < store.size(); ++i) {
    const bool tracer = (store.position()[i] - fill.split_point).dot(fill.split_normal) > 0.0;
    solver.set_species(i, tracer ? 1 : 0);
  }
}

Grains insert(const io::Case& the_case, const GrainFill& fill) {
  Grains grains;
  try {
    grains = insert_random(*fill.region, fill.insertion);
  } catch (const std::runtime_error& error) {
    throw io::case_error(the_case, "dem.fill", error.what());
  }
  for (const Vec3& x : grains.position) {
    if (!the_case.domain.contains(x))
      throw io::case_error(the_case, "dem.fill.region",
                           "the fill region reaches outside the domain");
  }
  return grains;
}

}  // namespace

std::shared_ptr<io::MethodSection> DemMethod::read(io::Reader& root,
                                                   const io::Case& the_case) const {
  return read_dem_section(root, the_case);
}

// For a restore, the grains are inserted (their number and radii define the fields) but not
// settled: the checkpoint holds where they settled and how they moved since.
io::MethodInstance DemMethod::build(const io::Case& the_case, const io::MethodSpec& spec,
                                    const io::BuildOptions& options) const {
  const DemSection& dem = dynamic_cast<const DemSection&>(*spec.section);
  io::MethodInstance instance;
  instance.store = std::make_unique<ParticleStore>();
  const Grains grains = insert(the_case, dem.fill);
  std::unique_ptr<DemSolver> solver;
  try {
    solver = std::make_unique<DemSolver>(*instance.store, the_case.domain, dem.config,
                                         the_case.gravity, grains);
  } catch (const InputError& error) {
    throw io::case_error(the_case, error.location().key_path, error.message());
  }
  if (!options.for_restore) {
    settle(the_case, dem.fill, *solver, *instance.store, instance.warnings);
    split_species(dem, *solver, *instance.store);
  }
  instance.solver = std::move(solver);
  return instance;
}

}  // namespace partimix::dem
