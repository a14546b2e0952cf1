// The ship-wake precompute (see wake_precompute.hpp).
#include "ship_lrm/wake/wake_precompute.hpp"

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace ship_lrm::wake {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

constexpr char kMagic[16] = "SHIPLRM-WAKECK1";

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
  CentrePlaneStats stats;
};

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
    put(out, c.stats.samples);
    put_vec(out, c.stats.sum);
    put_vec(out, c.stats.sum_sq);
    for (int p = 0; p < 4; ++p) {
      put(out, c.stats.phase_samples[p]);
      put_vec(out, c.stats.phase_sum[p]);
      put_vec(out, c.stats.phase_sum_sq[p]);
    }
    put_vec(out, c.state.populations);
    if (!out) throw TableError("writing checkpoint '" + tmp + "' failed (disk full?)");
  }
  fs::rename(tmp, path);  // atomic: a crash mid-write leaves the previous checkpoint
}

Checkpoint load(const std::string& path, std::uint64_t limit) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw TableError("cannot read checkpoint '" + path + "'");
  char magic[sizeof kMagic];
  in.read(magic, sizeof magic);
  if (!in || std::memcmp(magic, kMagic, sizeof kMagic) != 0) throw TableError("'" + path + "' is not a wake checkpoint");
  Checkpoint c;
  const auto sig = get_vec<char>(in, 4096);
  c.signature.assign(sig.begin(), sig.end());
  c.state.steps = get<long>(in);
  c.state.solver_steps = get<long>(in);
  c.state.voxel_time = get<double>(in);
  c.frames = get<int>(in);
  c.stats.samples = get<long>(in);
  c.stats.sum = get_vec<double>(in, limit);
  c.stats.sum_sq = get_vec<double>(in, limit);
  for (int p = 0; p < 4; ++p) {
    c.stats.phase_samples[p] = get<long>(in);
    c.stats.phase_sum[p] = get_vec<double>(in, limit);
    c.stats.phase_sum_sq[p] = get_vec<double>(in, limit);
  }
  c.state.populations = get_vec<float>(in, 19 * limit);
  return c;
}

void write_csv(const std::string& path, const CentrePlaneStats& s, bool phases, double wind) {
  std::ofstream out(path);
  if (!out) throw TableError("cannot write '" + path + "'");
  out << "x_m,z_m,solid,mean_u,mean_v,mean_w,tke";
  if (phases)
    for (int p = 0; p < 4; ++p) out << ",phase" << p << "_u,phase" << p << "_w,phase" << p << "_tke";
  out << ",wind\n";
  const auto m = s.mean(), k = s.tke();
  std::array<std::vector<float>, 4> pm, pk;
  if (phases)
    for (int p = 0; p < 4; ++p) {
      pm[p] = s.mean(p);
      pk[p] = s.tke(p);
    }
  for (int kz = 0; kz < s.nz; ++kz)
    for (int i = 0; i < s.nx; ++i) {
      const std::size_t n = i + static_cast<std::size_t>(s.nx) * kz;
      out << s.x[i] << "," << s.z[kz] << "," << int(s.solid[n]) << "," << m[3 * n] << "," << m[3 * n + 1] << "," << m[3 * n + 2] << ","
          << k[n];
      if (phases)
        for (int p = 0; p < 4; ++p) out << "," << pm[p][3 * n] << "," << pm[p][3 * n + 2] << "," << pk[p][n];
      out << "," << wind << "\n";
    }
}

}  // namespace

void CentrePlaneStats::add(const ShipWakeDomain::Plane& p, int phase) {
  const std::size_t n = p.u.size();
  nx = p.nx;
  nz = p.nz;
  x = p.x;
  z = p.z;
  solid = p.solid;
  auto& s = phase < 0 ? sum : phase_sum[phase];
  auto& q = phase < 0 ? sum_sq : phase_sum_sq[phase];
  if (s.empty()) {
    s.assign(n, 0.0);
    q.assign(n, 0.0);
  }
  for (std::size_t k = 0; k < n; ++k) {
    s[k] += p.u[k];
    q[k] += double(p.u[k]) * p.u[k];
  }
  ++(phase < 0 ? samples : phase_samples[phase]);
}

