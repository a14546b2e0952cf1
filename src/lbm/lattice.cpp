#include "ship_lrm/lbm/lattice.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <unordered_map>

#include "ship_lrm/lbm/lattice_view.hpp"

namespace ship_lrm::lbm {

const char* to_string(FaceType t) {
  switch (t) {
    case FaceType::Wall:
      return "wall";
    case FaceType::SlipWall:
      return "slip";
    case FaceType::MovingWall:
      return "moving_wall";
    case FaceType::Periodic:
      return "periodic";
    case FaceType::VelocityInlet:
      return "velocity_inlet";
    case FaceType::PressureOutlet:
      return "pressure_outlet";
    case FaceType::ImpedanceOutlet:
      return "impedance_outlet";
  }
  return "?";
}

const char* to_string(CellType t) {
  switch (t) {
    case CellType::Fluid:
      return "fluid";
    case CellType::Wall:
      return "wall";
    case CellType::SlipWall:
      return "slip_wall";
    case CellType::MovingWall:
      return "moving_wall";
    case CellType::VelocityInlet:
      return "velocity_inlet";
    case CellType::PressureOutlet:
      return "pressure_outlet";
    case CellType::ImpedanceOutlet:
      return "impedance_outlet";
  }
  return "?";
}

namespace {
const char* kFaceName[6] = {"-x", "+x", "-y", "+y", "-z", "+z"};

void check_velocity(const std::array<float, 3>& u, const std::string& where) {
  const float speed = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
  if (!std::isfinite(speed)) throw ConfigError(where + ": velocity is not finite");
  const float mach = speed / std::sqrt(d3q19::cs2);
  if (mach > kMaxSetupMach) {
    std::ostringstream s;
    s << where << ": lattice velocity " << speed << " is Mach " << mach << " > limit " << kMaxSetupMach
      << " (reduce the physical-to-lattice velocity ratio: finer time step)";
    throw ConfigError(s.str());
  }
}

CellType open_cell_type(FaceType f) {
  return f == FaceType::VelocityInlet ? CellType::VelocityInlet
                                      : (f == FaceType::PressureOutlet ? CellType::PressureOutlet : CellType::ImpedanceOutlet);
}
int open_priority(FaceType f) {
  return f == FaceType::VelocityInlet ? 3 : (f == FaceType::PressureOutlet ? 2 : (f == FaceType::ImpedanceOutlet ? 1 : 0));
}
}  // namespace

// Neighbour offsets for each of the 27 cell classes (x, y, z each: first, interior, last).
static std::vector<std::int64_t> bulk_class_offsets(const int n[3]) {
  std::vector<std::int64_t> off(27 * Q);
  const std::int64_t stride[3] = {1, n[0], static_cast<std::int64_t>(n[0]) * n[1]};
  for (int cls = 0; cls < 27; ++cls)
    for (int i = 0; i < Q; ++i) {
      const int k[3] = {cls / 9, (cls / 3) % 3, cls % 3};
      std::int64_t o = 0;
      for (int a = 0; a < 3; ++a) {
        const int p = k[a] == 0 ? 0 : (k[a] == 1 ? 1 : n[a] - 1);
        o += ((p + d3q19::c(i, a) + n[a]) % n[a] - p) * stride[a];
      }
      off[cls * Q + i] = o;
    }
  return off;
}

Lattice::Lattice(const LatticeConfig& cfg) : cfg_(cfg) {
  const int n[3] = {cfg.nx, cfg.ny, cfg.nz};
  for (int a = 0; a < 3; ++a) {
    if (n[a] < 3) {
      std::ostringstream s;
      s << "lattice size " << cfg.nx << " x " << cfg.ny << " x " << cfg.nz << ": every dimension needs at least 3 cells";
      throw ConfigError(s.str());
    }
  }
  if (static_cast<double>(cfg.nx) * cfg.ny * cfg.nz >= 4294967295.0) throw ConfigError("lattice has 2^32 cells or more; not supported");
  const float nu = cfg.collision.nu;
  if (!(nu > 0.0f) || !std::isfinite(nu)) {
    std::ostringstream s;
    s << "lattice viscosity nu = " << nu << " must be positive (relaxation time tau = 3 nu + 1/2 > 1/2)";
    throw ConfigError(s.str());
  }
  if (nu > 10.0f) throw ConfigError("lattice viscosity nu > 10 (tau > 30.5): the set-up is far outside the LBM's range");
  if (!(cfg.collision.smagorinsky >= 0.0f) || cfg.collision.smagorinsky > 1.0f)
    throw ConfigError("Smagorinsky constant must lie in [0, 1]");
  if (!(cfg.mach_guard > 0.0f)) throw ConfigError("mach_guard must be positive");
  if (cfg.guard_interval < 0) throw ConfigError("guard_interval must be >= 0");
  for (int a = 0; a < 3; ++a) {
    const bool lo = cfg.faces[2 * a].type == FaceType::Periodic, hi = cfg.faces[2 * a + 1].type == FaceType::Periodic;
    if (lo != hi)
      throw ConfigError(std::string("face ") + kFaceName[2 * a] + " and " + kFaceName[2 * a + 1] +
                        ": periodic must be set on both faces of an axis");
  }
  for (int f = 0; f < 6; ++f) {
    const auto& fc = cfg.faces[f];
    if (fc.type == FaceType::MovingWall || fc.type == FaceType::VelocityInlet)
      check_velocity(fc.velocity, std::string("face ") + kFaceName[f]);
    if (fc.type == FaceType::MovingWall && fc.velocity[f / 2] != 0.0f)
      throw ConfigError(std::string("face ") + kFaceName[f] +
                        ": a moving wall face must move tangentially (normal velocity component must be 0)");
    if (fc.type == FaceType::PressureOutlet && !(fc.density > 0.0f && fc.density < 2.0f))
      throw ConfigError(std::string("face ") + kFaceName[f] + ": outlet density must lie in (0, 2) lattice units");
    if (!(fc.pressure_relaxation >= 0.0f && fc.pressure_relaxation < 1.0f))
      throw ConfigError(std::string("face ") + kFaceName[f] + ": the outlet's pressure relaxation must lie in [0, 1) per step");
    if (open_face(fc.type) && n[f / 2] < 5)
      throw ConfigError(std::string("face ") + kFaceName[f] + ": open boundaries need at least 5 cells across the domain");
    if (fc.absorbing_cells != 0) {
      if (fc.type != FaceType::VelocityInlet)
        throw ConfigError(std::string("face ") + kFaceName[f] + ": an absorbing layer needs a velocity inlet face");
      if (fc.absorbing_cells < 0 || 2 * fc.absorbing_cells > n[f / 2] - 2)
        throw ConfigError(std::string("face ") + kFaceName[f] + ": the absorbing layer must be 1 to " + std::to_string((n[f / 2] - 2) / 2) +
                          " cells thick (" + std::to_string(fc.absorbing_cells) + " given)");
      if (!(fc.absorbing_strength > 0.0f && fc.absorbing_strength <= 1.0f))
        throw ConfigError(std::string("face ") + kFaceName[f] + ": the absorbing layer's strength must lie in (0, 1] per step");
    }
  }
  for (int a = 0; a < 3; ++a)
    if (!std::isfinite(cfg.uniform_force[a])) throw ConfigError("uniform force is not finite");
  type_.assign(cells(), static_cast<std::uint8_t>(CellType::Fluid));
  tag_.assign(cells(), 0);
  // Outermost layers of open faces become open-boundary cells; velocity inlets win at edges.
  for (int z = 0; z < cfg.nz; ++z)
    for (int y = 0; y < cfg.ny; ++y)
      for (int x = 0; x < cfg.nx; ++x) {
        const int p[3] = {x, y, z};
        FaceType best = FaceType::Wall;
        for (int f = 0; f < 6; ++f) {
          const bool on = (f % 2 == 0) ? p[f / 2] == 0 : p[f / 2] == n[f / 2] - 1;
          if (on && open_priority(cfg.faces[f].type) > open_priority(best)) best = cfg.faces[f].type;
        }
        if (open_face(best)) type_[index(x, y, z)] = static_cast<std::uint8_t>(open_cell_type(best));
      }
}

void Lattice::check_cell(int x, int y, int z, const char* what) const {
  if (finalized_) throw ConfigError(std::string(what) + ": the lattice is already in use by a solver; set cells before making it");
  if (x < 0 || y < 0 || z < 0 || x >= cfg_.nx || y >= cfg_.ny || z >= cfg_.nz) {
    std::ostringstream s;
    s << what << ": cell (" << x << ", " << y << ", " << z << ") is outside the " << cfg_.nx << " x " << cfg_.ny << " x " << cfg_.nz
      << " lattice";
    throw ConfigError(s.str());
  }
}

void Lattice::set_wall(int x, int y, int z) {
  check_cell(x, y, z, "set_wall");
  type_[index(x, y, z)] = static_cast<std::uint8_t>(CellType::Wall);
}

void Lattice::set_slip_wall(int x, int y, int z) {
  check_cell(x, y, z, "set_slip_wall");
  type_[index(x, y, z)] = static_cast<std::uint8_t>(CellType::SlipWall);
}

// Reflection rule of a fluid-like cell (see reflect_by_rule() in lattice_view.hpp): the set of
// complete slip planes it touches, bit 2a + (s > 0) set when every link with c_a = s (one axis a, one
// sign s) crosses a slip wall along a (a slip face or a slip-wall cell); 0 (bounce-back) if none.
// A cell in the edge or corner where slip planes meet has two or three bits.
std::uint8_t Lattice::reflection_mode(int x, int y, int z) const {
  const int n[3] = {cfg_.nx, cfg_.ny, cfg_.nz};
  std::uint8_t planes = 0;
  for (int a = 0; a < 3; ++a)
    for (int s = -1; s <= 1; s += 2) {
      bool complete = true;
      for (int i = 1; i < Q && complete; ++i) {
        if (d3q19::c(i, a) != s) continue;
        int p[3] = {x + d3q19::cx(i), y + d3q19::cy(i), z + d3q19::cz(i)};
        if (p[a] < 0 || p[a] >= n[a]) {
          complete = cfg_.faces[2 * a + (p[a] >= n[a] ? 1 : 0)].type == FaceType::SlipWall;
          continue;
        }
        // Beyond a face along another axis b: across a periodic face the link reaches the far side;
        // beyond a slip face (the domain's mirror image) or an open face (whose outside continues its
        // outermost layer: a slip sea that meets an inflow face goes on upstream) the cell the link
        // meets is the face layer's cell in its place; a no-slip wall face ends the plane.
        bool out = false;
        for (int b = 0; b < 3; ++b)
          if (p[b] < 0 || p[b] >= n[b]) {
            const FaceType beyond = cfg_.faces[2 * b + (p[b] >= n[b] ? 1 : 0)].type;
            if (beyond == FaceType::Periodic)
              p[b] = (p[b] + n[b]) % n[b];
            else if (beyond == FaceType::Wall || beyond == FaceType::MovingWall)
              out = true;
            else
              p[b] = p[b] < 0 ? 0 : n[b] - 1;
          }
        complete = !out && static_cast<CellType>(type_[index(p[0], p[1], p[2])] & ~kGeneralBit) == CellType::SlipWall;
      }
      if (complete) planes |= static_cast<std::uint8_t>(1u << (2 * a + (s > 0 ? 1 : 0)));
    }
  return planes;
}

// Links of the cells of each class (cell_class) that leave the domain through a non-periodic face
// (bit i), with kMovingWallLink where one of those faces is a moving wall. Through a periodic face
// a link reaches the cell the class's offsets give (bulk_class_offsets).
static std::array<std::uint32_t, 27> face_link_masks(const std::array<FaceCondition, 6>& faces) {
  std::array<std::uint32_t, 27> m{};
  for (int cls = 0; cls < 27; ++cls) {
    const int k[3] = {cls / 9, (cls / 3) % 3, cls % 3};  // first (0), interior (1) or last (2) along each axis
    for (int i = 1; i < Q; ++i) {
      bool hit = false, moving = false;
      for (int a = 0; a < 3; ++a) {
        const int ci = d3q19::c(i, a);
        const int f = (k[a] == 0 && ci < 0) ? 2 * a : ((k[a] == 2 && ci > 0) ? 2 * a + 1 : -1);
        if (f < 0 || faces[f].type == FaceType::Periodic) continue;
        hit = true;
        moving = moving || faces[f].type == FaceType::MovingWall;
      }
      if (hit) m[cls] |= 1u << i;
      if (moving) m[cls] |= kMovingWallLink;
    }
  }
  return m;
}

// face_links: face_link_masks of the configuration; row_offsets_ is set.
std::uint32_t Lattice::link_mask(int x, int y, int z, const std::array<std::uint32_t, 27>& face_links) const {
  const int n[3] = {cfg_.nx, cfg_.ny, cfg_.nz};
  const int cls = cell_class(n, x, y, z);
  const std::int64_t* off = &row_offsets_[Q * cls];
  const std::size_t c = index(x, y, z);
  std::uint32_t mask = face_links[cls];
  for (int i = 1; i < Q; ++i) {
    if ((face_links[cls] >> i) & 1u) continue;
    const auto t = static_cast<CellType>(type_[c + off[i]] & ~kGeneralBit);
    if (is_wall(t)) mask |= 1u << i;
    if (t == CellType::MovingWall) mask |= kMovingWallLink;
  }
  return mask;
}

namespace {
// A wall motion the solvers can take: velocity within the Mach limit, finite rotation, rho_w weight in [0, 1].
void check_wall_motion(const WallMotion& m, const std::string& where) {
  check_velocity({m.v[0], m.v[1], m.v[2]}, "wall motion");
  for (int a = 0; a < 3; ++a)
    if (!std::isfinite(m.omega[a]) || !std::isfinite(m.centre[a])) throw ConfigError(where + ": a value is not finite");
  if (!(m.local_density >= 0.0f && m.local_density <= 1.0f)) throw ConfigError(where + ": local_density must lie in [0, 1]");
}
}  // namespace

int Lattice::add_wall_motion(const WallMotion& m) {
  if (walls_.size() >= 256) throw ConfigError("at most 256 moving walls are supported");
  check_wall_motion(m, "add_wall_motion");
  walls_.push_back(m);
  return static_cast<int>(walls_.size()) - 1;
}

void Lattice::set_wall_motion(int wall, const WallMotion& m) {
  if (wall < 0 || wall >= static_cast<int>(walls_.size())) throw ConfigError("set_wall_motion: unknown wall index " + std::to_string(wall));
  check_wall_motion(m, "set_wall_motion");
  walls_[wall] = m;
}

void Lattice::set_moving_wall(int x, int y, int z, int wall) {
  check_cell(x, y, z, "set_moving_wall");
  if (wall < 0 || wall >= static_cast<int>(walls_.size()))
    throw ConfigError("set_moving_wall: unknown wall index (call add_wall_motion first)");
  type_[index(x, y, z)] = static_cast<std::uint8_t>(CellType::MovingWall);
  tag_[index(x, y, z)] = static_cast<std::uint8_t>(wall);
}

void Lattice::set_held(int x, int y, int z, int wall) {
  check_cell(x, y, z, "set_held");
  if (wall != kHeldAtRest && (wall < 0 || wall >= static_cast<int>(walls_.size()) || wall >= kHeldWallAtRest))
    throw ConfigError("set_held: unknown wall index (call add_wall_motion first, or pass kHeldAtRest)");
  held_cell_.push_back(static_cast<std::uint32_t>(index(x, y, z)));
  held_wall_.push_back(wall == kHeldAtRest ? kHeldWallAtRest : static_cast<std::uint8_t>(wall));
}

void Lattice::order_held_cells() {
  std::vector<std::size_t> order(held_cell_.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return held_cell_[a] < held_cell_[b]; });
  std::vector<std::uint32_t> cells(order.size());
  std::vector<std::uint8_t> walls(order.size());
  for (std::size_t k = 0; k < order.size(); ++k) {
    cells[k] = held_cell_[order[k]];
    walls[k] = held_wall_[order[k]];
    const std::size_t c = cells[k];
    const char* why = static_cast<CellType>(type_[c]) != CellType::Fluid ? "is not a fluid cell (a wall or an open-boundary cell)"
                      : (k > 0 && cells[k - 1] == c)                     ? "is held twice"
                                                                         : nullptr;
    if (why) {
      std::ostringstream s;
      s << "set_held: cell (" << c % cfg_.nx << ", " << (c / cfg_.nx) % cfg_.ny << ", " << c / (static_cast<std::size_t>(cfg_.nx) * cfg_.ny)
        << ") " << why;
      throw ConfigError(s.str());
    }
  }
  held_cell_ = std::move(cells);
  held_wall_ = std::move(walls);
}

