// The ship-wake precompute (see wake_precompute.hpp).
#include "ship_lrm/wake/wake_precompute.hpp"

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

namespace ship_lrm::wake {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

constexpr char kMagic[16] = "SHIPLRM-WAKECK2";  // 2: with the fine region, its statistics and the probes
constexpr char kOldMagic[16] = "SHIPLRM-WAKECK1";

// What a checkpoint must match to be resumed.
std::string signature(const PrecomputeOptions& o, const ShipWakeDomain& d) {
  std::ostringstream s;
  s.precision(17);
  s << "ship=" << o.ship << " scale=" << o.scale << " motion=" << o.motion << " N=" << o.domain.cells_per_length
    << " wind=" << o.domain.wind << " lattice_wind=" << o.domain.lattice_wind << " smagorinsky=" << o.domain.smagorinsky
    << " grid=" << d.nx() << "x" << d.ny() << "x" << d.nz() << " interval=" << o.frame_interval << " stats=" << o.stats_interval
    << " half=" << o.half_precision;
  if (o.domain.collision != lbm::CollisionModel::Bgk) s << " collision=" << lbm::to_string(o.domain.collision);
  if (o.domain.characteristic_inlet) s << " inlet=characteristic";  // none: the reflecting inlet of the tables before 2026-12-04
  if (o.domain.fine.enabled())
    s << " fine=" << o.domain.fine.ratio << ":" << o.domain.fine.aft << ":" << o.domain.fine.fore << ":" << o.domain.fine.half_width << ":"
      << o.domain.fine.top;
  if (const FineRegion* f = d.fine())
    s << " stored=" << f->stored_lo()[0] << "," << f->stored_lo()[2] << ":" << f->stored_shape()[0] << "x" << f->stored_shape()[2];
  if (!o.probes.empty()) {
    s << (o.probes_on_ship ? " ship_probes=" : " probes=");
    for (const auto& p : o.probes) s << p[0] << "," << p[1] << "," << p[2] << ";";
  }
  return s.str();
}

template <class T>
void put(std::ostream& out, const T& v) {
  out.write(reinterpret_cast<const char*>(&v), sizeof v);
}
template <class T>
void put_vec(std::ostream& out, const std::vector<T>& v) {
  put<std::uint64_t>(out, v.size());
  out.write(reinterpret_cast<const char*>(v.data()), static_cast<std::streamsize>(v.size() * sizeof(T)));
}
template <class T>
T get(std::istream& in) {
  T v{};
  in.read(reinterpret_cast<char*>(&v), sizeof v);
  if (!in) throw TableError("checkpoint: truncated");
  return v;
}
template <class T>
std::vector<T> get_vec(std::istream& in, std::uint64_t limit) {
  const auto n = get<std::uint64_t>(in);
  if (n > limit) throw TableError("checkpoint: corrupt (a field of " + std::to_string(n) + " values)");
  std::vector<T> v(n);
  in.read(reinterpret_cast<char*>(v.data()), static_cast<std::streamsize>(n * sizeof(T)));
  if (!in) throw TableError("checkpoint: truncated");
  return v;
}

struct Checkpoint {
  std::string signature;
  ShipWakeDomain::State state;
  int frames = 0;
  CentrePlaneStats stats, fine_stats;
  ProbeSeries probes;
  long next_sample = 0;     // the next statistics sample's number (its time: number x interval)
  int last_phase_slot = 0;  // the quarter period of the last phase sample
};

void put_stats(std::ostream& out, const CentrePlaneStats& s) {
  put(out, s.samples);
  put_vec(out, s.sum);
  put_vec(out, s.sum_sq);
  put_vec(out, s.sum_cross);
  for (int p = 0; p < 4; ++p) {
    put(out, s.phase_samples[p]);
    put_vec(out, s.phase_sum[p]);
    put_vec(out, s.phase_sum_sq[p]);
    put_vec(out, s.phase_sum_cross[p]);
  }
}

void get_stats(std::istream& in, CentrePlaneStats& s, std::uint64_t limit) {
  s.samples = get<long>(in);
  s.sum = get_vec<double>(in, limit);
  s.sum_sq = get_vec<double>(in, limit);
  s.sum_cross = get_vec<double>(in, limit);
  for (int p = 0; p < 4; ++p) {
    s.phase_samples[p] = get<long>(in);
    s.phase_sum[p] = get_vec<double>(in, limit);
    s.phase_sum_sq[p] = get_vec<double>(in, limit);
    s.phase_sum_cross[p] = get_vec<double>(in, limit);
  }
}

void save(const std::string& path, const Checkpoint& c) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary);
    if (!out) throw TableError("cannot write checkpoint '" + tmp + "'");
    out.write(kMagic, sizeof kMagic);
    put_vec(out, std::vector<char>(c.signature.begin(), c.signature.end()));
    put(out, c.state.steps);
    put(out, c.state.solver_steps);
    put(out, c.state.voxel_time);
    put(out, c.frames);
    put_stats(out, c.stats);
    put_vec(out, c.state.populations);
    put<std::uint8_t>(out, c.state.has_fine ? 1 : 0);
    if (c.state.has_fine) {
      put<std::uint8_t>(out, c.state.fine_started ? 1 : 0);
      const FineRegion::State& f = c.state.fine;
      put(out, f.time);
      put(out, f.steps);
      put(out, f.solver_steps);
      put(out, f.voxel_time);
      put_vec(out, f.populations);
      put_vec(out, f.faces.cell_state);
      put_vec(out, f.faces.values);
      put_stats(out, c.fine_stats);
    }
    put_vec(out, c.probes.time);
    put_vec(out, c.probes.u);
    put(out, c.next_sample);
    put(out, c.last_phase_slot);
    if (!out) throw TableError("writing checkpoint '" + tmp + "' failed (disk full?)");
  }
  fs::rename(tmp, path);  // atomic: a crash mid-write leaves the previous checkpoint
}

