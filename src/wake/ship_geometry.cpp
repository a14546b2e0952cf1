// Ship geometry as a signed-distance field (see ship_geometry.hpp).
#include "ship_lrm/wake/ship_geometry.hpp"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>

namespace ship_lrm::wake {
namespace {

// Face corner indices of a VTK hexahedron (bottom, top, four sides).
constexpr int kFaces[6][4] = {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};

// Closest distance from p to triangle abc (Ericson, Real-Time Collision Detection, 5.1.5).
double point_triangle_distance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return (p - a).norm();
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return (p - b).norm();
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return (p - (a + ab * (d1 / (d1 - d3)))).norm();
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return (p - c).norm();
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return (p - (a + ac * (d2 / (d2 - d6)))).norm();
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return (p - (b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6))))).norm();
  const double denom = 1.0 / (va + vb + vc);
  return (p - (a + ab * (vb * denom) + ac * (vc * denom))).norm();
}

ShipDatum datum_of(const std::vector<Triangle>& tris, double waterline) {
  ShipDatum d;
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const auto& t : tris)
    for (const auto& v : t.v) {
      lo = lo.cwiseMin(v);
      hi = hi.cwiseMax(v);
    }
  d.length = hi.x() - lo.x();
  d.stern_x = lo.x();
  d.beam = hi.y() - lo.y();
  d.deck_top = lo.z();
  d.waterline = std::isnan(waterline) ? hi.z() : waterline;
  // the stem: foremost point at or above the waterline
  d.stem_x = lo.x();
  for (const auto& t : tris)
    for (const auto& v : t.v)
      if (v.z() <= d.waterline + 1e-9 * d.length) d.stem_x = std::max(d.stem_x, v.x());
  return d;
}

}  // namespace

// ---- block ships --------------------------------------------------------------------------------

BlockShip::Block BlockShip::box(const std::string& name, double x0, double x1, double y0, double y1, double z0, double z1) {
  Block b;
  b.name = name;
  b.corners = {Vec3(x0, y0, z1), Vec3(x1, y0, z1), Vec3(x1, y1, z1), Vec3(x0, y1, z1),
               Vec3(x0, y0, z0), Vec3(x1, y0, z0), Vec3(x1, y1, z0), Vec3(x0, y1, z0)};
  return b;
}

BlockShip::BlockShip(std::string name, std::vector<Block> blocks, double waterline) : name_(std::move(name)), blocks_(std::move(blocks)) {
  if (blocks_.empty()) throw GeometryError("ship '" + name_ + "': no blocks");
  for (const auto& b : blocks_) {
    Vec3 centre = Vec3::Zero();
    for (const auto& c : b.corners) {
      if (!c.allFinite()) throw GeometryError("ship block '" + b.name + "': a corner is not finite");
      centre += c / 8.0;
    }
    double size = 0;
    for (const auto& c : b.corners) size = std::max(size, (c - centre).norm());
    std::array<Plane, 6> planes;
    for (int f = 0; f < 6; ++f) {
      const Vec3& a = b.corners[kFaces[f][0]];
      const Vec3& c1 = b.corners[kFaces[f][1]];
      const Vec3& c3 = b.corners[kFaces[f][3]];
      Vec3 n = (c1 - a).cross(c3 - a);
      if (n.norm() < 1e-12 * size * size) n = (b.corners[kFaces[f][2]] - c1).cross(c3 - c1);  // a wedge face
      if (n.norm() < 1e-12 * size * size) throw GeometryError("ship block '" + b.name + "': degenerate face");
      n.normalize();
      if (n.dot(centre - a) > 0) n = -n;
      planes[f] = {n, n.dot(a)};
      for (int k = 0; k < 4; ++k)
        if (std::abs(n.dot(b.corners[kFaces[f][k]]) - planes[f].d) > 1e-9 * size)
          throw GeometryError("ship block '" + b.name + "': face " + std::to_string(f) + " is not planar");
    }
    for (const auto& c : b.corners)
      for (const auto& pl : planes)
        if (pl.n.dot(c) - pl.d > 1e-9 * size) throw GeometryError("ship block '" + b.name + "' is not convex");
    planes_.push_back(planes);
  }
  datum_ = datum_of(mesh(), waterline);
}

