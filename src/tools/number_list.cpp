// Number lists of the command-line options ("0:5:70" or "0,10,25"), shared by the sub-commands.
#include <cmath>
#include <sstream>

#include "commands.hpp"

namespace ship_lrm::tools {

std::vector<double> parse_number_list(const std::string& text, const std::string& option, double lo, double hi, const std::string& unit) {
  std::vector<double> v;
  const auto num = [&](const std::string& s) {
    size_t pos = 0;
    double x = 0;
    try {
      x = std::stod(s, &pos);
    } catch (const std::exception&) {
      pos = 0;
    }
    if (pos != s.size() || !std::isfinite(x)) throw CLI::ValidationError(option, "'" + s + "' is not a number");
    return x;
  };
  if (text.find(':') != std::string::npos) {
    std::stringstream ss(text);
    std::string a, b, c;
    if (!std::getline(ss, a, ':') || !std::getline(ss, b, ':') || !std::getline(ss, c) || c.find(':') != std::string::npos)
      throw CLI::ValidationError(option, "expected start:step:stop, e.g. 0:5:70");
    const double start = num(a), step = num(b), stop = num(c);
    if (step <= 0 || stop < start) throw CLI::ValidationError(option, "needs step > 0 and stop >= start");
    for (int i = 0; start + i * step <= stop + 1e-9; ++i) v.push_back(start + i * step);
  } else {
    std::stringstream ss(text);
    std::string a;
    while (std::getline(ss, a, ',')) v.push_back(num(a));
  }
  if (v.empty() || v.size() > 400) throw CLI::ValidationError(option, "needs 1 to 400 values");
  std::ostringstream range;
  range << lo << ".." << hi << (unit.empty() ? "" : " " + unit);
  for (double x : v)
    if (x < lo || x > hi) throw CLI::ValidationError(option, "values must lie in " + range.str());
  return v;
}

}  // namespace ship_lrm::tools