int Lattice::open_normal(int x, int y, int z) const {
  const int p[3] = {x, y, z}, n[3] = {cfg_.nx, cfg_.ny, cfg_.nz};
  const auto t = static_cast<CellType>(type_[index(x, y, z)]);
  int best = -1, best_score = -1;
  for (int f = 0; f < 6; ++f) {
    const bool on = (f % 2 == 0) ? p[f / 2] == 0 : p[f / 2] == n[f / 2] - 1;
    if (!on || cfg_.faces[f].type == FaceType::Periodic) continue;
    const int score = (open_face(cfg_.faces[f].type) && open_cell_type(cfg_.faces[f].type) == t) ? 2 : 1;
    if (score > best_score) best = f, best_score = score;
  }
  return best;  // face index f = axis*2 + (outward normal > 0)
}

void Lattice::set_open(int x, int y, int z, CellType t, const std::array<float, 4>& value) {
  const auto old = type_[index(x, y, z)];
  type_[index(x, y, z)] = static_cast<std::uint8_t>(t);
  if (open_normal(x, y, z) < 0) {
    type_[index(x, y, z)] = old;
    std::ostringstream s;
    s << to_string(t) << " at (" << x << ", " << y << ", " << z << "): open boundary cells must lie on a non-periodic face of the domain";
    throw ConfigError(s.str());
  }
  explicit_values_.emplace_back(static_cast<std::uint32_t>(index(x, y, z)), value);
}