double BlockShip::signed_distance(const Vec3& p) const {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& planes : planes_) {
    double d = -std::numeric_limits<double>::infinity();
    for (const auto& pl : planes) d = std::max(d, pl.n.dot(p) - pl.d);
    best = std::min(best, d);
  }
  return best;
}

std::vector<Triangle> BlockShip::mesh() const {
  std::vector<Triangle> out;
  for (std::size_t b = 0; b < blocks_.size(); ++b)
    for (int f = 0; f < 6; ++f) {
      const auto& c = blocks_[b].corners;
      const Vec3 &p0 = c[kFaces[f][0]], &p1 = c[kFaces[f][1]], &p2 = c[kFaces[f][2]], &p3 = c[kFaces[f][3]];
      const bool flip = (p1 - p0).cross(p3 - p0).dot(planes_[b][f].n) < 0;
      for (const auto& t : {std::array<Vec3, 3>{p0, p1, p2}, std::array<Vec3, 3>{p0, p2, p3}}) {
        if ((t[1] - t[0]).cross(t[2] - t[0]).norm() == 0) continue;  // a wedge's collapsed half
        out.push_back(flip ? Triangle{{t[0], t[2], t[1]}} : Triangle{t});
      }
    }
  return out;
}

// Generic destroyer with the NatoGD's proportions. The NRC geometry (thesis ref. [12]) is not public
// here; the proportions follow the NatoGD schematic (thesis fig. 5.2, dimensions withheld in our copy)
// as closely as we could reconstruct them: every value is an estimate [EST], listed with its reasoning
// in docs/design.md. Full scale: l = 150 m (thesis table 6.3).
std::unique_ptr<BlockShip> make_natogd(double s) {
  if (!(s > 0)) throw GeometryError("ship scale must be > 0");
  const double deck_len = 25.5;    // flight deck, stern to hangar door [EST, 0.17 l]
  const double stern = -deck_len;  // origin at the hangar door base
  const double bow = stern + 150.0;
  const double half_beam = 9.0;         // beam 18 m [EST, 0.12 l]
  const double freeboard = 6.5;         // deck above the waterline at the stern [EST]
  const double keel = freeboard + 2.0;  // hull continues below the waterline into the sea [model choice]
  const double taper_start = 80.0;      // where the bow starts to narrow [EST]
  std::vector<BlockShip::Block> b;
  b.push_back(BlockShip::box("hull", stern, taper_start, -half_beam, half_beam, 0.0, keel));
  BlockShip::Block bowb;
  bowb.name = "bow";
  const double tip = 0.5;  // half-width at the stem
  bowb.corners = {Vec3(taper_start, -half_beam, keel), Vec3(bow, -tip, keel), Vec3(bow, tip, keel), Vec3(taper_start, half_beam, keel),
                  Vec3(taper_start, -half_beam, -2.0), Vec3(bow, -tip, -2.0), Vec3(bow, tip, -2.0), Vec3(taper_start, half_beam, -2.0)};
  b.push_back(bowb);                                                                     // forecastle 2 m above the main deck [EST]
  b.push_back(BlockShip::box("hangar", 0.0, 20.0, -7.0, 7.0, -7.0, 0.0));                // door 14 m wide, 7 m high [EST]
  b.push_back(BlockShip::box("aft superstructure", 20.0, 45.0, -7.0, 7.0, -10.0, 0.0));  // [EST]
  b.push_back(BlockShip::box("funnel", 33.0, 43.0, -3.5, 3.5, -17.0, -10.0));            // [EST]
  b.push_back(BlockShip::box("bridge", 55.0, 75.0, -7.0, 7.0, -13.0, 0.0));              // [EST]
  b.push_back(BlockShip::box("mast", 60.0, 63.0, -1.25, 1.25, -30.0, -13.0));            // [EST]
  for (auto& block : b)
    for (auto& c : block.corners) c *= s;
  return std::make_unique<BlockShip>(s == 1.0 ? "natogd" : "natogd x" + std::to_string(s), std::move(b), freeboard * s);
}

