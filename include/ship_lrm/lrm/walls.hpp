// Solid bodies in the LRM domain, described by signed distance (docs/design.md, "Walls in
// the domain"): the ground or a ship deck, which move relative to the domain, and the fuselage, which is
// fixed to it. The domain voxelises them: a cell whose centre lies inside (distance < 0) becomes a
// no-slip wall with halfway bounce-back (Ladd 1994), moving with the body's rigid motion.
#pragma once

#include <string>

#include "ship_lrm/common/vec.hpp"

namespace ship_lrm::lrm {

// Rigid-body velocity field of a solid relative to the domain: u(r) = velocity + omega x r, with r
// from the hub (mr axes, m/s, rad/s).
struct RigidMotion {
  Vec3 velocity = Vec3::Zero();
  Vec3 omega = Vec3::Zero();
  bool moving() const { return !(velocity.isZero(0) && omega.isZero(0)); }
};

class WallSurface {
 public:
  virtual ~WallSurface() = default;
  virtual std::string name() const = 0;
  // Signed distance (m) from p (m, mr axes, from the hub) to the surface; negative inside the solid.
  // It may underestimate the distance but must change by no more than p moves (|gradient| <= 1):
  // the voxelisation skips blocks of cells on that bound (LrmDomain::update_walls).
  virtual double signed_distance(const Vec3& p) const = 0;
  // Motion relative to the domain; a body fixed to the rotorcraft (the fuselage) has none.
  virtual RigidMotion motion() const { return {}; }
  // Keep this body out of the two outermost cell layers (thesis 6.4, fig. 9.3: the gap between the
  // ship's walls and the LRM's faces is fluid, fed by the faces). A body that moves through the faces
  // otherwise turns open-boundary cells into walls and back, which disturbs the flow (known defect,
  // test_ship_walls.cpp) and made the approach diverge where the hull entered the domain.
  virtual bool clear_of_faces() const { return false; }
  // Free slip instead of no slip: the cells inside become slip walls (lbm::CellType::SlipWall), which
  // reflect specularly where they form a plane and bounce back at edges and corners. A slip wall has no
  // tangential velocity to impose, so the body may only slide along itself: motion() must not move it
  // across its surface (LrmDomain refuses it otherwise). Meant for a level ground at full-scale
  // Reynolds numbers, whose boundary layer the LRM's cells cannot resolve.
  virtual bool slip() const { return false; }
};

// Flat ground (or sea, or a deck larger than the domain): the solid half-space more than `height`
// below the hub along the unit vector `down` (mr axes; +z when the rotor is level).
class GroundPlane final : public WallSurface {
 public:
  explicit GroundPlane(double height, const Vec3& down = Vec3::UnitZ());
  std::string name() const override { return "ground"; }
  double signed_distance(const Vec3& p) const override { return height_ - p.dot(down_); }
  RigidMotion motion() const override { return motion_; }
  // New pose (a climbing or pitching rotorcraft) and motion relative to the domain: for ground at rest
  // in the world, velocity = -hub velocity over ground and omega = -(the domain's angular velocity).
  void set_pose(double height, const Vec3& down);
  void set_motion(const RigidMotion& m) { motion_ = m; }
  double height() const { return height_; }
  bool clear_of_faces() const override { return clear_of_faces_; }
  void set_clear_of_faces(bool on) { clear_of_faces_ = on; }
  bool slip() const override { return slip_; }
  void set_slip(bool on) { slip_ = on; }

 private:
  double height_;
  Vec3 down_;
  RigidMotion motion_;
  bool clear_of_faces_ = false;
  bool slip_ = false;
};

// A Bo 105-like fuselage fixed to the domain: an ellipsoidal cabin below the hub and a tail boom
// (a capsule) to the tail rotor. Dimensions are estimates from the published overall data
// (fuselage length 8.56 m, width 1.58 m, hub 1.49 m above the cg: thesis table 6.5, Padfield
// appendix 4B); see docs/design.md.
class Fuselage final : public WallSurface {
 public:
  struct Shape {
    Vec3 cabin_centre{0.25, 0.0, 1.55};     // m from the hub, mr axes [EST]
    Vec3 cabin_semi_axes{2.2, 0.79, 0.75};  // m: length 4.4, width 1.58 [EST from the 1.58 m width]
    Vec3 boom_start{-1.6, 0.0, 1.25};       // m from the hub [EST]
    Vec3 boom_end{-6.0, 0.0, 1.0};          // fin base below the tail rotor (6.0 m aft of the cg [P4B]) [EST]; fin not modelled
    double boom_radius = 0.35;              // m [EST]
  };
  Fuselage() : Fuselage(Shape{}) {}
  explicit Fuselage(const Shape& s) : s_(s) {}
  std::string name() const override { return "fuselage"; }
  double signed_distance(const Vec3& p) const override;

 private:
  Shape s_;
};

}  // namespace ship_lrm::lrm