void Lattice::set_velocity_inlet(int x, int y, int z, const std::array<float, 3>& u) {
  check_cell(x, y, z, "set_velocity_inlet");
  check_velocity(u, "set_velocity_inlet");
  set_open(x, y, z, CellType::VelocityInlet, {u[0], u[1], u[2], 0.0f});
}

void Lattice::set_pressure_outlet(int x, int y, int z, float rho) {
  check_cell(x, y, z, "set_pressure_outlet");
  if (!(rho > 0.0f && rho < 2.0f)) throw ConfigError("set_pressure_outlet: density must lie in (0, 2) lattice units");
  set_open(x, y, z, CellType::PressureOutlet, {rho, 0.0f, 0.0f, 0.0f});
}

void Lattice::set_impedance_outlet(int x, int y, int z) {
  check_cell(x, y, z, "set_impedance_outlet");
  set_open(x, y, z, CellType::ImpedanceOutlet, {1.0f, 0.0f, 0.0f, 0.0f});
}

// Support set of the open boundaries, the cells whose state (aux) their update reads: every
// fluid-like cell within two cells along an axis of an open-boundary cell (velocity_gradient and
// the outlets' interior neighbours) and, at edges and corners of open faces, the two inward
// diagonal neighbours (open_edge_neighbour). Open-boundary cells are in it too.
std::vector<char> Lattice::support_marks() const {
  const int n[3] = {cfg_.nx, cfg_.ny, cfg_.nz};
  std::vector<char> mark(cells(), 0);
  auto mark_fluid = [&](const int p[3]) {
    const std::size_t q = index(p[0], p[1], p[2]);
    if (!is_wall(static_cast<CellType>(type_[q] & ~kGeneralBit))) mark[q] = 1;
  };
  // open-boundary cells lie on the faces only (set_open): rows inside the lattice have two of them
  // (at x = 0 and x = nx - 1), the others are walked whole
  for (int z = 0; z < n[2]; ++z)
    for (int y = 0; y < n[1]; ++y) {
      const bool inner_row = y > 0 && z > 0 && y < n[1] - 1 && z < n[2] - 1;
      for (int x = 0; x < n[0]; x += (inner_row && x == 0) ? std::max(n[0] - 1, 1) : 1) {
        if (!is_open_boundary(static_cast<CellType>(type_[index(x, y, z)] & ~kGeneralBit))) continue;
        const int p0[3] = {x, y, z};
        int step[3] = {0, 0, 0}, faces = 0;
        for (int a = 0; a < 3; ++a) {
          if (p0[a] == 0 && open_face(cfg_.faces[2 * a].type))
            step[a] = 1;
          else if (p0[a] == n[a] - 1 && open_face(cfg_.faces[2 * a + 1].type))
            step[a] = -1;
          faces += step[a] != 0;
          for (int d = -2; d <= 2; ++d) {
            int p[3] = {x, y, z};
            p[a] += d;
            if (p[a] < 0 || p[a] >= n[a]) {
              if (cfg_.faces[2 * a + (p[a] >= 0 ? 1 : 0)].type != FaceType::Periodic) continue;
              p[a] = (p[a] + n[a]) % n[a];
            }
            mark_fluid(p);
          }
        }
        for (int k = 1; k <= 2 && faces >= 2; ++k) {
          const int p[3] = {x + k * step[0], y + k * step[1], z + k * step[2]};
          if (p[0] >= 0 && p[0] < n[0] && p[1] >= 0 && p[1] < n[1] && p[2] >= 0 && p[2] < n[2]) mark_fluid(p);
        }
      }
    }
  return mark;
}