// Simple Frigate Shape 2 (TTCP): a 138.68 m (455 ft) frigate with a 13.72 m (45 ft) beam, a flush deck,
// a two-step superstructure and a flight deck at the stern. Dimensions as we recall them from the
// published SFS2 descriptions [EST, verify against the TTCP drawings]; see docs/design.md.
std::unique_ptr<BlockShip> make_sfs2(double s) {
  if (!(s > 0)) throw GeometryError("ship scale must be > 0");
  const double deck_len = 27.43;  // 90 ft [EST]
  const double stern = -deck_len, bow = stern + 138.68;
  const double hb = 13.72 / 2, freeboard = 6.10, keel = freeboard + 2.0;
  const double taper_start = bow - 27.43;  // [EST]
  std::vector<BlockShip::Block> b;
  b.push_back(BlockShip::box("hull", stern, taper_start, -hb, hb, 0.0, keel));
  BlockShip::Block bowb;
  bowb.name = "bow";
  const double tip = 0.25;  // half-width at the stem (a wedge needs an edge, not a point)
  bowb.corners = {Vec3(taper_start, -hb, keel), Vec3(bow, -tip, keel), Vec3(bow, tip, keel), Vec3(taper_start, hb, keel),
                  Vec3(taper_start, -hb, 0.0),  Vec3(bow, -tip, 0.0),  Vec3(bow, tip, 0.0),  Vec3(taper_start, hb, 0.0)};
  b.push_back(bowb);
  b.push_back(BlockShip::box("hangar", 0.0, 21.34, -hb, hb, -6.10, 0.0));             // 70 ft long, 20 ft high [EST]
  b.push_back(BlockShip::box("superstructure", 21.34, 48.77, -hb, hb, -12.19, 0.0));  // second step 40 ft [EST]
  for (auto& block : b)
    for (auto& c : block.corners) c *= s;
  return std::make_unique<BlockShip>(s == 1.0 ? "sfs2" : "sfs2 x" + std::to_string(s), std::move(b), freeboard * s);
}

// ---- STL --------------------------------------------------------------------------------------------

std::vector<Triangle> read_stl(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw GeometryError("cannot open STL file '" + path + "'");
  std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::vector<Triangle> tris;
  if (data.size() >= 84) {
    std::uint32_t n = 0;
    std::memcpy(&n, data.data() + 80, 4);
    if (data.size() == 84 + 50ull * n) {  // binary
      for (std::uint32_t k = 0; k < n; ++k) {
        Triangle t;
        for (int v = 0; v < 3; ++v) {
          float xyz[3];
          std::memcpy(xyz, data.data() + 84 + 50ull * k + 12 + 12 * v, 12);
          t.v[v] = Vec3(xyz[0], xyz[1], xyz[2]);
        }
        tris.push_back(t);
      }
      if (tris.empty()) throw GeometryError("STL file '" + path + "' has no triangles");
      return tris;
    }
  }
  // ASCII: solid ... facet normal ... outer loop vertex x y z (x3) endloop endfacet ... endsolid
  std::istringstream s(data);
  std::string word;
  if (!(s >> word) || word != "solid")
    throw GeometryError("'" + path + "' is neither a binary STL (size does not match its triangle count) nor an ASCII STL");
  Triangle t;
  int v = 0;
  while (s >> word) {
    if (word == "vertex") {
      double x, y, z;
      if (!(s >> x >> y >> z))
        throw GeometryError("STL file '" + path + "': malformed vertex after triangle " + std::to_string(tris.size()));
      if (v >= 3) throw GeometryError("STL file '" + path + "': a facet with more than 3 vertices");
      t.v[v++] = Vec3(x, y, z);
    } else if (word == "endloop") {
      if (v != 3) throw GeometryError("STL file '" + path + "': a facet without 3 vertices");
      tris.push_back(t);
      v = 0;
    }
  }
  if (tris.empty()) throw GeometryError("STL file '" + path + "' has no triangles");
  return tris;
}