// limit: the most values a coarse field may have; fine_limit: a fine one
Checkpoint load(const std::string& path, std::uint64_t limit, std::uint64_t fine_limit) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw TableError("cannot read checkpoint '" + path + "'");
  char magic[sizeof kMagic];
  in.read(magic, sizeof magic);
  if (in && std::memcmp(magic, kOldMagic, sizeof kOldMagic) == 0)
    throw TableError("checkpoint '" + path +
                     "' was written by an older ship_lrm; delete it (or pass --no-resume --overwrite) to start afresh");
  if (!in || std::memcmp(magic, kMagic, sizeof kMagic) != 0) throw TableError("'" + path + "' is not a wake checkpoint");
  Checkpoint c;
  const auto sig = get_vec<char>(in, 1 << 20);
  c.signature.assign(sig.begin(), sig.end());
  c.state.steps = get<long>(in);
  c.state.solver_steps = get<long>(in);
  c.state.voxel_time = get<double>(in);
  c.frames = get<int>(in);
  get_stats(in, c.stats, limit);
  c.state.populations = get_vec<float>(in, 19 * limit);
  c.state.has_fine = get<std::uint8_t>(in) != 0;
  if (c.state.has_fine) {
    c.state.fine_started = get<std::uint8_t>(in) != 0;
    FineRegion::State& f = c.state.fine;
    f.time = get<double>(in);
    f.steps = get<long>(in);
    f.solver_steps = get<long>(in);
    f.voxel_time = get<double>(in);
    f.populations = get_vec<float>(in, 19 * fine_limit);
    f.faces.cell_state = get_vec<float>(in, 19 * fine_limit);
    f.faces.values = get_vec<float>(in, 19 * fine_limit);
    get_stats(in, c.fine_stats, fine_limit);
  }
  c.probes.time = get_vec<double>(in, std::uint64_t(1) << 32);
  c.probes.u = get_vec<float>(in, std::uint64_t(1) << 34);
  c.next_sample = get<long>(in);
  c.last_phase_slot = get<int>(in);
  return c;
}

}  // namespace

std::string preset_table_path(const std::string& name) {
  const char* file = name == "default" ? "wake_default_v3.h5" : name == "realistic" ? "wake_realistic_v1.h5" : nullptr;
  if (!file) throw ConfigError("the wake preset '" + name + "' has no cached table (default, realistic)");
  if (const char* p = std::getenv("SHIP_LRM_WAKE_CACHE")) return std::string(p) + "/" + file;
  const char* home = std::getenv("HOME");
  return std::string(home ? home : ".") + "/.cache/ship_lrm/" + file;
}

std::string default_table_path() { return preset_table_path("default"); }

