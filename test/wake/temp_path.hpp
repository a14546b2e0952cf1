// A fresh path for a test file under the system's temporary directory (shared by the wake tests).
#pragma once
#include <filesystem>
#include <string>

namespace ship_lrm::test {

// <tmp>/<dir>/<name>, the directory created, any old file of that name (and its checkpoint) removed.
inline std::string temp_path(const std::string& dir, const std::string& name) {
  const std::filesystem::path d = std::filesystem::temp_directory_path() / dir;
  std::filesystem::create_directories(d);
  const std::filesystem::path p = d / name;
  std::filesystem::remove(p);
  std::filesystem::remove(p.string() + ".ckpt");
  return p.string();
}

}  // namespace ship_lrm::test
