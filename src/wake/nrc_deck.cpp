// The NRC wind-tunnel deck case (see nrc_deck.hpp).
#include "ship_lrm/wake/nrc_deck.hpp"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>

#include "ship_lrm/wake/probe_points.hpp"

namespace ship_lrm::wake {
namespace {

namespace fs = std::filesystem;

constexpr double kNrcWind = 9.77;    // m/s (thesis 7.1)
constexpr int kMaxNestRatio = 8;     // fine cells per coarse cell
constexpr int kMinCoarseCells = 24;  // per ship length: the coarse domain still places the ship
constexpr int kPreferredCoarseCells = 52;
constexpr double kDeckHeight = 0.05;  // ship lengths above the deck: the deck region's top
// the thesis' deck probes (7.1), wind-tunnel frame, model scale
constexpr std::array<std::array<double, 3>, 2> kThesisProbes{{{0.3, 0.0, 0.07}, {0.3, 0.06, 0.07}}};

// Standard error of the TKE from five batch means of probe p's series (Law & Kelton's batch means: the
// batches far longer than the flow's correlation time are near independent).
double tke_standard_error(const ProbeSeries& s, int p) {
  constexpr int kBatches = 5;
  const std::size_t n = s.time.size() / kBatches;
  if (n < 2) return std::numeric_limits<double>::quiet_NaN();
  double sum = 0, sq = 0;
  for (int b = 0; b < kBatches; ++b) {
    ProbeSeries part;
    part.points = {s.points[p]};
    for (std::size_t k = b * n; k < (b + 1) * n; ++k) {
      part.time.push_back(s.time[k]);
      for (int d = 0; d < 3; ++d) part.u.push_back(s.u[3 * (k * s.probes() + p) + d]);
    }
    const double k = part.statistics(0).tke;
    sum += k;
    sq += k * k;
  }
  const double mean = sum / kBatches, var = std::max(0.0, (sq - kBatches * mean * mean) / (kBatches - 1));
  return std::sqrt(var / kBatches);
}

}  // namespace

std::array<int, 2> nest_resolution(int cells_per_length) {
  int best = 0;
  for (int r = 2; r <= kMaxNestRatio; ++r) {
    if (cells_per_length % r != 0 || cells_per_length / r < kMinCoarseCells) continue;
    if (best == 0 || std::abs(cells_per_length / r - kPreferredCoarseCells) < std::abs(cells_per_length / best - kPreferredCoarseCells))
      best = r;
  }
  if (best == 0)
    throw ConfigError("nrc-deck: " + std::to_string(cells_per_length) + " cells per ship length do not nest: give a multiple of " +
                      "2 .. " + std::to_string(kMaxNestRatio) + " over at least " + std::to_string(kMinCoarseCells) +
                      " coarse cells per length (e.g. 364 = 52 x 7, 546 = 78 x 7)");
  return {cells_per_length / best, best};
}

NrcDeckOptions with_quick_setting(NrcDeckOptions o) {
  if (o.quick) {
    o.cells_per_length = 64;
    o.seconds = 0.3;
  }
  return o;
}

NrcDeckResult run_nrc_deck(const NrcDeckOptions& in) {
  NrcDeckResult r;
  r.options = with_quick_setting(in);
  NrcDeckOptions& o = r.options;
  if (o.motion != "static" && o.motion != "pitch" && o.motion != "heave")
    throw ConfigError("nrc-deck: --motion must be static, pitch or heave (thesis 7.2), got '" + o.motion + "'");
  if (!(o.seconds > 0) || !std::isfinite(o.seconds) || o.seconds > 1e4) throw ConfigError("nrc-deck: --seconds must be in (0, 1e4]");
  if (!(o.sample_interval > 0) || !(o.sample_interval <= o.seconds))
    throw ConfigError("nrc-deck: the sample interval must be > 0 and at most the statistics time");
  if (o.out_dir.empty()) throw ConfigError("nrc-deck: no output folder");
  const auto nest = nest_resolution(o.cells_per_length);
  r.coarse_cells_per_length = nest[0];
  r.ratio = nest[1];
  r.wind = kNrcWind;
  r.statistics_seconds = o.seconds;

  PrecomputeOptions p;
  p.ship = "natogd";
  p.scale = "model";
  p.motion = o.motion;
  p.domain.cells_per_length = nest[0];
  p.domain.wind = kNrcWind;
  p.domain.density = 1.225;  // thesis table 6.2
  p.domain.backend = o.backend;
  p.domain.fine.ratio = nest[1];
  // The region (NrcDeckOptions::box). It must hold the whole superstructure: a region from 0.1 ship
  // lengths forward of the hangar door, fed with the coarse domain's steady wake of the bridge and
  // mast, stays laminar even at 364 cells per length (TKE / U^2 4e-5 at the thesis' probes), one over
  // the superstructure is turbulent at 273 (5.7e-3; docs/validation.md, "The NRC deck case"). Every
  // face but the fore one stays two coarse cells clear of the ship down to 32 coarse cells per
  // length. A moving ship may not cross the fore face: the region then reaches past the bow.
  p.domain.fine.aft = o.box[0];
  p.domain.fine.fore = o.box[1];
  p.domain.fine.half_width = o.box[2];
  p.domain.fine.top = o.box[3];
  const auto ship = make_ship("natogd", "model");
  const ShipDatum& d = ship->datum();
  if (o.motion != "static") p.domain.fine.fore = (d.stem_x + 3.0 * d.length / nest[0]) / d.length;
  // The coarse domain starts up alone; the region starts three of its flow-through times before
  // the statistics.
  r.run_box = {p.domain.fine.aft, p.domain.fine.fore, p.domain.fine.half_width, p.domain.fine.top};
  const double startup = o.startup >= 0 ? o.startup : p.domain.domain_length * d.length / kNrcWind;
  p.domain.fine.start = std::max(0.0, startup - 3.0 * (p.domain.fine.fore - p.domain.fine.aft) * d.length / kNrcWind);
  p.startup = startup;
  p.duration = o.seconds;
  p.frame_interval = o.seconds;  // the table's first and last frames: the statistics are the product here
  p.stats_interval = o.sample_interval;
  p.half_precision = true;
  p.resume = o.resume;
  p.stop = o.stop;
  p.progress = o.progress;
  std::vector<std::array<double, 3>> tunnel(kThesisProbes.begin(), kThesisProbes.end());
  tunnel.insert(tunnel.end(), o.extra_probes.begin(), o.extra_probes.end());
  for (const auto& t : tunnel) p.probes.push_back(to_ship_frame(t, ProbeFrame::Tunnel));
  p.probes_on_ship = true;  // the NRC model's COBRA probes are fixed to the ship (thesis 7.1)
  std::error_code ec;
  fs::create_directories(o.out_dir, ec);
  if (!fs::is_directory(o.out_dir)) throw ConfigError("nrc-deck: cannot create the folder '" + o.out_dir + "'");
  p.out = (fs::path(o.out_dir) / ("nrc_deck_" + o.motion + "_N" + std::to_string(o.cells_per_length) + ".h5")).string();
  r.run = precompute_wake(p);
  if (r.run.interrupted) return r;

  const double U = kNrcWind;
  for (int k = 0; k < static_cast<int>(tunnel.size()); ++k) {
    const auto st = r.run.probes.statistics(k);
    NrcDeckProbe q;
    q.position = tunnel[k];
    q.samples = st.samples;
    q.mean = from_ship_frame(st.mean, ProbeFrame::Tunnel);
    q.variance = {st.stress[0], st.stress[1], st.stress[2]};  // the diagonal is the same in both frames
    q.tke_over_u2 = st.tke / (U * U);
    q.tke_uncertainty = tke_standard_error(r.run.probes, k) / (U * U);
    r.probes.push_back(q);
  }
  // the deck region of the fine centre plane
  const CentrePlaneStats& f = r.run.fine_stats;
  const double stern = ship->datum().stern_x, top = kDeckHeight * ship->datum().length;
  const auto mean = f.mean();
  const auto k = f.tke();
  double sum = 0;
  for (int kz = 0; kz < f.nz; ++kz)
    for (int i = 0; i < f.nx; ++i) {
      const std::size_t n = i + static_cast<std::size_t>(f.nx) * kz;
      if (f.solid[n] || f.x[i] < stern || f.x[i] > 0.0 || f.z[kz] > 0.0 || f.z[kz] < -top) continue;
      ++r.deck_points;
      sum += k[n];
      const double forward = mean[3 * n] / U;  // the wind blows aft (-x): forward mean flow is reversed flow
      if (forward > 0) ++r.reversed_points;
      r.reversed_max_over_u = std::max(r.reversed_max_over_u, forward);
    }
  r.deck_tke_over_u2 = r.deck_points > 0 ? sum / r.deck_points / (U * U) : std::numeric_limits<double>::quiet_NaN();
  return r;
}

}  // namespace ship_lrm::wake
