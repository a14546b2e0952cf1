// A progress line for the long runs of the sub-commands (see commands.hpp, ProgressLine): on a
// terminal one line on stderr rewritten about once a second, elsewhere (a log file, a pipe) one full
// line at every tenth of the work, so that a log holds a few lines instead of thousands; nothing for a
// run shorter than a second (terminal) or five (log).
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "commands.hpp"

namespace ship_lrm::tools {

ProgressLine::ProgressLine(std::string label) : label_(std::move(label)), start_(Clock::now()), terminal_(isatty(STDERR_FILENO) == 1) {}

ProgressLine::~ProgressLine() { finish(); }

void ProgressLine::update(double fraction, const std::string& detail, double eta_seconds) {
  if (!std::isfinite(fraction)) return;
  fraction = std::clamp(fraction, 0.0, 1.0);
  const auto now = Clock::now();
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  if (!shown_ && elapsed < (terminal_ ? 1.0 : 5.0)) return;  // a short run prints nothing
  if (terminal_) {
    if (shown_ && std::chrono::duration<double>(now - last_).count() < 1.0 && fraction < 1.0) return;
  } else {
    const int tenth = static_cast<int>(std::floor(fraction * 10.0 + 1e-9));
    if (tenth <= last_tenth_) return;
    last_tenth_ = tenth;
  }
  // the remaining time from the wall clock so far, unless the caller knows better
  if (!(eta_seconds >= 0)) eta_seconds = fraction > 0 ? elapsed * (1.0 - fraction) / fraction : -1.0;
  const int width = 30, done = static_cast<int>(fraction * width);
  char eta[32] = "ETA    ?";
  if (eta_seconds >= 0) std::snprintf(eta, sizeof eta, "ETA %5.0f s", eta_seconds);
  std::fprintf(stderr, "%s%s [%-*s] %5.1f %%  %s%s%s", terminal_ ? "\r" : "", label_.c_str(), width, std::string(done, '#').c_str(),
               100.0 * fraction, eta, detail.empty() ? "" : "  ", detail.c_str());
  std::fprintf(stderr, terminal_ ? " " : "\n");
  std::fflush(stderr);
  shown_ = true;
  last_ = now;
}

void ProgressLine::finish() {
  if (terminal_ && shown_) std::fprintf(stderr, "\n");
  shown_ = false;
}

}  // namespace ship_lrm::tools
