// Sub-commands of the `ship_lrm` command-line program; each file registers one.
#pragma once

#include <CLI/CLI.hpp>
#include <chrono>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "ship_lrm/lrm/domain_slice.hpp"

namespace ship_lrm::tools {

// Each returns the action of its sub-command: it returns -1 when that sub-command was not chosen,
// else the exit code.
std::function<int()> add_bench_command(CLI::App& app);
std::function<int()> add_units_command(CLI::App& app);
std::function<int()> add_validate_command(CLI::App& app);
// "0:5:70" (start:step:stop) or "0,10,25", 1 to 400 values in lo..hi; CLI::ValidationError naming
// `option` otherwise (number_list.cpp).
std::vector<double> parse_number_list(const std::string& text, const std::string& option, double lo, double hi, const std::string& unit);
// Throws CLI::ValidationError naming the option when a floating-point option of the parsed command
// (app and its chosen sub-commands) is not a finite number: "nan" passes CLI11's range checks.
void reject_non_finite_numbers(const CLI::App& app);
// Output paths (output_files.cpp). A file the command writes: ConfigError when it is a folder,
// or exists and overwrite is not set.
void check_output_file(const std::string& path, const std::string& option, bool overwrite);
// Creates dir (ConfigError when it is a file); refuses to overwrite an existing file of `names`
// unless overwrite is set.
void prepare_output(const std::filesystem::path& dir, const std::vector<std::string>& names, bool overwrite);
// The progress of a long run on stderr (progress_line.cpp): "label [####    ]  45.0 %  ETA 812 s
// detail". On a terminal one line rewritten about once a second; elsewhere (a log) a line at every
// tenth of the work, from 5 s on (a terminal: from 1 s on). The ETA comes from the wall clock so far
// unless update() is given one.
class ProgressLine {
 public:
  explicit ProgressLine(std::string label);
  ~ProgressLine();
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;
  void update(double fraction, const std::string& detail = "", double eta_seconds = -1.0);  // fraction of the work done, 0..1
  void finish();  // ends a terminal's line (also done by the destructor)

 private:
  using Clock = std::chrono::steady_clock;
  std::string label_;
  Clock::time_point start_, last_;
  bool terminal_, shown_ = false;
  int last_tenth_ = 0;
};
#ifdef SHIP_LRM_HAVE_FLIGHT
std::function<int()> add_trim_command(CLI::App& app);
std::function<int()> add_doublet_command(CLI::App& app);
std::function<int()> add_sweep_command(CLI::App& app);
std::function<int()> add_wake_command(CLI::App& app);
std::function<int()> add_approach_command(CLI::App& app);
// `sweep free-wake` (cmd_sweep_free_wake.cpp), registered by add_sweep_command.
std::function<int()> add_free_wake_sweep(CLI::App& sweep);
// `validate nrc-deck` under the validate command (cmd_validate_nrc_deck.cpp).
std::function<int()> add_nrc_deck_command(CLI::App& validate);
// Where `ship_lrm wake --preset default` keeps its table: $SHIP_LRM_WAKE_CACHE or ~/.cache/ship_lrm.

// Shared by the sweep commands (cmd_flight.cpp):
// parse_number_list in 0..100 m/s as --speeds.
std::vector<double> parse_speeds(const std::string& text);
// "6", "0.5": a number as it appears in a file name or a label.
std::string tag(double v);
// "V = 10 m/s", above a ground "V = 10 m/s, z/R = 0.5", in a climb "V = 0 m/s, climb 5 m/s": a sweep's
// case in its progress line and summary.
std::string case_label(double speed, double height = 0, double climb = 0);
// Checks before any run that `path` (given to `option`) is a readable CSV file whose header row
// names every one of `columns`; CLI::ValidationError otherwise.
void check_csv_columns(const std::string& path, const std::string& option, const std::vector<std::string>& columns);
// The values of `column` in every data row of that file, as written; std::nullopt when the header
// has no such column (CLI::ValidationError when the file cannot be read).
std::optional<std::vector<std::string>> csv_column(const std::string& path, const std::string& option, const std::string& column);
// scripts/plot_flight.py <kind> csv png [--reference ref]; a failure is a warning, the CSV stays.
void plot(const std::string& kind, const std::filesystem::path& csv, const std::filesystem::path& png, const std::string& reference);
// Runs a shipped script from scripts/ with Debian's python3 (the one with matplotlib, numpy and
// PyWavelets; a pyenv python3 earlier on PATH may lack them), `args` appended as given (the caller
// quotes them). True when it succeeded.
bool run_script(const std::string& script, const std::string& args);
// A time-averaged plane of the LRM domain (lrm::SliceAverage) to dir/stem.csv: x_m, z_m, u_x_m_s,
// u_y_m_s, u_z_m_s (relative to the grid, mr axes), wall, rotor_radius_m, and where the slice has
// them the undisturbed air's undisturbed_u_x_m_s, ... (the table's, thesis fig. 9.3 (c)); with png, its
// plot (plot_flight.py plane) to dir/stem.png.
void write_plane(const std::filesystem::path& dir, const std::string& stem, const lrm::DomainSlice& s, double radius, bool png);
// The two files write_plane makes for a stem (so that prepare_output checks them before any run).
void add_plane_outputs(std::vector<std::string>& names, const std::string& stem);
#endif

}  // namespace ship_lrm::tools