void write_stl(const std::string& path, const std::vector<Triangle>& tris, const std::string& header) {
  std::ofstream out(path, std::ios::binary);
  if (!out) throw GeometryError("cannot write '" + path + "'");
  char head[80] = {};
  std::memcpy(head, header.data(), std::min<std::size_t>(header.size(), 79));
  out.write(head, 80);
  const std::uint32_t n = static_cast<std::uint32_t>(tris.size());
  out.write(reinterpret_cast<const char*>(&n), 4);
  for (const auto& t : tris) {
    Vec3 nrm = (t.v[1] - t.v[0]).cross(t.v[2] - t.v[0]);
    if (nrm.norm() > 0) nrm.normalize();
    float rec[12];
    for (int d = 0; d < 3; ++d) rec[d] = static_cast<float>(nrm[d]);
    for (int v = 0; v < 3; ++v)
      for (int d = 0; d < 3; ++d) rec[3 + 3 * v + d] = static_cast<float>(t.v[v][d]);
    out.write(reinterpret_cast<const char*>(rec), sizeof rec);
    const std::uint16_t attr = 0;
    out.write(reinterpret_cast<const char*>(&attr), 2);
  }
  if (!out) throw GeometryError("writing '" + path + "' failed");
}

StlShip::StlShip(const std::string& path, double scale, bool z_up, double waterline) : name_(path), tris_(read_stl(path)) {
  if (!(scale > 0)) throw GeometryError("STL scale must be > 0");
  for (auto& t : tris_)
    for (auto& v : t.v) {
      if (!v.allFinite()) throw GeometryError("STL file '" + path + "' has a non-finite vertex");
      v *= scale;
      if (z_up) v = Vec3(v.x(), -v.y(), -v.z());  // z up, y to port -> z down, y starboard
    }
  // closed and consistently oriented: each directed edge as often as its reverse. A single closed
  // surface has each once; a union of closed parts (the block ships' export by --mesh: hull,
  // superstructure and hangar as overlapping boxes) may share an edge between parts.
  std::map<std::array<float, 3>, int> ids;
  const auto id = [&](const Vec3& v) {
    const std::array<float, 3> key{static_cast<float>(v.x()), static_cast<float>(v.y()), static_cast<float>(v.z())};
    return ids.emplace(key, static_cast<int>(ids.size())).first->second;
  };
  std::map<std::pair<int, int>, int> edges;
  for (const auto& t : tris_) {
    const int a = id(t.v[0]), b = id(t.v[1]), c = id(t.v[2]);
    if (a == b || b == c || a == c) continue;  // degenerate (zero-area) triangle: ignored
    for (auto e : {std::make_pair(a, b), std::make_pair(b, c), std::make_pair(c, a)}) ++edges[e];
  }
  for (const auto& [e, count] : edges) {
    const auto rev = edges.find({e.second, e.first});
    if (rev == edges.end() || rev->second != count) {
      Vec3 p = Vec3::Zero();
      for (const auto& [key, i] : ids)
        if (i == e.first) p = Vec3(key[0], key[1], key[2]);
      throw GeometryError("STL file '" + path +
                          "' is not a closed, consistently oriented surface (a hole or a flipped triangle at the edge from (" +
                          std::to_string(p.x()) + ", " + std::to_string(p.y()) + ", " + std::to_string(p.z()) +
                          ")); repair it (e.g. with MeshLab or admesh) and try again");
    }
  }
  // the inside test counts crossings with the sign of the outward normal: orient the surface outward
  // (a positive enclosed volume, divergence theorem)
  double volume = 0, extent = 0;
  for (const auto& t : tris_) {
    volume += t.v[0].dot(t.v[1].cross(t.v[2])) / 6.0;
    for (const auto& v : t.v) extent = std::max(extent, v.cwiseAbs().maxCoeff());
  }
  if (!(std::abs(volume) > 1e-12 * extent * extent * extent)) throw GeometryError("STL file '" + path + "' encloses no volume");
  if (volume < 0)
    for (auto& t : tris_) std::swap(t.v[1], t.v[2]);
  datum_ = datum_of(tris_, waterline);
  // buckets over (y, z)
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const auto& t : tris_)
    for (const auto& v : t.v) {
      lo = lo.cwiseMin(v);
      hi = hi.cwiseMax(v);
    }
  const double span = std::max({hi.y() - lo.y(), hi.z() - lo.z(), 1e-9});
  const int per_side = std::clamp(static_cast<int>(std::sqrt(tris_.size() / 4.0)), 1, 256);
  cell_ = span / per_side;
  y0_ = lo.y();
  z0_ = lo.z();
  ny_ = static_cast<int>((hi.y() - lo.y()) / cell_) + 1;
  nz_ = static_cast<int>((hi.z() - lo.z()) / cell_) + 1;
  buckets_.assign(static_cast<std::size_t>(ny_) * nz_, {});
  for (int k = 0; k < static_cast<int>(tris_.size()); ++k) {
    double ya = 1e300, yb = -1e300, za = 1e300, zb = -1e300;
    for (const auto& v : tris_[k].v) {
      ya = std::min(ya, v.y());
      yb = std::max(yb, v.y());
      za = std::min(za, v.z());
      zb = std::max(zb, v.z());
    }
    for (int j = std::max(0, static_cast<int>((ya - y0_) / cell_)); j <= std::min(ny_ - 1, static_cast<int>((yb - y0_) / cell_)); ++j)
      for (int l = std::max(0, static_cast<int>((za - z0_) / cell_)); l <= std::min(nz_ - 1, static_cast<int>((zb - z0_) / cell_)); ++l)
        buckets_[j + static_cast<std::size_t>(ny_) * l].push_back(k);
  }
}

