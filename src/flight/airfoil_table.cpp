// Section polar table: loading from YAML and bilinear lookup in angle of attack and Mach number.
#include "ship_lrm/flight/airfoil_table.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>

#include "ship_lrm/flight/parameters.hpp"

namespace ship_lrm::flight {

AirfoilTable::AirfoilTable(std::string name, std::vector<double> alpha_deg, std::vector<double> mach, std::vector<std::vector<double>> cl,
                           std::vector<std::vector<double>> cd, std::vector<std::vector<double>> cm)
    : name_(std::move(name)), mach_(std::move(mach)) {
  const int na = static_cast<int>(alpha_deg.size());
  if (na < 3 || std::abs(alpha_deg.front() + 180.0) > 1e-9 || std::abs(alpha_deg.back() - 180.0) > 1e-9)
    throw ParameterError("airfoil table '" + name_ + "': alpha_deg must run from -180 to 180");
  const double step = (alpha_deg.back() - alpha_deg.front()) / (na - 1);
  for (int i = 0; i < na; ++i)
    if (std::abs(alpha_deg[i] - (alpha_deg.front() + i * step)) > 1e-6)
      throw ParameterError("airfoil table '" + name_ + "': alpha_deg must be equally spaced");
  if (mach_.empty() || !std::is_sorted(mach_.begin(), mach_.end()) || mach_.front() < 0)
    throw ParameterError("airfoil table '" + name_ + "': mach must be a non-empty ascending list of values >= 0");
  const auto check = [&](const std::vector<std::vector<double>>& t, const char* key) {
    if (t.size() != mach_.size()) throw ParameterError("airfoil table '" + name_ + "': " + key + " needs one row per Mach number");
    for (const auto& row : t) {
      if (static_cast<int>(row.size()) != na)
        throw ParameterError("airfoil table '" + name_ + "': every " + key + " row needs one value per alpha_deg");
      for (double v : row)
        if (!std::isfinite(v)) throw ParameterError("airfoil table '" + name_ + "': " + key + " has a non-finite value");
    }
  };
  check(cl, "cl");
  check(cd, "cd");
  check(cm, "cm");
  alpha_count_ = na;
  alpha_first_ = -M_PI;
  alpha_step_inv_ = 1.0 / (step * M_PI / 180.0);
  data_.resize(mach_.size() * na * 3);
  for (size_t m = 0; m < mach_.size(); ++m)
    for (int a = 0; a < na; ++a) {
      double* d = &data_[(m * na + a) * 3];
      d[0] = cl[m][a];
      d[1] = cd[m][a];
      d[2] = cm[m][a];
    }
}

SectionCoefficients AirfoilTable::lookup(double alpha, double mach) const {
  // wrap into [-pi, pi]
  if (alpha > M_PI || alpha < -M_PI) alpha = std::remainder(alpha, 2.0 * M_PI);
  double fa = (alpha - alpha_first_) * alpha_step_inv_;
  int ia = static_cast<int>(fa);
  ia = std::clamp(ia, 0, alpha_count_ - 2);
  const double wa = std::clamp(fa - ia, 0.0, 1.0);
  int im = 0;
  double wm = 0;
  const int nm = static_cast<int>(mach_.size());
  if (nm > 1) {
    if (mach >= mach_.back()) {
      im = nm - 2;
      wm = 1;
    } else if (mach > mach_.front()) {
      while (im < nm - 2 && mach_[im + 1] < mach) ++im;
      wm = (mach - mach_[im]) / (mach_[im + 1] - mach_[im]);
    }
  }
  const auto at = [&](int m, int a, int k) { return data_[(static_cast<size_t>(m) * alpha_count_ + a) * 3 + k]; };
  SectionCoefficients out{};
  double* o = &out.cl;
  for (int k = 0; k < 3; ++k) {
    const double lo = at(im, ia, k) * (1 - wa) + at(im, ia + 1, k) * wa;
    const double hi = nm > 1 ? at(im + 1, ia, k) * (1 - wa) + at(im + 1, ia + 1, k) * wa : lo;
    o[k] = lo * (1 - wm) + hi * wm;
  }
  return out;
}

AirfoilTable load_airfoil_table(const std::string& path) {
  YAML::Node root;
  try {
    root = YAML::LoadFile(path);
  } catch (const YAML::Exception& e) {
    throw ParameterError(path + ": cannot read airfoil table: " + e.what());
  }
  const auto get = [&](const char* key) {
    if (!root[key]) throw ParameterError(path + ": field '" + key + "' is missing");
    return root[key];
  };
  try {
    return AirfoilTable(root["name"] ? root["name"].as<std::string>() : path, get("alpha_deg").as<std::vector<double>>(),
                        get("mach").as<std::vector<double>>(), get("cl").as<std::vector<std::vector<double>>>(),
                        get("cd").as<std::vector<std::vector<double>>>(), get("cm").as<std::vector<std::vector<double>>>());
  } catch (const YAML::Exception& e) {
    throw ParameterError(path + ": malformed airfoil table: " + e.what());
  } catch (const ParameterError& e) {
    throw ParameterError(path + ": " + e.what());
  }
}

}  // namespace ship_lrm::flight
