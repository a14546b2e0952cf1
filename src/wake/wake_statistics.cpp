// Statistics of a ship-wake run (see wake_statistics.hpp).
#include "ship_lrm/wake/wake_statistics.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>

#include "ship_lrm/wake/wake_table.hpp"

namespace ship_lrm::wake {
namespace {

// u'u', v'v', w'w', u'v', u'w', v'w' from the sums of c samples (sum: 3, sq: 3, cross: uv, uw, vw)
std::array<double, 6> stresses(const double* sum, const double* sq, const double* cross, long c) {
  std::array<double, 6> r{0, 0, 0, 0, 0, 0};
  if (c <= 0) return r;
  const double m[3] = {sum[0] / c, sum[1] / c, sum[2] / c};
  for (int d = 0; d < 3; ++d) r[d] = std::max(0.0, sq[d] / c - m[d] * m[d]);
  r[3] = cross[0] / c - m[0] * m[1];
  r[4] = cross[1] / c - m[0] * m[2];
  r[5] = cross[2] / c - m[1] * m[2];
  return r;
}

void accumulate(const float* u, double* sum, double* sq, double* cross) {
  for (int d = 0; d < 3; ++d) {
    sum[d] += u[d];
    sq[d] += double(u[d]) * u[d];
  }
  cross[0] += double(u[0]) * u[1];
  cross[1] += double(u[0]) * u[2];
  cross[2] += double(u[1]) * u[2];
}

}  // namespace

void CentrePlaneStats::set_geometry(const PlaneSample& p) {
  nx = p.nx;
  nz = p.nz;
  x = p.x;
  z = p.z;
  solid = p.solid;
  const std::size_t n = p.u.size();
  for (auto* v : {&sum, &sum_sq, &sum_cross})
    if (v->size() != n) v->assign(n, 0.0);
}

void CentrePlaneStats::add(const PlaneSample& p, int phase) {
  const std::size_t n = p.u.size();
  nx = p.nx;
  nz = p.nz;
  x = p.x;
  z = p.z;
  solid = p.solid;
  auto& s = phase < 0 ? sum : phase_sum[phase];
  auto& q = phase < 0 ? sum_sq : phase_sum_sq[phase];
  auto& c = phase < 0 ? sum_cross : phase_sum_cross[phase];
  for (auto* v : {&s, &q, &c})
    if (v->size() != n) v->assign(n, 0.0);
  for (std::size_t k = 0; k < n; k += 3) accumulate(&p.u[k], &s[k], &q[k], &c[k]);
  ++(phase < 0 ? samples : phase_samples[phase]);
}

std::vector<float> CentrePlaneStats::mean(int phase) const {
  const auto& s = phase < 0 ? sum : phase_sum[phase];
  const long c = phase < 0 ? samples : phase_samples[phase];
  std::vector<float> m(s.size(), 0.0f);
  for (std::size_t k = 0; k < s.size() && c > 0; ++k) m[k] = static_cast<float>(s[k] / c);
  return m;
}

std::vector<float> CentrePlaneStats::stress(int phase) const {
  const auto& s = phase < 0 ? sum : phase_sum[phase];
  const auto& q = phase < 0 ? sum_sq : phase_sum_sq[phase];
  const auto& x3 = phase < 0 ? sum_cross : phase_sum_cross[phase];
  const long c = phase < 0 ? samples : phase_samples[phase];
  const std::size_t points = s.size() / 3;
  std::vector<float> r(6 * points, 0.0f);
  if (q.size() != s.size() || x3.size() != s.size()) return r;
  for (std::size_t p = 0; p < points; ++p) {
    const auto t = stresses(&s[3 * p], &q[3 * p], &x3[3 * p], c);
    for (int a = 0; a < 6; ++a) r[6 * p + a] = static_cast<float>(t[a]);
  }
  return r;
}

std::vector<float> CentrePlaneStats::tke(int phase) const {
  const std::vector<float> r = stress(phase);
  std::vector<float> k(r.size() / 6);
  for (std::size_t p = 0; p < k.size(); ++p) k[p] = 0.5f * (r[6 * p] + r[6 * p + 1] + r[6 * p + 2]);
  return k;
}

void write_plane_csv(const std::string& path, const CentrePlaneStats& s, bool phases, double wind) {
  std::ofstream out(path);
  if (!out) throw TableError("cannot write '" + path + "'");
  out << "x_m,z_m,solid,mean_u,mean_v,mean_w,tke,uu,vv,ww,uv,uw,vw";
  if (phases)
    for (int p = 0; p < 4; ++p) out << ",phase" << p << "_u,phase" << p << "_w,phase" << p << "_tke";
  out << ",wind\n";
  const auto m = s.mean(), k = s.tke(), r = s.stress();
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
      for (int a = 0; a < 6; ++a) out << "," << r[6 * n + a];
      if (phases)
        for (int p = 0; p < 4; ++p) {
          if (pk[p].size() <= n) {  // a phase with no sample yet (a run shorter than the period)
            out << ",nan,nan,nan";
            continue;
          }
          out << "," << pm[p][3 * n] << "," << pm[p][3 * n + 2] << "," << pk[p][n];
        }
      out << "," << wind << "\n";
    }
  if (!out) throw TableError("writing '" + path + "' failed (disk full?)");
}