bool StlShip::inside(const Vec3& p0) const {
  // winding number along a ray in +x: +1 where it leaves through an outward face, -1 where it enters;
  // inside where the sum is positive (for one closed surface the parity rule, for a union of
  // overlapping closed parts the union). A tiny irrational offset keeps the ray off edges and vertices.
  const Vec3 p = p0 + Vec3(0, 1.2345678e-7, 2.3456789e-7) * cell_;
  const int j = static_cast<int>(std::floor((p.y() - y0_) / cell_)), l = static_cast<int>(std::floor((p.z() - z0_) / cell_));
  if (j < 0 || l < 0 || j >= ny_ || l >= nz_) return false;
  int winding = 0;
  for (int k : buckets_[j + static_cast<std::size_t>(ny_) * l]) {
    const auto& v = tris_[k].v;
    // barycentric test in the (y, z) projection
    const double d = (v[1].y() - v[0].y()) * (v[2].z() - v[0].z()) - (v[2].y() - v[0].y()) * (v[1].z() - v[0].z());
    if (d == 0) continue;
    const double a = ((v[1].y() - p.y()) * (v[2].z() - p.z()) - (v[2].y() - p.y()) * (v[1].z() - p.z())) / d;
    const double b = ((v[2].y() - p.y()) * (v[0].z() - p.z()) - (v[0].y() - p.y()) * (v[2].z() - p.z())) / d;
    const double c = 1.0 - a - b;
    if (a < 0 || b < 0 || c < 0) continue;
    if (a * v[0].x() + b * v[1].x() + c * v[2].x() > p.x()) winding += d > 0 ? 1 : -1;  // d: the normal's x part
  }
  return winding > 0;
}

double StlShip::signed_distance(const Vec3& p) const {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& t : tris_) best = std::min(best, point_triangle_distance(p, t.v[0], t.v[1], t.v[2]));
  return inside(p) ? -best : best;
}

double ship_scale(const std::string& scale) {
  if (scale == "model") return 1.0 / 50.0;  // the NRC wind-tunnel model (thesis 6.2)
  if (scale == "full") return 1.0;
  throw GeometryError("scale must be 'model' (1/50) or 'full', got '" + scale + "'");
}

std::unique_ptr<ShipGeometry> make_ship(const std::string& which, const std::string& scale) {
  const double s = ship_scale(scale);
  if (which == "natogd") return make_natogd(s);
  if (which == "sfs2") return make_sfs2(s);
  if (which.size() > 4) {
    std::string ext = which.substr(which.size() - 4);
    std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
    if (ext == ".stl") return std::make_unique<StlShip>(which, s);
  }
  throw GeometryError("ship must be 'natogd', 'sfs2' or an .stl file, got '" + which + "'");
}

}  // namespace ship_lrm::wake