std::vector<float> CentrePlaneStats::mean(int phase) const {
  const auto& s = phase < 0 ? sum : phase_sum[phase];
  const long c = phase < 0 ? samples : phase_samples[phase];
  std::vector<float> m(s.size(), 0.0f);
  for (std::size_t k = 0; k < s.size() && c > 0; ++k) m[k] = static_cast<float>(s[k] / c);
  return m;
}

std::vector<float> CentrePlaneStats::tke(int phase) const {
  const auto& s = phase < 0 ? sum : phase_sum[phase];
  const auto& q = phase < 0 ? sum_sq : phase_sum_sq[phase];
  const long c = phase < 0 ? samples : phase_samples[phase];
  std::vector<float> k(s.size() / 3, 0.0f);
  for (std::size_t p = 0; p < k.size() && c > 0; ++p) {
    double e = 0;
    for (int d = 0; d < 3; ++d) {
      const double m = s[3 * p + d] / c;
      e += std::max(0.0, q[3 * p + d] / c - m * m);
    }
    k[p] = static_cast<float>(0.5 * e);
  }
  return k;
}

std::string default_table_path() {
  if (const char* p = std::getenv("SHIP_LRM_WAKE_CACHE")) return std::string(p) + "/wake_default_v3.h5";
  const char* home = std::getenv("HOME");
  return std::string(home ? home : ".") + "/.cache/ship_lrm/wake_default_v3.h5";
}

