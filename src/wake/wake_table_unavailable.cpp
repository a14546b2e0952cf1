// Stand-in for the HDF5 wake table file when the core is built without HDF5 (a bare GPU machine): a
// table can still be served from another process (WakeTable over a WindowSource).
#include "ship_lrm/wake/wake_table.hpp"

namespace ship_lrm::wake {
namespace {
[[noreturn]] void unavailable() {
  throw TableError("this build has no HDF5: the wake table is unavailable (install libhdf5-dev and rebuild)");
}
}  // namespace

struct WakeTableWriter::Impl {};
WakeTableWriter::WakeTableWriter(const std::string&, const WakeTableInfo&, bool, int) { unavailable(); }
WakeTableWriter::~WakeTableWriter() = default;
void WakeTableWriter::append(const std::vector<float>&, const std::vector<float>&, const std::vector<float>&, const std::vector<float>&) {
  unavailable();
}
void WakeTableWriter::write_statistic(const std::string&, const std::vector<float>&, const std::vector<int>&) { unavailable(); }
void WakeTableWriter::close() {}
void WakeTableWriter::write_xdmf() const {}

std::unique_ptr<WindowSource> open_table_file(const std::string&, WakeTableInfo&, WakeTableInfo*) { unavailable(); }

}  // namespace ship_lrm::wake
