#include "coupling/cfd_dem_type.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "cfd/cfd_section.hpp"
#include "cfd/cfd_solver.hpp"
#include "coupling/cfd_dem_coupling.hpp"
#include "coupling/drag_law.hpp"
#include "dem/dem_section.hpp"
#include "dem/dem_solver.hpp"

namespace partimix::coupling {
namespace {

std::size_t method_index(const io::Case& the_case, const std::string& name) {
  for (std::size_t m = 0; m < the_case.methods.size(); ++m)
    if (the_case.methods[m].name == name)
      return m;
  throw std::logic_error("the case runs no method " + name);
}

// The lagged virtual mass is stable while C_vm ρ / ρ_p < 1 for every species (docs/cfd-dem.md,
// "The forces on a grain").
void check_virtual_mass(io::Reader& item, const io::Case& the_case, double coefficient) {
  const double density = the_case.section<cfd::CfdSection>("cfd").config.settings.density;
  for (const dem::Species& species : the_case.section<dem::DemSection>("dem").config.species) {
    const double ratio = coefficient * density / species.density;
    if (!(ratio < 1.0))
      throw item.error("virtual_mass",
                       fmt::format("C_vm rho / rho_p = {:.3g} for species '{}': the lagged "
                                   "virtual mass needs it below 1",
                                   ratio, species.name));
  }
}

// The weights a mapping may hold, grains times the cells within a kernel's reach, are bounded by
// limits.grid_nodes, so a kernel as wide as the box cannot exhaust the memory or hang the run.
void check_kernel_size(const io::Case& the_case, const io::CouplingSpec& spec,
                       const cfd::CfdSolver& fluid, std::size_t grains, double radius) {
  const grid::StaggeredGrid& grid = fluid.fluid().grid();
  double cells = 1.0;
  for (int axis = 0; axis < grid.dimensions(); ++axis)
    cells *=
        std::min(2.0 * radius / grid.spacing(axis) + 1.0, static_cast<double>(grid.cells(axis)));
  const double weights = cells * static_cast<double>(grains);
  if (weights > the_case.limits.grid_nodes)
    throw io::case_error(the_case, spec.key + ".kernel_radius",
                         fmt::format("a kernel {:.3g} m wide reaches {:.3g} cells per grain, "
                                     "{:.3g} weights for the {} grains: more than "
                                     "limits.grid_nodes = {:.3g}; narrow it or coarsen the cells",
                                     radius, cells, weights, grains, the_case.limits.grid_nodes));
}

}  // namespace

std::shared_ptr<io::CouplingSection> CfdDemType::read(io::Reader& item,
                                                      const io::Case& the_case) const {
  const io::MethodSpec* fluid = the_case.method("cfd");
  const io::MethodSpec* grains = the_case.method("dem");
  if (fluid == nullptr || grains == nullptr)
    throw item.error("type", "cfd_dem couples the methods cfd and dem: name both in `solver`");
  if (method_index(the_case, "cfd") > method_index(the_case, "dem"))
    throw io::case_error(the_case, "solver",
                         "with a cfd_dem coupling list cfd before dem (solver: [cfd, dem]): the "
                         "fluid steps first, then the grains in its new state (docs/cfd-dem.md, "
                         "\"One coupled step\")");
  if (fluid->sub_steps != 1)
    throw io::case_error(the_case, "time.sub_steps.cfd",
                         "with a cfd_dem coupling the fluid takes one step per step of the run "
                         "(the grains sub-cycle: time.sub_steps.dem)");
  auto section = std::make_shared<CfdDemSection>();
  CfdDemSettings& s = section->settings;
  s.drag = item.choice("drag", s.drag, drag_law_registry().names());
  const std::string pressure =
      item.choice("pressure_force", "gradient", {"gradient", "buoyancy", "none"});
  s.pressure_force = pressure == "gradient"   ? PressureForce::gradient
                     : pressure == "buoyancy" ? PressureForce::buoyancy
                                              : PressureForce::none;
  s.divided = item.choice("void_fraction", "kernel", {"kernel", "divided"}) == "divided";
  s.kernel_radius = item.automatic<double>("kernel_radius", io::kPositive);
  s.min_void_fraction =
      item.optional<double>("min_void_fraction", s.min_void_fraction, io::kPositive);
  if (!(s.min_void_fraction < 1.0))
    throw item.error("min_void_fraction", "must lie in (0, 1)");
  s.two_way = item.optional<bool>("two_way", s.two_way);
  s.virtual_mass = item.optional<bool>("virtual_mass", s.virtual_mass);
  s.virtual_mass_coefficient = item.optional<double>("virtual_mass_coefficient",
                                                     s.virtual_mass_coefficient, io::kNonNegative);
  if (s.virtual_mass)
    check_virtual_mass(item, the_case, s.virtual_mass_coefficient);
  s.grain_sub_steps = grains->sub_steps;
  return section;
}

std::unique_ptr<Coupling> CfdDemType::build(const io::Case& the_case, const io::CouplingSpec& spec,
                                            std::span<io::MethodInstance> methods) const {
  const CfdDemSettings& settings = dynamic_cast<const CfdDemSection&>(*spec.section).settings;
  const std::size_t f = method_index(the_case, "cfd");
  const std::size_t g = method_index(the_case, "dem");
  auto& fluid = dynamic_cast<cfd::CfdSolver&>(*methods[f].solver);
  auto& grains = dynamic_cast<dem::DemSolver&>(*methods[g].solver);
  auto coupling = std::make_unique<CfdDemCoupling>(fluid, f, grains, g, *methods[g].store, settings,
                                                   the_case.gravity);
  check_kernel_size(the_case, spec, fluid, grains.particles().size(), coupling->kernel_radius());
  return coupling;
}

}  // namespace partimix::coupling
