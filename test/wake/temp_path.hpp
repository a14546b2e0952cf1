// A fresh path for a test file under the system's temporary directory (shared by the wake tests).
#pragma once
#include <unistd.h>

#include <filesystem>
#include <set>
#include <string>
#include <system_error>

namespace ship_lrm::test {

// <tmp>/<dir>_<pid>/<name>, the directory created, any old file of that name (and its checkpoint)
// removed. One directory per process: ctest -j runs the tests of one binary in several processes at
// once, and each makes its own files. The directory is removed when the process ends.
inline std::string temp_path(const std::string& dir, const std::string& name) {
  struct RemovedAtExit {
    std::set<std::filesystem::path> paths;
    ~RemovedAtExit() {
      std::error_code e;
      for (const auto& p : paths) std::filesystem::remove_all(p, e);
    }
  };
  static RemovedAtExit made;
  const std::filesystem::path d = std::filesystem::temp_directory_path() / (dir + "_" + std::to_string(::getpid()));
  std::filesystem::create_directories(d);
  made.paths.insert(d);
  const std::filesystem::path p = d / name;
  std::filesystem::remove(p);
  std::filesystem::remove(p.string() + ".ckpt");
  return p.string();
}

}  // namespace ship_lrm::test