std::string named_table(const std::string& given, std::string& preset) {
  preset.clear();
  if (given.empty() || ((given == "default" || given == "realistic") && !std::filesystem::exists(given))) {
    preset = given.empty() ? "default" : given;
    return preset_table_path(preset);
  }
  return given;
}

std::string missing_table_message(const std::string& path, const std::string& preset) {
  if (!preset.empty())
    return "the " + preset + " wake table " + path + " does not exist yet; make it with `ship_lrm wake --preset " + preset + "`";
  return "wake table '" + path + "' not found; make one with `ship_lrm wake --preset default --out " + path + "`";
}

PrecomputeOptions preset(const std::string& name) {
  PrecomputeOptions o;
  if (name == "default" || name == "realistic") {
    // The approach scenario (thesis 9.1): NatoGD full scale, wind over deck 20.58 m/s, heave + pitch
    // of the approach sea state, 30 s of frames every 0.1 s (a 0.2 - 2 Hz band of the loads: 5 Hz
    // Nyquist). "default": N = 48 (dx = 3.1 m, against the thesis' 0.41 m at N = 364), within minutes
    // on 2 cores, and laminar over the deck (docs/validation.md, "The ship wake").
    o.ship = "natogd";
    o.scale = "full";
    o.motion = "approach";
    o.domain.cells_per_length = 48;
    o.domain.wind = 20.58;
    o.domain.density = 1.1934;
    o.duration = 30;
    o.frame_interval = 0.1;
    if (name == "default") return o;
    // "realistic": the deck region at the thesis' converged 364 cells per ship length (52 x 7), a
    // region over the whole superstructure (what sheds the deck's turbulence: an aft box fed with the
    // coarse steady wake stays laminar), from 0.4 ship lengths aft of the hangar door (60 m, 35 m
    // behind the stern: the last 8 s of the approach and the hover) to past the bow (the moving ship
    // may not cross the fore face), 0.1 wide either side (the hull's half beam and two coarse cells),
    // 0.31 high (the mast and two coarse cells). The table stores the part the rotor flies through:
    // 0.4 aft to 0.05 forward of the door, 0.2 ship lengths (30 m) above the waterline. The region
    // starts once the air has crossed it before the first frame; the coarse domain starts alone.
    o.domain.cells_per_length = 52;
    o.domain.fine.ratio = 7;
    o.domain.fine.aft = -0.4;
    const ShipDatum d = make_ship(o.ship, o.scale)->datum();
    o.domain.fine.fore = (d.stem_x + 3.0 * d.length / o.domain.cells_per_length) / d.length;
    o.domain.fine.half_width = 0.1;
    o.domain.fine.top = 0.31;
    o.domain.fine.stored_aft = -0.4;
    o.domain.fine.stored_fore = 0.05;
    o.domain.fine.stored_top = 0.2;
    o.startup = o.domain.domain_length * d.length / o.domain.wind;
    o.domain.fine.start = o.startup - (o.domain.fine.fore - o.domain.fine.aft) * d.length / o.domain.wind;
    return o;
  }
  if (name == "tiny") {
    o.ship = "natogd";
    o.scale = "full";
    o.motion = "static";
    o.domain.cells_per_length = 16;
    o.domain.wind = 20.58;
    o.startup = 10;
    o.duration = 2;
    o.frame_interval = 0.5;
    o.half_precision = false;
    return o;
  }
  throw ConfigError("unknown wake preset '" + name + "' (default, realistic, tiny)");
}

