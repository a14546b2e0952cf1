// Output files and folders of the sub-commands: nothing the user made is replaced unless asked
// (--overwrite), and a wrong kind of path (a file where a folder is meant, or the reverse) is
// invalid input before any run.
#include <filesystem>

#include "commands.hpp"
#include "ship_lrm/lbm/solver.hpp"

namespace ship_lrm::tools {
namespace fs = std::filesystem;

void check_output_file(const std::string& path, const std::string& option, bool overwrite) {
  if (path.empty()) return;
  std::error_code ec;
  if (fs::is_directory(path, ec))
    throw ConfigError(option + ": '" + path + "' is a folder; give a file name (" + option + " " + (fs::path(path) / "name").string() +
                      ")");
  if (fs::exists(path, ec) && !overwrite) throw ConfigError(option + ": '" + path + "' exists; pass --overwrite to replace it");
}

void prepare_output(const fs::path& dir, const std::vector<std::string>& names, bool overwrite) {
  std::error_code ec;
  if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
    throw ConfigError("--out: '" + dir.string() + "' is a file; --out names the folder the results go to");
  fs::create_directories(dir);
  for (const auto& n : names)
    if (fs::exists(dir / n) && !overwrite) throw std::runtime_error((dir / n).string() + " exists; pass --overwrite to replace it");
}

}  // namespace ship_lrm::tools
