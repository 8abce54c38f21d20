#include "mpm/point_fill.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "core/error.hpp"
#include "geometry/lattice.hpp"
#include "materials/granular/granular_stress.hpp"

namespace partimix::mpm {
namespace {

std::vector<Vec3> lattice_of(const PointFill& fill, std::size_t index, const Domain& domain,
                             const io::SizeLimits& limits) {
  geometry::LatticeOptions options;
  options.visits = limits.lattice_points;
  options.points = limits.particles;
  std::vector<Vec3> points;
  try {
    points = geometry::fill(*fill.region, fill.spacing, domain, options);
  } catch (const InputError& error) {
    throw InputError({"", 0, 0, fmt::format("mpm.fill[{}].spacing", index)}, error.message());
  }
  if (points.empty()) {
    throw InputError(
        {"", 0, 0, fmt::format("mpm.fill[{}].region", index)},
        fmt::format("the region holds no lattice point of spacing {:.6g} m", fill.spacing));
  }
  return points;
}

// Geostatic stress at depth z below the free surface along gravity's direction g_hat: vertical
// -rho_c |g| z, horizontal K0 times it (docs/mpm.md, "Filling").
Mat3 geostatic_stress(const materials::GranularMaterial& material, const PointFill& fill,
                      const Vec3& gravity, double depth) {
  const double k0 = fill.lateral_stress_ratio.value_or(1.0 - std::sin(std::atan(material.mu_s)));
  const Vec3 down = gravity.normalized();
  const double vertical = -material.density * gravity.norm() * depth;
  const Mat3 along = down * down.transpose();
  return vertical * (k0 * (Mat3::Identity() - along) + along);
}

void add_fill(const MpmConfig& config, std::size_t index, const std::vector<Vec3>& points,
              const Domain& domain, const Vec3& gravity, ParticleStore& store,
              PointFields& fields) {
  const PointFill& fill = config.fills[index];
  const materials::GranularMaterial& material = config.materials[fill.material];
  const double share = std::pow(fill.spacing, domain.dimensions);
  const bool geostatic = fill.geostatic && gravity.norm() > 0.0;
  double top = -std::numeric_limits<double>::infinity();
  const Vec3 up = geostatic ? Vec3(-gravity.normalized()) : Vec3::Zero();
  for (const Vec3& x : points)
    top = std::max(top, up.dot(x) + 0.5 * fill.spacing);
  const std::size_t first = store.size();
  store.resize(first + points.size());
  for (std::size_t k = 0; k < points.size(); ++k) {
    const std::size_t p = first + k;
    store.id()[p] = static_cast<std::int64_t>(p);
    store.kind()[p] = static_cast<std::int32_t>(ParticleKind::material_point);
    store.tag()[p] = fill.tag;
    store.position()[p] = points[k];
    store.velocity()[p] = fill.velocity;
    store.mass()[p] = material.density * share;
    fields.material.values[p] = fill.material;
    const Mat3 stress = geostatic
                            ? geostatic_stress(material, fill, gravity, top - up.dot(points[k]))
                            : Mat3::Zero();
    const double pressure = -stress.trace() / 3.0;
    fields.set_stress(p, stress);
    fields.pressure.values[p] = pressure;
    fields.density.values[p] = material.density * std::exp(pressure / material.bulk_modulus());
    fields.volume.values[p] = store.mass()[p] / fields.density.values[p];
    fields.volumetric_strain.values[p] = pressure / material.bulk_modulus();
  }
}

}  // namespace

void fill_points(const MpmConfig& config, const Domain& domain, const Vec3& gravity,
                 const io::SizeLimits& limits, ParticleStore& store, PointFields& fields) {
  for (std::size_t i = 0; i < config.fills.size(); ++i) {
    const std::vector<Vec3> points = lattice_of(config.fills[i], i, domain, limits);
    if (static_cast<double>(store.size() + points.size()) > limits.particles) {
      throw InputError({"", 0, 0, fmt::format("mpm.fill[{}].spacing", i)},
                       fmt::format("the fills hold more than limits.particles = {:.3g} points",
                                   limits.particles));
    }
    add_fill(config, i, points, domain, gravity, store, fields);
  }
}

}  // namespace partimix::mpm