PrecomputeResult precompute_wake(const PrecomputeOptions& opt) {
  if (opt.out.empty()) throw ConfigError("wake: no output file (--out FILE.h5)");
  if (!(opt.duration > 0) || !(opt.frame_interval > 0) || !std::isfinite(opt.duration))
    throw ConfigError("wake: duration and frame interval must be > 0");
  auto ship = std::shared_ptr<const ShipGeometry>(make_ship(opt.ship, opt.scale));
  const double scale = ship_scale(opt.scale);
  const ShipDatum& sd = ship->datum();
  auto motion = std::shared_ptr<const ShipMotion>(make_motion(opt.motion, scale, motion_centre(sd)));
  ShipWakeDomain domain(opt.domain, ship, motion);
  const double dt = domain.units().dt();
  const double startup = opt.startup >= 0 ? opt.startup : opt.domain.domain_length * sd.length / opt.domain.wind;
  const double stats_interval = opt.stats_interval > 0 ? opt.stats_interval : opt.frame_interval;
  if (opt.frame_interval < dt)
    throw ConfigError("wake: the frame interval " + std::to_string(opt.frame_interval) + " s is shorter than the time step " +
                      std::to_string(dt) + " s");
  const long total_steps = static_cast<long>(std::ceil((startup + opt.duration) / dt + 0.5));
  const int total_frames = static_cast<int>(std::floor(opt.duration / opt.frame_interval + 1e-9)) + 1;
  const auto* periodic = dynamic_cast<const SinusoidalMotion*>(motion.get());
  const double period = periodic ? 1.0 / periodic->params().frequency : 0.0;
  FineRegion* fine = domain.fine();
  if (fine && opt.domain.fine.start > startup + 1e-12)
    throw ConfigError("wake: the fine region starts at " + std::to_string(opt.domain.fine.start) +
                      " s, after the first frame and statistics sample (the start-up, " + std::to_string(startup) +
                      " s); start it earlier");

  PrecomputeResult r;
  r.table = opt.out;
  r.xdmf = fs::path(opt.out).replace_extension(".xdmf").string();
  const std::string stem = fs::path(opt.out).replace_extension("").string();
  r.centre_plane_csv = stem + "_centre_plane.csv";
  if (fine) r.fine_centre_plane_csv = stem + "_fine_centre_plane.csv";
  if (!opt.probes.empty()) r.probes_csv = stem + "_probes.csv";
  r.cells = domain.cells();
  r.dx = domain.units().dx();
  r.dt = dt;
  r.fine_cells = fine ? fine->grid().cells() : 0;
  r.fine_dx = fine ? fine->grid().dx : 0.0;

  // the probes: each in the fluid of the finest level that covers it, before any step
  ProbeSeries& probes = r.probes;
  for (const auto& p : opt.probes) {
    for (double v : p)
      if (!std::isfinite(v)) throw ConfigError("wake: a probe point is not finite");
    probes.points.push_back(p);
  }
  // the air at point q (mean frame) from the finest level that covers it
  const auto probe_air = [&](const lbm::Fields& coarse, const lbm::Fields* fine_fields, const Vec3& q, std::array<double, 3>& u) {
    if (fine && fine_fields && fine->velocity_at(*fine_fields, q, u)) return true;
    if (fine && fine_fields) {  // inside the fine grid but at a solid: not the coarse value there either
      const NodeGrid& g = fine->grid();
      const Vec3 rel = (q - g.origin) / g.dx;
      if (rel.x() >= 0 && rel.y() >= 0 && rel.z() >= 0 && rel.x() <= g.nx - 1 && rel.y() <= g.ny - 1 && rel.z() <= g.nz - 1) return false;
    }
    return domain.velocity_at(coarse, q, u);
  };
  // the air at probe p at time t; a ship-fixed probe is where the ship has taken it and records the
  // air relative to itself in the ship's axes
  const bool on_ship = opt.probes_on_ship && !motion->is_static();
  const auto probe_velocity = [&](const lbm::Fields& coarse, const lbm::Fields* fine_fields, const std::array<double, 3>& p,
                                  std::array<double, 3>& u, double t) {
    const Vec3 body(p[0], p[1], p[2]);
    if (!probe_air(coarse, fine_fields, on_ship ? motion->position(body, t) : body, u)) return false;
    if (on_ship) {
      const Vec3 rel = motion->placement(t).rotation.transpose() * (Vec3(u[0], u[1], u[2]) - motion->velocity(body, t));
      u = {rel.x(), rel.y(), rel.z()};
    }
    return true;
  };
  if (!probes.points.empty()) {
    const lbm::Fields c = domain.fields();
    lbm::Fields f;
    if (fine) f = fine->fields();
    for (int k = 0; k < probes.probes(); ++k) {
      std::array<double, 3> u{};
      const auto& p = probes.points[k];
      if (!probe_velocity(c, fine ? &f : nullptr, p, u, domain.time()))
        throw ConfigError("wake: probe " + std::to_string(k) + " at (" + std::to_string(p[0]) + ", " + std::to_string(p[1]) + ", " +
                          std::to_string(p[2]) +
                          ") m (ship frame) is not in the fluid: inside or next to the ship or the sea, or "
                          "outside the domain");
    }
  }

  const std::string ckpt = opt.out + ".ckpt";
  WakeTableInfo info = domain.table_info();
  info.frame_interval = opt.frame_interval;
  info.start_time = startup;
  info.scale = opt.scale;
  info.half_precision = opt.half_precision;
  const std::string sig = signature(opt, domain);

  // resume from a matching checkpoint, or start afresh
  std::unique_ptr<WakeTableWriter> writer;
  CentrePlaneStats& stats = r.stats;
  CentrePlaneStats& fine_stats = r.fine_stats;
  long resumed_next_sample = -1;
  int resumed_phase_slot = 0;
  if (opt.resume && fs::exists(ckpt)) {
    Checkpoint c = load(ckpt, domain.cells() * 3 + 16, r.fine_cells * 3 + 16);
    if (c.signature != sig)
      throw ConfigError("wake: checkpoint '" + ckpt + "' belongs to another run (" + c.signature + "); delete it or choose another --out");
    if (c.probes.u.size() != 3 * c.probes.time.size() * probes.points.size())
      throw TableError("checkpoint '" + ckpt + "': its probe series does not match the probes");
    domain.restore(c.state);
    writer = std::make_unique<WakeTableWriter>(opt.out, info, true, c.frames);
    stats = std::move(c.stats);
    fine_stats = std::move(c.fine_stats);
    probes.time = std::move(c.probes.time);
    probes.u = std::move(c.probes.u);
    resumed_next_sample = c.next_sample;
    resumed_phase_slot = c.last_phase_slot;
    r.resumed = true;
  } else {
    writer = std::make_unique<WakeTableWriter>(opt.out, info, false, 0);
  }
  // the geometry of the statistics (on a resume the sums came from the checkpoint)
  stats.set_geometry(domain.centre_plane(domain.fields()));
  if (fine) fine_stats.set_geometry(domain.fine_centre_plane(fine->fields()));
  const auto t0 = Clock::now();
  auto last_ckpt = t0, last_report = t0;
  const long start_step = domain.steps();
  const double coarse_s0 = domain.coarse_seconds(), fine_s0 = domain.fine_seconds();
  // (a resumed run continues the checkpoint's counts: a sample taken up to half a step before its
  // time is not taken again after the checkpoint)
  long next_sample = static_cast<long>(std::ceil(startup / stats_interval - 1e-9));
  int last_phase_slot = periodic ? static_cast<int>(std::floor(domain.time() / (0.25 * period))) : 0;
  if (r.resumed) {
    next_sample = resumed_next_sample;
    last_phase_slot = resumed_phase_slot;
  }
  const auto checkpoint = [&] {
    Checkpoint c;
    c.signature = sig;
    c.state = domain.state();
    c.frames = writer->frames();
    c.stats = stats;
    c.fine_stats = fine_stats;
    c.probes.time = probes.time;
    c.probes.u = probes.u;
    c.next_sample = next_sample;
    c.last_phase_slot = last_phase_slot;
    save(ckpt, c);
    last_ckpt = Clock::now();
  };
  const auto frame_due = [&](int k) { return startup + k * opt.frame_interval; };
  // cell updates so far (the fine region's from its start)
  const long fine_steps0 = fine ? fine->steps() : 0;
  const auto updates = [&] {
    return static_cast<double>(domain.steps() - start_step) * domain.cells() +
           (fine ? static_cast<double>(fine->steps() - fine_steps0) * fine->grid().cells() : 0.0);
  };
  long report_steps = domain.steps();
  double report_updates = 0;
  while (domain.steps() < total_steps && writer->frames() < total_frames) {
    if ((opt.stop && opt.stop->load()) || (opt.stop_at_step >= 0 && domain.steps() >= opt.stop_at_step)) {
      checkpoint();
      r.interrupted = true;
      break;
    }
    domain.step(1);
    const double t = domain.time();
    // what is due this step; the fields are copied once for all of it
    const bool frame = t + 0.5 * dt >= frame_due(writer->frames());
    const bool sample = t + 0.5 * dt >= next_sample * stats_interval;
    int phase = -1;  // phase ensembles at 0, 1/4, 1/2, 3/4 of the period (thesis 7.2)
    if (periodic && t >= startup) {
      const int slot = static_cast<int>(std::floor((t + 0.5 * dt) / (0.25 * period)));
      if (slot != last_phase_slot) {
        last_phase_slot = slot;
        phase = ((slot % 4) + 4) % 4;
      }
    }
    if (frame || sample || phase >= 0) {
      const lbm::Fields f = domain.fields();
      lbm::Fields ff;
      if (fine) ff = fine->fields();
      if (frame) {
        std::vector<float> u, rho, fu, frho;
        domain.table_frame(f, u, rho);
        if (fine) fine->table_frame(ff, opt.domain.density, fu, frho);
        writer->append(u, rho, fu, frho);
      }
      if (sample || phase >= 0) {
        const auto pl = domain.centre_plane(f);
        PlaneSample fpl;
        if (fine) fpl = domain.fine_centre_plane(ff);
        if (sample) {
          stats.add(pl, -1);
          if (fine) fine_stats.add(fpl, -1);
          if (!probes.points.empty()) {
            probes.time.push_back(t);
            for (const auto& p : probes.points) {
              std::array<double, 3> u{};
              if (!probe_velocity(f, fine ? &ff : nullptr, p, u, t)) u.fill(std::numeric_limits<double>::quiet_NaN());
              for (double v : u) probes.u.push_back(static_cast<float>(v));
            }
          }
          ++next_sample;
        }
        if (phase >= 0) {
          stats.add(pl, phase);
          if (fine) fine_stats.add(fpl, phase);
        }
      }
    }
    const auto now = Clock::now();
    if (std::chrono::duration<double>(now - last_ckpt).count() >= opt.checkpoint_seconds) checkpoint();
    if (const double since = std::chrono::duration<double>(now - last_report).count(); opt.progress && since >= 1.0) {
      // rates over the last report's interval: a fine region that starts late changes them
      last_report = now;
      const double u = updates(), per_step = since / std::max(1L, domain.steps() - report_steps);
      const double fraction = static_cast<double>(domain.steps()) / total_steps;
      opt.progress({fraction, t, per_step * (total_steps - domain.steps()), (u - report_updates) / since / 1e6, writer->frames()});
      report_steps = domain.steps();
      report_updates = u;
    }
  }
  r.wall_seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  r.steps = domain.steps();
  r.simulated = domain.time();
  r.frames = writer->frames();
  r.rebuilds = domain.rebuilds();
  const long done = domain.steps() - start_step;
  r.mlups = updates() / std::max(r.wall_seconds, 1e-9) / 1e6;
  r.coarse_seconds = domain.coarse_seconds() - coarse_s0;
  r.fine_seconds = domain.fine_seconds() - fine_s0;
  r.coarse_mlups = done * static_cast<double>(domain.cells()) / std::max(r.coarse_seconds, 1e-9) / 1e6;
  if (fine) r.fine_mlups = static_cast<double>(fine->steps() - fine_steps0) * fine->grid().cells() / std::max(r.fine_seconds, 1e-9) / 1e6;
  // statistics: in the table and as CSV for the plots
  const std::vector<int> dims3{stats.nz, stats.nx, 3}, dims6{stats.nz, stats.nx, 6}, dims1{stats.nz, stats.nx};
  writer->write_statistic("centre_plane_mean_velocity", stats.mean(), dims3);
  writer->write_statistic("centre_plane_reynolds_stress", stats.stress(), dims6);
  writer->write_statistic("centre_plane_tke", stats.tke(), dims1);
  writer->write_statistic("centre_plane_samples", {static_cast<float>(stats.samples)}, {1});
  if (fine) {
    const std::vector<int> f3{fine_stats.nz, fine_stats.nx, 3}, f6{fine_stats.nz, fine_stats.nx, 6}, f1{fine_stats.nz, fine_stats.nx};
    writer->write_statistic("fine_centre_plane_mean_velocity", fine_stats.mean(), f3);
    writer->write_statistic("fine_centre_plane_reynolds_stress", fine_stats.stress(), f6);
    writer->write_statistic("fine_centre_plane_tke", fine_stats.tke(), f1);
  }
  writer->close();
  const bool phases = periodic != nullptr && stats.phase_samples[0] > 0;
  write_plane_csv(r.centre_plane_csv, stats, phases, opt.domain.wind);
  if (fine) write_plane_csv(r.fine_centre_plane_csv, fine_stats, phases, opt.domain.wind);
  if (!probes.points.empty()) write_probe_series_csv(r.probes_csv, probes);
  if (!r.interrupted) {
    std::error_code ec;
    fs::remove(ckpt, ec);
  }
  return r;
}

}  // namespace ship_lrm::wake
