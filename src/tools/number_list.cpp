// Numbers on the command line: the lists of the options ("0:5:70" or "0,10,25"), shared by the
// sub-commands, and the check that every floating-point option holds a finite number.
#include <cmath>
#include <sstream>

#include "commands.hpp"

namespace ship_lrm::tools {
namespace {

// The whole of s as a finite number (std::stod alone takes a prefix, "nan" and "inf").
bool parse_finite(const std::string& s, double& x) {
  size_t pos = 0;
  try {
    x = std::stod(s, &pos);
  } catch (const std::exception&) {
    return false;
  }
  return pos == s.size() && std::isfinite(x);
}

}  // namespace

std::vector<double> parse_number_list(const std::string& text, const std::string& option, double lo, double hi, const std::string& unit) {
  std::vector<double> v;
  const auto num = [&](const std::string& s) {
    if (s.empty()) throw CLI::ValidationError(option, "an empty entry in '" + text + "'");
    double x = 0;
    if (!parse_finite(s, x)) throw CLI::ValidationError(option, "'" + s + "' is not a number");
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
    if (!text.empty() && text.back() == ',') num("");  // "5,10,": the empty entry getline does not return
  }
  if (v.empty() || v.size() > 400) throw CLI::ValidationError(option, "needs 1 to 400 values");
  std::ostringstream range;
  range << lo << ".." << hi << (unit.empty() ? "" : " " + unit);
  for (double x : v)
    if (x < lo || x > hi) throw CLI::ValidationError(option, "values must lie in " + range.str());
  return v;
}

void reject_non_finite_numbers(const CLI::App& app) {
  // CLI11's range checks compare with < and >, which NaN passes; "inf" passes the unbounded ones.
  for (const CLI::Option* opt : app.get_options()) {
    if (opt->get_type_name().rfind("FLOAT", 0) != 0) continue;
    for (const std::string& value : opt->results()) {
      double x = 0;
      if (!parse_finite(value, x)) throw CLI::ValidationError(opt->get_name(), "'" + value + "' is not a finite number");
    }
  }
  for (const CLI::App* sub : app.get_subcommands()) reject_non_finite_numbers(*sub);
}

}  // namespace ship_lrm::tools