PrecomputeOptions preset(const std::string& name) {
  PrecomputeOptions o;
  if (name == "default") {
    // The approach scenario (thesis 9.1): NatoGD full scale, wind over deck 20.58 m/s, heave + pitch
    // of the approach sea state. N = 48 (dx = 3.1 m, against the thesis' 0.41 m at N = 364) keeps it
    // within minutes on 2 cores; frames every 0.1 s (the wind crosses a cell in 0.15 s).
    o.ship = "natogd";
    o.scale = "full";
    o.motion = "approach";
    o.domain.cells_per_length = 48;
    o.domain.wind = 20.58;
    o.domain.density = 1.1934;
    o.duration = 30;
    o.frame_interval = 0.1;
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
  throw lbm::ConfigError("unknown wake preset '" + name + "' (default, tiny)");
}

PrecomputeResult precompute_wake(const PrecomputeOptions& opt) {
  if (opt.out.empty()) throw lbm::ConfigError("wake: no output file (--out FILE.h5)");
  if (!(opt.duration > 0) || !(opt.frame_interval > 0) || !std::isfinite(opt.duration))
    throw lbm::ConfigError("wake: duration and frame interval must be > 0");
  auto ship = std::shared_ptr<const ShipGeometry>(make_ship(opt.ship, opt.scale));
  const double scale = ship_scale(opt.scale);
  const ShipDatum& sd = ship->datum();
  auto motion = std::shared_ptr<const ShipMotion>(make_motion(opt.motion, scale, motion_centre(sd)));
  ShipWakeDomain domain(opt.domain, ship, motion);
  const double dt = domain.units().dt();
  const double startup = opt.startup >= 0 ? opt.startup : opt.domain.domain_length * sd.length / opt.domain.wind;
  const double stats_interval = opt.stats_interval > 0 ? opt.stats_interval : opt.frame_interval;
  if (opt.frame_interval < dt)
    throw lbm::ConfigError("wake: the frame interval " + std::to_string(opt.frame_interval) + " s is shorter than the time step " +
                           std::to_string(dt) + " s");
  const long total_steps = static_cast<long>(std::ceil((startup + opt.duration) / dt + 0.5));
  const int total_frames = static_cast<int>(std::floor(opt.duration / opt.frame_interval + 1e-9)) + 1;
  const auto* periodic = dynamic_cast<const SinusoidalMotion*>(motion.get());
  const double period = periodic ? 1.0 / periodic->params().frequency : 0.0;

  PrecomputeResult r;
  r.table = opt.out;
  r.xdmf = fs::path(opt.out).replace_extension(".xdmf").string();
  r.centre_plane_csv = fs::path(opt.out).replace_extension("").string() + "_centre_plane.csv";
  r.cells = domain.cells();
  r.dx = domain.units().dx();
  r.dt = dt;
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
  if (opt.resume && fs::exists(ckpt)) {
    Checkpoint c = load(ckpt, domain.cells() * 3 + 16);
    if (c.signature != sig)
      throw lbm::ConfigError("wake: checkpoint '" + ckpt + "' belongs to another run (" + c.signature +
                             "); delete it or choose another --out");
    domain.restore(c.state);
    writer = std::make_unique<WakeTableWriter>(opt.out, info, true, c.frames);
    stats = std::move(c.stats);
    r.resumed = true;
  } else {
    writer = std::make_unique<WakeTableWriter>(opt.out, info, false, 0);
  }
  // the geometry of the statistics (on a resume the sums came from the checkpoint)
  {
    const auto pl = domain.centre_plane(domain.fields());
    stats.nx = pl.nx;
    stats.nz = pl.nz;
    stats.x = pl.x;
    stats.z = pl.z;
    stats.solid = pl.solid;
    if (stats.sum.empty()) {
      stats.sum.assign(pl.u.size(), 0.0);
      stats.sum_sq.assign(pl.u.size(), 0.0);
    }
  }
  const auto t0 = Clock::now();
  auto last_ckpt = t0, last_report = t0;
  const long start_step = domain.steps();
  const auto checkpoint = [&] {
    Checkpoint c;
    c.signature = sig;
    c.state = domain.state();
    c.frames = writer->frames();
    c.stats = stats;
    save(ckpt, c);
    last_ckpt = Clock::now();
  };
  const auto frame_due = [&](int k) { return startup + k * opt.frame_interval; };
  long next_sample = static_cast<long>(std::ceil(startup / stats_interval - 1e-9));
  if (domain.time() > startup) next_sample = static_cast<long>(std::floor(domain.time() / stats_interval + 1e-9)) + 1;
  int last_phase_slot = periodic ? static_cast<int>(std::floor(domain.time() / (0.25 * period))) : 0;
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
      if (frame) {
        std::vector<float> u, rho;
        domain.table_frame(f, u, rho);
        writer->append(u, rho);
      }
      if (sample || phase >= 0) {
        const auto pl = domain.centre_plane(f);
        if (sample) {
          stats.add(pl, -1);
          ++next_sample;
        }
        if (phase >= 0) stats.add(pl, phase);
      }
    }
    const auto now = Clock::now();
    if (std::chrono::duration<double>(now - last_ckpt).count() >= opt.checkpoint_seconds) checkpoint();
    if (opt.progress && std::chrono::duration<double>(now - last_report).count() >= 1.0) {
      last_report = now;
      const double wall = std::chrono::duration<double>(now - t0).count();
      const long done = domain.steps() - start_step;
      const double fraction = static_cast<double>(domain.steps()) / total_steps;
      const double per_step = done > 0 ? wall / done : 0;
      opt.progress(
          {fraction, t, per_step * (total_steps - domain.steps()), done * domain.cells() / std::max(wall, 1e-9) / 1e6, writer->frames()});
    }
  }
  r.wall_seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  r.steps = domain.steps();
  r.simulated = domain.time();
  r.frames = writer->frames();
  r.rebuilds = domain.rebuilds();
  r.mlups = (domain.steps() - start_step) * static_cast<double>(domain.cells()) / std::max(r.wall_seconds, 1e-9) / 1e6;
  // statistics: in the table and as CSV for the plots
  const std::vector<int> dims3{stats.nz, stats.nx, 3}, dims1{stats.nz, stats.nx};
  writer->write_statistic("centre_plane_mean_velocity", stats.mean(), dims3);
  writer->write_statistic("centre_plane_tke", stats.tke(), dims1);
  writer->write_statistic("centre_plane_samples", {static_cast<float>(stats.samples)}, {1});
  writer->close();
  write_csv(r.centre_plane_csv, stats, periodic != nullptr && stats.phase_samples[0] > 0, opt.domain.wind);
  if (!r.interrupted) {
    std::error_code ec;
    fs::remove(ckpt, ec);
  }
  return r;
}

}  // namespace ship_lrm::wake
