#pragma once
// Structure-of-arrays particle storage (DESIGN.md, "Data and speed"): one contiguous array per
// quantity, indexed by particle. Every store has the core fields id, kind, tag, position,
// velocity and mass; a method adds its own named fields (density, pressure, ...) at set-up.
// Writers and analyses find fields by name; the hot loops hold direct references.
#include <cstdint>
#include <deque>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "core/vec.hpp"

namespace partimix {

// What a particle is. Wall particles are fixed boundary particles of a vessel or body (SPH);
// grains are the spheres of DEM; material points carry a continuum (MPM). Fluid, grains and
// material points are the material that analyses measure.
enum class ParticleKind : std::int32_t { fluid = 0, wall = 1, grain = 2, material_point = 3 };

template <class T>
struct Field {
  std::string name;
  std::string unit;
  bool output = true;  // written to VTK frames
  std::vector<T> values;
};

class ParticleStore {
 public:
  ParticleStore();
  ParticleStore(const ParticleStore&) = delete;
  ParticleStore& operator=(const ParticleStore&) = delete;

  std::size_t size() const { return ids_->values.size(); }

  // Resizes every field; new entries are zero. Allocation happens here, never per step.
  void resize(std::size_t count);

  // Adds a named field (names are unique across all fields). The returned reference stays
  // valid for the life of the store.
  Field<double>& add_scalar(const std::string& name, const std::string& unit, bool output = true);
  Field<Vec3>& add_vector(const std::string& name, const std::string& unit, bool output = true);
  Field<std::int32_t>& add_integer(const std::string& name, const std::string& unit,
                                   bool output = true);

  // Finds a field by name; nullptr if absent.
  const Field<double>* find_scalar(const std::string& name) const;
  const Field<Vec3>* find_vector(const std::string& name) const;
  // The same, writable: to set a method's field at set-up (an initial angular velocity, the
  // density of a pressure field).
  Field<double>* find_scalar(const std::string& name) {
    return const_cast<Field<double>*>(std::as_const(*this).find_scalar(name));
  }
  Field<Vec3>* find_vector(const std::string& name) {
    return const_cast<Field<Vec3>*>(std::as_const(*this).find_vector(name));
  }
  const Field<std::int32_t>* find_integer(const std::string& name) const;

  std::vector<std::int64_t>& id() { return ids_->values; }
  std::vector<std::int32_t>& kind() { return kinds_->values; }
  std::vector<std::int32_t>& tag() { return tags_->values; }
  std::vector<Vec3>& position() { return positions_->values; }
  std::vector<Vec3>& velocity() { return velocities_->values; }
  std::vector<double>& mass() { return masses_->values; }
  const std::vector<std::int64_t>& id() const { return ids_->values; }
  const std::vector<std::int32_t>& kind() const { return kinds_->values; }
  const std::vector<std::int32_t>& tag() const { return tags_->values; }
  const std::vector<Vec3>& position() const { return positions_->values; }
  const std::vector<Vec3>& velocity() const { return velocities_->values; }
  const std::vector<double>& mass() const { return masses_->values; }

  bool is_fluid(std::size_t i) const {
    return kinds_->values[i] == static_cast<std::int32_t>(ParticleKind::fluid);
  }

  // A particle of the material a method moves (SPH fluid or DEM grain), not a wall.
  bool is_material(std::size_t i) const {
    return kinds_->values[i] != static_cast<std::int32_t>(ParticleKind::wall);
  }

  const std::deque<Field<double>>& scalar_fields() const { return scalars_; }
  const std::deque<Field<Vec3>>& vector_fields() const { return vectors_; }
  const std::deque<Field<std::int32_t>>& integer_fields() const { return integers_; }
  const std::deque<Field<std::int64_t>>& id_fields() const { return id_fields_; }
  // The same, writable: to set the values of every field at once (restoring a checkpoint); the
  // fields themselves are added only through add_scalar and its kin.
  std::deque<Field<double>>& scalar_fields() { return scalars_; }
  std::deque<Field<Vec3>>& vector_fields() { return vectors_; }
  std::deque<Field<std::int32_t>>& integer_fields() { return integers_; }
  std::deque<Field<std::int64_t>>& id_fields() { return id_fields_; }

  // Reorders every field so that new particle k is old particle new_to_old[k]. Uses scratch
  // buffers kept between calls, so it does not allocate once they have grown to size.
  void reorder(std::span<const std::uint32_t> new_to_old);

  // Bytes held by all fields and scratch buffers (for the memory-per-particle figures).
  std::size_t bytes() const;

 private:
  bool has_name(const std::string& name) const;

  std::deque<Field<double>> scalars_;
  std::deque<Field<Vec3>> vectors_;
  std::deque<Field<std::int32_t>> integers_;
  std::deque<Field<std::int64_t>> id_fields_;
  Field<std::int64_t>* ids_;
  Field<std::int32_t>* kinds_;
  Field<std::int32_t>* tags_;
  Field<Vec3>* positions_;
  Field<Vec3>* velocities_;
  Field<double>* masses_;
  std::vector<double> scratch_scalar_;
  std::vector<Vec3> scratch_vector_;
  std::vector<std::int64_t> scratch_integer_;
};

}  // namespace partimix