static_assert(static_cast<int>(CellType::Wall) == 1 && static_cast<int>(CellType::SlipWall) == 2 &&
                  static_cast<int>(CellType::MovingWall) == 3,
              "finalize's row masks test is_wall as 1 <= type <= 3");

void Lattice::finalize() {
  if (finalized_) return;
  order_held_cells();
  const int n[3] = {cfg_.nx, cfg_.ny, cfg_.nz};
  std::unordered_map<std::uint32_t, std::array<float, 4>> values;
  for (const auto& [c, v] : explicit_values_) values[c] = v;
  row_offsets_ = bulk_class_offsets(n);
  const std::array<std::uint32_t, 27> face_links = face_link_masks(cfg_.faces);
  const std::vector<char> support = support_marks();
  // Link masks and reflection rules of all fluid-like cells first, in parallel: the LRM rebuilds
  // its lattice whenever its wall cells change (a moving ship: dozens of times a second).
  bool slip = false;
  for (const FaceCondition& f : cfg_.faces) slip = slip || f.type == FaceType::SlipWall;
  for (std::size_t c = 0; c < cells() && !slip; ++c) slip = static_cast<CellType>(type_[c]) == CellType::SlipWall;
  std::vector<std::uint32_t> masks(cells(), 0);
#pragma omp parallel for schedule(static)
  for (int z = 0; z < n[2]; ++z)
    for (int y = 0; y < n[1]; ++y) {
      // Rows inside the lattice: link_mask's interior case direction by direction along the row, a
      // loop that vectorises (a moving ship re-voxelises, and this pass was 70 % of it at 40^3).
      const bool inner_row = y > 0 && z > 0 && y < n[1] - 1 && z < n[2] - 1;
      if (inner_row) {
        std::uint32_t* m = &masks[index(1, y, z)];
        const int len = n[0] - 2;
        for (int i = 1; i < Q; ++i) {
          const std::uint8_t* t = &type_[index(1 + d3q19::cx(i), y + d3q19::cy(i), z + d3q19::cz(i))];
          for (int x = 0; x < len; ++x) {
            const unsigned ty = t[x] & ~kGeneralBit;
            // 1 <= ty <= 3: is_wall (static_assert above)
            m[x] |= (ty - 1u < 3u ? 1u << i : 0u) | (ty == static_cast<unsigned>(CellType::MovingWall) ? kMovingWallLink : 0u);
          }
        }
      }
      for (int x = 0; x < n[0]; ++x) {
        const std::size_t c = index(x, y, z);
        if (is_wall(static_cast<CellType>(type_[c]))) continue;
        tag_[c] = slip ? reflection_mode(x, y, z) : 0;  // reflection_mode is 0 without slip walls
        if (!inner_row || x == 0 || x == n[0] - 1) masks[c] = link_mask(x, y, z, face_links);
      }
    }
  // The lists of the cells by kind, in cell order, made by slabs of z in parallel and joined in
  // order (a segment never leaves its row, so none crosses a slab; same lists as one pass).
  struct Lists {
    std::vector<Segment> segments;
    std::vector<std::uint32_t> general, general_mask, bnd_cell, bnd_mask;
    std::vector<std::uint8_t> bnd_normal;
    std::vector<float> bnd_value;
  };
  const int slabs = std::min(n[2], 16);
  std::vector<Lists> slab(slabs);
#pragma omp parallel for schedule(dynamic)
  for (int k = 0; k < slabs; ++k) {
    Lists& o = slab[k];
    for (int z = n[2] * k / slabs; z < n[2] * (k + 1) / slabs; ++z)
      for (int y = 0; y < n[1]; ++y)
        for (int x = 0; x < n[0]; ++x) {
          const std::size_t c = index(x, y, z);
          const auto t = static_cast<CellType>(type_[c]);
          if (is_wall(t)) continue;
          if (is_open_boundary(t)) {
            const int f = open_normal(x, y, z);
            o.bnd_cell.push_back(static_cast<std::uint32_t>(c));
            o.bnd_normal.push_back(static_cast<std::uint8_t>(f));
            o.bnd_mask.push_back(masks[c]);
            std::array<float, 4> v{0, 0, 0, 0};
            const auto it = values.find(static_cast<std::uint32_t>(c));
            if (it != values.end()) {
              v = it->second;
            } else {
              const FaceCondition& fc = cfg_.faces[f];
              if (t == CellType::VelocityInlet) v = {fc.velocity[0], fc.velocity[1], fc.velocity[2], 0.0f};
              if (t == CellType::PressureOutlet) v = {fc.density, 0, 0, 0};
              if (t == CellType::ImpedanceOutlet) v = {1.0f, 0, 0, 0};
            }
            o.bnd_value.insert(o.bnd_value.end(), v.begin(), v.end());
            continue;
          }
          // Cells with resting walls among their neighbours stream through their link mask; runs of
          // cells with equal class, mask and reflection rule form one vectorised segment. Bulk cells
          // (mask 0) are segments too. Cells next to moving walls take the checked path.
          const std::uint32_t mask = masks[c];
          const std::uint32_t cls = static_cast<std::uint32_t>(cell_class(n, x, y, z));
          const std::uint8_t store = support[c] ? 1 : 0;
          if (mask != 0) type_[c] |= kGeneralBit;  // the GPU kernel's checked path
          if (mask & kMovingWallLink) {
            o.general.push_back(static_cast<std::uint32_t>(c));
            o.general_mask.push_back(mask);
            continue;
          }
          // A segment stays in one row (x > 0): the solvers count its cells' x from the first one.
          Segment* last = o.segments.empty() ? nullptr : &o.segments.back();
          if (last && x > 0 && last->first + last->count == c && last->cell_class == cls && last->link_mask == mask &&
              last->reflection == tag_[c]) {
            ++last->count;
            last->store_state |= store;
          } else
            o.segments.push_back({static_cast<std::uint32_t>(c), 1, cls, mask, tag_[c], store});
        }
  }
  const auto join = [&](auto& to, auto member) {
    std::size_t size = to.size();
    for (const Lists& o : slab) size += (o.*member).size();
    to.reserve(size);
    for (const Lists& o : slab) to.insert(to.end(), (o.*member).begin(), (o.*member).end());
  };
  join(segments_, &Lists::segments);
  join(general_, &Lists::general);
  join(general_mask_, &Lists::general_mask);
  join(bnd_cell_, &Lists::bnd_cell);
  join(bnd_mask_, &Lists::bnd_mask);
  join(bnd_normal_, &Lists::bnd_normal);
  join(bnd_value_, &Lists::bnd_value);
  // The open boundaries' velocity-gradient stencils, by the function the solvers' kernels share.
  LatticeView host;
  for (int a = 0; a < 3; ++a) host.n[a] = n[a];
  host.ncells = cells();
  host.type = type_.data();
  for (int f = 0; f < 6; ++f) host.face[f] = static_cast<std::uint8_t>(cfg_.faces[f].type);
  const long nb = static_cast<long>(bnd_cell_.size());
  bnd_grad_cell_.assign(9 * nb, 0);
  bnd_grad_weight_.assign(9 * nb, 0.0f);
#pragma omp parallel for schedule(static)
  for (long b = 0; b < nb; ++b) {
    int x, y, z;
    cell_coords(host, bnd_cell_[b], x, y, z);
    gradient_stencil(host, x, y, z, bnd_cell_[b], &bnd_grad_cell_[9 * b], &bnd_grad_weight_[9 * b]);
  }
  // The absorbing layers' cells and their targets: the boundary index of each face's cells by their
  // position along the face (the two other axes, the lower one fastest), then the fluid cells within
  // reach, each once with the nearest face.
  absorbing_cell_.clear();
  absorbing_target_.clear();
  absorbing_sigma_.clear();
  std::array<std::vector<std::int32_t>, 6> face_target;
  bool any_layer = false;
  for (int f = 0; f < 6; ++f)
    if (cfg_.faces[f].absorbing_cells > 0) {
      face_target[f].assign(cells() / n[f / 2], -1);
      any_layer = true;
    }
  const auto along = [&](int f, const int p[3]) {
    const int a = f / 2, a1 = (a + 1) % 3, a2 = (a + 2) % 3, lo = std::min(a1, a2), hi = std::max(a1, a2);
    return p[lo] + static_cast<std::size_t>(n[lo]) * p[hi];
  };
  for (long b = 0; b < nb && any_layer; ++b) {
    const int f = bnd_normal_[b];
    if (face_target[f].empty() || static_cast<CellType>(type_[bnd_cell_[b]] & ~kGeneralBit) != CellType::VelocityInlet) continue;
    int p[3];
    cell_coords(host, bnd_cell_[b], p[0], p[1], p[2]);
    face_target[f][along(f, p)] = static_cast<std::int32_t>(b);
  }
  std::vector<char> held(any_layer ? cells() : 0, 0);
  if (any_layer)
    for (std::uint32_t c : held_cell_) held[c] = 1;
  for (std::size_t c = 0; c < cells() && any_layer; ++c) {
    if (static_cast<CellType>(type_[c] & ~kGeneralBit) != CellType::Fluid || held[c]) continue;
    int p[3];
    cell_coords(host, c, p[0], p[1], p[2]);
    int best = -1, best_d = 0;
    for (int f = 0; f < 6; ++f) {
      const int L = cfg_.faces[f].absorbing_cells, a = f / 2, d = (f & 1) ? n[a] - 1 - p[a] : p[a];
      if (L == 0 || d < 1 || d > L || face_target[f][along(f, p)] < 0 || (best >= 0 && d >= best_d)) continue;
      best = f;
      best_d = d;
    }
    if (best < 0) continue;
    const int L = cfg_.faces[best].absorbing_cells;
    const float r = static_cast<float>(L + 1 - best_d) / static_cast<float>(L + 1);
    absorbing_cell_.push_back(static_cast<std::uint32_t>(c));
    absorbing_target_.push_back(static_cast<std::uint32_t>(face_target[best][along(best, p)]));
    absorbing_sigma_.push_back(cfg_.faces[best].absorbing_strength * r * r);
  }
  finalized_ = true;
}

}  // namespace ship_lrm::lbm
