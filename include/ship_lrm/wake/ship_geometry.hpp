// Ship geometry as a signed-distance field (thesis 5.1, 6.2): a parametric generic destroyer
// with the NATO Generic Destroyer's proportions, a Simple Frigate Shape 2 preset, and STL import for
// users who have the real geometry. Export as a triangle mesh (STL) for rviz and ParaView.
//
// Ship frame (used by the wake table too): x forward (stern to bow), y starboard, z down (FRD, like
// the rotorcraft's cg frame of thesis fig. 5.4); origin on the centreline at the bottom of the hangar
// doors, the "hangar frame" of thesis 9.1. Lengths in metres.
#pragma once
#include <array>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "ship_lrm/common/vec.hpp"

namespace ship_lrm::wake {

// Unreadable or invalid geometry: a malformed or open STL, bad dimensions.
class GeometryError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

struct Triangle {
  std::array<Vec3, 3> v;
};

// What the wake domain needs to know to place a ship (thesis 6.2): its length over all, where the
// stem meets the waterline, and the waterline's height.
struct ShipDatum {
  double length = 0;     // over all, along x
  double stern_x = 0;    // aftmost x
  double stem_x = 0;     // foremost x at the waterline (the domain's "crossing of waterline and stem")
  double waterline = 0;  // z of the waterline (> 0: below the hangar-door base)
  double beam = 0;       // largest width
  double deck_top = 0;   // z of the highest point (< 0)
};

class ShipGeometry {
 public:
  virtual ~ShipGeometry() = default;
  virtual std::string name() const = 0;
  // Signed distance (m) from p (ship frame) to the surface; negative inside the ship. For the
  // parametric shapes outside the solid it is a lower bound near edges (the sign is exact). It
  // changes by no more than p moves (|gradient| <= 1), which the LRM's voxelisation relies on.
  virtual double signed_distance(const Vec3& p) const = 0;
  virtual bool inside(const Vec3& p) const { return signed_distance(p) < 0.0; }
  virtual const ShipDatum& datum() const = 0;
  // The surface as triangles (outward normals by the right-hand rule).
  virtual std::vector<Triangle> mesh() const = 0;
};

// A union of convex hexahedra (boxes, tapered boxes), each given by 8 corners: bottom face 0-1-2-3,
// top face 4-5-6-7 above them in the same order (VTK hexahedron). Faces must be planar and the
// part convex (checked: GeometryError).
class BlockShip final : public ShipGeometry {
 public:
  struct Block {
    std::string name;
    std::array<Vec3, 8> corners;
  };
  BlockShip(std::string name, std::vector<Block> blocks, double waterline);
  std::string name() const override { return name_; }
  double signed_distance(const Vec3& p) const override;
  const ShipDatum& datum() const override { return datum_; }
  std::vector<Triangle> mesh() const override;
  const std::vector<Block>& blocks() const { return blocks_; }

  // An axis-aligned box from x0..x1, y0..y1, z0..z1 (ship frame).
  static Block box(const std::string& name, double x0, double x1, double y0, double y1, double z0, double z1);

 private:
  struct Plane {
    Vec3 n;  // outward unit normal
    double d;
  };
  std::string name_;
  std::vector<Block> blocks_;
  std::vector<std::array<Plane, 6>> planes_;
  ShipDatum datum_;
};

// Generic destroyer with the NatoGD's proportions at full scale (l = 150 m) times `scale` (1/50 for the
// wind-tunnel model: l = 3 m, thesis table 6.2). Every dimension and its source: docs/design.md.
std::unique_ptr<BlockShip> make_natogd(double scale = 1.0);
// Simple Frigate Shape 2 (TTCP), full scale times `scale`. Dimensions: docs/design.md.
std::unique_ptr<BlockShip> make_sfs2(double scale = 1.0);

// A closed triangle mesh read from STL (binary or ASCII), in metres after `scale`, in the ship frame
// (or z up, y to port when z_up is set, as most CAD exports: converted). Refuses meshes with holes or
// inconsistent orientation (every edge must be traversed as often in one direction as in the other),
// naming the first bad edge, and meshes that enclose no volume; inward-facing normals are turned out.
// One closed surface, or a union of closed parts (as `ship_lrm wake --mesh` exports the block ships):
// inside is their union, by the winding number. The signed distance is exact outside; inside a union
// its magnitude may be too small near a part's face that lies within another part. The waterline is
// the lowest point unless given.
class StlShip final : public ShipGeometry {
 public:
  StlShip(const std::string& path, double scale = 1.0, bool z_up = false, double waterline = std::nan(""));
  std::string name() const override { return name_; }
  double signed_distance(const Vec3& p) const override;
  bool inside(const Vec3& p) const override;
  const ShipDatum& datum() const override { return datum_; }
  std::vector<Triangle> mesh() const override { return tris_; }

 private:
  std::string name_;
  std::vector<Triangle> tris_;
  ShipDatum datum_;
  // buckets of triangle indices over (y, z) for the inside test by the winding number along +x
  double y0_ = 0, z0_ = 0, cell_ = 1;
  int ny_ = 1, nz_ = 1;
  std::vector<std::vector<int>> buckets_;
};

// Reads the triangles of an STL file (binary or ASCII); GeometryError when unreadable.
std::vector<Triangle> read_stl(const std::string& path);
// Writes a binary STL.
void write_stl(const std::string& path, const std::vector<Triangle>& tris, const std::string& header = "ship_lrm");

// "natogd", "sfs2" or a path to an .stl file; scale "model" (1/50) or "full" (1). GeometryError otherwise.
std::unique_ptr<ShipGeometry> make_ship(const std::string& which, const std::string& scale);
// 1/50 for "model", 1 for "full"; GeometryError otherwise.
double ship_scale(const std::string& scale);

}  // namespace ship_lrm::wake
