// The project's one error for invalid input: a set-up, a file or an option that cannot be run (sizes,
// relaxation, boundary combinations, the Mach limit, a missing device, a table that does not exist).
// The command-line tool turns it into exit code 2 and its message; the nodelets into a named fault.
#pragma once

#include <stdexcept>

namespace ship_lrm {

class ConfigError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

}  // namespace ship_lrm
