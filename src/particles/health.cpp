#include "particles/health.hpp"

#include <cmath>

#include <fmt/format.h>

namespace partimix {
namespace {

std::string where(const ParticleStore& store, std::size_t i) {
  const Vec3& x = store.position()[i];
  return fmt::format("particle {} at ({:.6g}, {:.6g}, {:.6g})", store.id()[i], x.x(), x.y(), x.z());
}

template <class Field, class IsFinite>
std::optional<std::string> first_non_finite(const ParticleStore& store, const Field& field,
                                            IsFinite&& is_finite) {
  for (std::size_t i = 0; i < field.values.size(); ++i) {
    if (!is_finite(field.values[i])) {
      return fmt::format("{} has a non-finite {}", where(store, i), field.name);
    }
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::string> find_bad_particle(const ParticleStore& store, const Domain& domain) {
  for (const auto& field : store.scalar_fields()) {
    auto bad = first_non_finite(store, field, [](double v) { return std::isfinite(v); });
    if (bad)
      return bad;
  }
  for (const auto& field : store.vector_fields()) {
    auto bad = first_non_finite(store, field, [](const Vec3& v) { return v.allFinite(); });
    if (bad)
      return bad;
  }
  for (std::size_t i = 0; i < store.size(); ++i) {
    if (!domain.contains(store.position()[i])) {
      return where(store, i) + " left the domain";
    }
  }
  return std::nullopt;
}

}  // namespace partimix
