#include "particles/particle_store.hpp"

#include <stdexcept>

namespace partimix {
namespace {

template <class T, class Scratch>
void permute(std::vector<T>& values, std::span<const std::uint32_t> new_to_old,
             std::vector<Scratch>& scratch) {
  scratch.resize(values.size());
  for (std::size_t k = 0; k < new_to_old.size(); ++k) {
    scratch[k] = static_cast<Scratch>(values[new_to_old[k]]);
  }
  for (std::size_t k = 0; k < new_to_old.size(); ++k) {
    values[k] = static_cast<T>(scratch[k]);
  }
}

template <class T>
const Field<T>* find_in(const std::deque<Field<T>>& fields, const std::string& name) {
  for (const auto& field : fields) {
    if (field.name == name) {
      return &field;
    }
  }
  return nullptr;
}

}  // namespace

ParticleStore::ParticleStore() {
  id_fields_.push_back({"id", "", true, {}});
  ids_ = &id_fields_.back();
  integers_.push_back({"kind", "", true, {}});
  kinds_ = &integers_.back();
  integers_.push_back({"tag", "", true, {}});
  tags_ = &integers_.back();
  vectors_.push_back({"position", "m", false, {}});
  positions_ = &vectors_.back();
  vectors_.push_back({"velocity", "m/s", true, {}});
  velocities_ = &vectors_.back();
  scalars_.push_back({"mass", "kg", false, {}});
  masses_ = &scalars_.back();
}

void ParticleStore::resize(std::size_t count) {
  for (auto& field : scalars_)
    field.values.resize(count, 0.0);
  for (auto& field : vectors_)
    field.values.resize(count, Vec3::Zero());
  for (auto& field : integers_)
    field.values.resize(count, 0);
  for (auto& field : id_fields_)
    field.values.resize(count, 0);
}

bool ParticleStore::has_name(const std::string& name) const {
  return find_in(scalars_, name) || find_in(vectors_, name) || find_in(integers_, name) ||
         find_in(id_fields_, name);
}

Field<double>& ParticleStore::add_scalar(const std::string& name, const std::string& unit,
                                         bool output) {
  if (has_name(name)) {
    throw std::logic_error("particle field '" + name + "' added twice");
  }
  scalars_.push_back({name, unit, output, std::vector<double>(size(), 0.0)});
  return scalars_.back();
}

Field<Vec3>& ParticleStore::add_vector(const std::string& name, const std::string& unit,
                                       bool output) {
  if (has_name(name)) {
    throw std::logic_error("particle field '" + name + "' added twice");
  }
  vectors_.push_back({name, unit, output, std::vector<Vec3>(size(), Vec3::Zero())});
  return vectors_.back();
}

Field<std::int32_t>& ParticleStore::add_integer(const std::string& name, const std::string& unit,
                                                bool output) {
  if (has_name(name)) {
    throw std::logic_error("particle field '" + name + "' added twice");
  }
  integers_.push_back({name, unit, output, std::vector<std::int32_t>(size(), 0)});
  return integers_.back();
}

const Field<double>* ParticleStore::find_scalar(const std::string& name) const {
  return find_in(scalars_, name);
}

const Field<Vec3>* ParticleStore::find_vector(const std::string& name) const {
  return find_in(vectors_, name);
}

const Field<std::int32_t>* ParticleStore::find_integer(const std::string& name) const {
  return find_in(integers_, name);
}

void ParticleStore::reorder(std::span<const std::uint32_t> new_to_old) {
  if (new_to_old.size() != size()) {
    throw std::logic_error("reorder: permutation size differs from particle count");
  }
  for (auto& field : scalars_)
    permute(field.values, new_to_old, scratch_scalar_);
  for (auto& field : vectors_)
    permute(field.values, new_to_old, scratch_vector_);
  for (auto& field : integers_)
    permute(field.values, new_to_old, scratch_integer_);
  for (auto& field : id_fields_)
    permute(field.values, new_to_old, scratch_integer_);
}

std::size_t ParticleStore::bytes() const {
  std::size_t total = scratch_scalar_.capacity() * sizeof(double) +
                      scratch_vector_.capacity() * sizeof(Vec3) +
                      scratch_integer_.capacity() * sizeof(std::int64_t);
  for (const auto& field : scalars_)
    total += field.values.capacity() * sizeof(double);
  for (const auto& field : vectors_)
    total += field.values.capacity() * sizeof(Vec3);
  for (const auto& field : integers_)
    total += field.values.capacity() * sizeof(std::int32_t);
  for (const auto& field : id_fields_)
    total += field.values.capacity() * sizeof(std::int64_t);
  return total;
}

}  // namespace partimix
