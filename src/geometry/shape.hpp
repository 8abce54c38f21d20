#pragma once
// Shapes known by their signed distance (negative inside) and bounding box. Lattice samplers fill
// a shape or lay wall layers around it from these two alone, so any new shape gets both.
#include "core/vec.hpp"

namespace partimix::geometry {

class Shape {
 public:
  virtual ~Shape() = default;
  virtual double signed_distance(const Vec3& x) const = 0;
  virtual Vec3 lower() const = 0;
  virtual Vec3 upper() const = 0;
};

// Axis-aligned box [lo, hi].
class Box final : public Shape {
 public:
  Box(const Vec3& lo, const Vec3& hi) : lo_(lo), hi_(hi) {}
  double signed_distance(const Vec3& x) const override;
  Vec3 lower() const override { return lo_; }
  Vec3 upper() const override { return hi_; }

 private:
  Vec3 lo_;
  Vec3 hi_;
};

// Solid cylinder along z: base centre, radius, height. As a wall it is a vessel: side and
// bottom, with the top left open by the wall's open faces.
class Cylinder final : public Shape {
 public:
  Cylinder(const Vec3& base_centre, double radius, double height)
      : base_(base_centre), radius_(radius), height_(height) {}
  double signed_distance(const Vec3& x) const override;
  Vec3 lower() const override { return base_ - Vec3(radius_, radius_, 0.0); }
  Vec3 upper() const override { return base_ + Vec3(radius_, radius_, height_); }

 private:
  Vec3 base_;
  double radius_;
  double height_;
};

}  // namespace partimix::geometry