ProbeSeries::Statistics ProbeSeries::statistics(int probe) const {
  Statistics st;
  double sum[3] = {0, 0, 0}, sq[3] = {0, 0, 0}, cross[3] = {0, 0, 0};
  const std::size_t n = probes(), samples = time.size();
  for (std::size_t k = 0; k < samples; ++k) {
    const float* v = &u[3 * (k * n + probe)];
    if (!(std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]))) continue;
    accumulate(v, sum, sq, cross);
    ++st.samples;
  }
  if (st.samples == 0) {
    st.mean.fill(std::numeric_limits<double>::quiet_NaN());
    st.stress.fill(std::numeric_limits<double>::quiet_NaN());
    st.tke = std::numeric_limits<double>::quiet_NaN();
    return st;
  }
  for (int d = 0; d < 3; ++d) st.mean[d] = sum[d] / st.samples;
  st.stress = stresses(sum, sq, cross, st.samples);
  st.tke = 0.5 * (st.stress[0] + st.stress[1] + st.stress[2]);
  return st;
}

void write_probe_series_csv(const std::string& path, const ProbeSeries& s) {
  std::ofstream out(path);
  if (!out) throw TableError("cannot write '" + path + "'");
  out.precision(7);
  out << "time_s";
  for (int p = 0; p < s.probes(); ++p) out << ",p" << p << "_u,p" << p << "_v,p" << p << "_w";
  out << "\n";
  for (std::size_t k = 0; k < s.time.size(); ++k) {
    out << s.time[k];
    for (int p = 0; p < s.probes(); ++p)
      for (int d = 0; d < 3; ++d) out << "," << s.u[3 * (k * s.probes() + p) + d];
    out << "\n";
  }
  if (!out) throw TableError("writing '" + path + "' failed (disk full?)");
}

void write_probe_statistics_csv(const std::string& path, const ProbeSeries& s, const std::vector<std::array<double, 3>>& labels,
                                const std::string& frame, double wind) {
  std::ofstream out(path);
  if (!out) throw TableError("cannot write '" + path + "'");
  out.precision(7);
  out << "probe,x_m,y_m,z_m,frame,samples,mean_u,mean_v,mean_w,uu,vv,ww,uv,uw,vw,tke,tke_over_u2,wind\n";
  for (int p = 0; p < s.probes(); ++p) {
    const auto st = s.statistics(p);
    const auto& l = labels.size() == s.points.size() ? labels[p] : s.points[p];
    out << p << "," << l[0] << "," << l[1] << "," << l[2] << "," << frame << "," << st.samples;
    for (double m : st.mean) out << "," << m;
    for (double r : st.stress) out << "," << r;
    out << "," << st.tke << "," << st.tke / (wind * wind) << "," << wind << "\n";
  }
  if (!out) throw TableError("writing '" + path + "' failed (disk full?)");
}

}  // namespace ship_lrm::wake
