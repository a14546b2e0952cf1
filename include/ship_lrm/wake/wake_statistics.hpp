// Statistics of a ship-wake run that users compare with wind tunnels and ships at sea (thesis 7.1,
// 7.2): on the centre plane y = 0 the mean velocity, the Reynolds-stress tensor and the turbulent
// kinetic energy k = (u'u' + v'v' + w'w') / 2, and for a periodic ship motion their phase averages at
// 0, 1/4, 1/2 and 3/4 of the period (fig. 7.6); at probe points the velocity's time series, its mean
// and Reynolds stresses (spectra and histograms from the series: scripts/plot_probes.py).
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace ship_lrm::wake {

// One sample of a plane: velocity (m/s, 3 per point, x fastest then z) and a solid flag per point.
struct PlaneSample {
  int nx = 0, nz = 0;
  std::vector<float> u;
  std::vector<std::uint8_t> solid;
  std::vector<double> x, z;  // ship-frame coordinates of the columns and rows
};

// Sums of the samples of a plane, overall and in four phase ensembles.
struct CentrePlaneStats {
  int nx = 0, nz = 0;
  std::vector<double> x, z;  // ship-frame coordinates
  std::vector<std::uint8_t> solid;
  long samples = 0;
  // per point: sum of u, v, w (3), of their squares (3) and of uv, uw, vw (3)
  std::vector<double> sum, sum_sq, sum_cross;
  std::array<long, 4> phase_samples{0, 0, 0, 0};
  std::array<std::vector<double>, 4> phase_sum, phase_sum_sq, phase_sum_cross;
  void set_geometry(const PlaneSample& p);          // and zero sums of the right size where there are none
  void add(const PlaneSample& p, int phase = -1);   // phase -1: the overall statistics, 0..3: that phase's ensemble
  std::vector<float> mean(int phase = -1) const;    // 3 per point
  std::vector<float> stress(int phase = -1) const;  // Reynolds stresses u'u', v'v', w'w', u'v', u'w', v'w' (m^2/s^2), 6 per point
  std::vector<float> tke(int phase = -1) const;     // k, 1 per point
};

// Writes the plane's statistics as CSV (x_m, z_m, solid, mean_u, mean_v, mean_w, tke, uu, vv, ww, uv,
// uw, vw, [phaseK_u, phaseK_w, phaseK_tke: nan for a phase with no sample], wind); TableError when
// the file cannot be written.
void write_plane_csv(const std::string& path, const CentrePlaneStats& s, bool phases, double wind);

// Velocity time series at probe points; a sample where a probe is not in the fluid (a moving deck
// reaching it) is NaN and left out of its statistics.
struct ProbeSeries {
  std::vector<std::array<double, 3>> points;  // ship frame of the mean pose, m
  std::vector<double> time;                   // s
  std::vector<float> u;                       // per sample, per probe: 3 (m/s, mean frame)
  int probes() const { return static_cast<int>(points.size()); }
  struct Statistics {
    long samples = 0;
    std::array<double, 3> mean{0, 0, 0};
    std::array<double, 6> stress{0, 0, 0, 0, 0, 0};  // u'u', v'v', w'w', u'v', u'w', v'w'
    double tke = 0;
  };
  Statistics statistics(int probe) const;
};

// The series as CSV: time_s, then per probe pK_u, pK_v, pK_w (m/s, ship frame: x forward, y
// starboard, z down); and the statistics, one row per probe, with the points as `labels` give them.
void write_probe_series_csv(const std::string& path, const ProbeSeries& s);
void write_probe_statistics_csv(const std::string& path, const ProbeSeries& s, const std::vector<std::array<double, 3>>& labels,
                                const std::string& frame, double wind);

}  // namespace ship_lrm::wake
