// Azimuth record of blade forces and its harmonic coefficients (thesis 6.5).
#include "ship_lrm/rotor/force_harmonics.hpp"

#include <cmath>

namespace ship_lrm::rotor {
namespace {
constexpr double kBinWidth = 2.0 * M_PI / kAzimuthSamples;

int bin_of(double psi) {
  double a = std::fmod(psi, 2.0 * M_PI);
  if (a < 0) a += 2.0 * M_PI;
  int b = static_cast<int>(std::lround(a / kBinWidth));
  return b % kAzimuthSamples;
}
}  // namespace

AzimuthForceRecord::AzimuthForceRecord(int blades) : samples_(blades), last_bin_(blades, -1), last_force_(blades, Vec3::Zero()) {
  for (auto& s : samples_)
    for (auto& v : s) v.setZero();
}

void AzimuthForceRecord::deposit(int blade, double psi, const Vec3& force) {
  auto& s = samples_[blade];
  const int b = bin_of(psi);
  const int prev = last_bin_[blade];
  if (prev >= 0 && prev != b) {
    // Fill the samples passed since the previous deposit (either direction, the shorter way round).
    int gap = (b - prev + kAzimuthSamples) % kAzimuthSamples;
    int dir = 1;
    if (gap > kAzimuthSamples / 2) {
      gap = kAzimuthSamples - gap;
      dir = -1;
    }
    for (int k = 1; k < gap; ++k) {
      const double w = static_cast<double>(k) / gap;
      s[(prev + dir * k + kAzimuthSamples) % kAzimuthSamples] = last_force_[blade] * (1 - w) + force * w;
    }
  }
  s[b] = force;
  last_bin_[blade] = b;
  last_force_[blade] = force;
}

void AzimuthForceRecord::fill(const std::vector<Vec3>& per_blade_force) {
  for (size_t i = 0; i < samples_.size(); ++i)
    for (auto& v : samples_[i]) v = per_blade_force[i % per_blade_force.size()];
}

RotorForceHarmonics AzimuthForceRecord::harmonics() const {
  // cos(k psi_j), sin(k psi_j) of the 72 samples, tabulated once (the coupled step asks every step)
  static const auto table = [] {
    std::array<std::array<double, 2 * (kHarmonicOrder + 1)>, kAzimuthSamples> t{};
    for (int j = 0; j < kAzimuthSamples; ++j)
      for (int k = 0; k <= kHarmonicOrder; ++k) {
        t[j][k] = std::cos(k * j * kBinWidth);
        t[j][kHarmonicOrder + 1 + k] = std::sin(k * j * kBinWidth);
      }
    return t;
  }();
  RotorForceHarmonics h;
  for (const auto& s : samples_)
    for (int j = 0; j < kAzimuthSamples; ++j) {
      h.cos[0] += s[j];
      for (int k = 1; k <= kHarmonicOrder; ++k) {
        h.cos[k] += s[j] * table[j][k];
        h.sin[k] += s[j] * table[j][kHarmonicOrder + 1 + k];
      }
    }
  h.cos[0] /= kAzimuthSamples;
  for (int k = 1; k <= kHarmonicOrder; ++k) {
    h.cos[k] *= 2.0 / kAzimuthSamples;
    h.sin[k] *= 2.0 / kAzimuthSamples;
  }
  return h;
}

}  // namespace ship_lrm::rotor
